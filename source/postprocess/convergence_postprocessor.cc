// convergence.csv and convergence.txt: one row per refinement cycle.
#include <restshape/base/units.h>
#include <restshape/postprocess/convergence_postprocessor.h>

#include <sstream>

namespace RestShape
{
  using namespace dealii;

  void
  ConvergencePostprocessor::execute(const PostprocessInput &in)
  {
    const unsigned int n_cells =
      in.mesh.triangulation().n_global_active_cells();
    const unsigned int n_dofs =
      in.forward.discretization().dof_handler().n_dofs();
    table.add_value("cycle", in.cycle);
    table.add_value("cells", n_cells);
    table.add_value("dofs", n_dofs);
    row    = {double(in.cycle),
              double(n_cells),
              double(n_dofs),
              in.estimate.relative,
              double(in.stats.newton_iterations),
              in.reductions.max_displacement_mm,
              in.forward.potential_energy()};
    header = {"cycle",
              "n_cells",
              "n_dofs",
              "estimated_error",
              "newton_iterations",
              "max_displacement_mm",
              "potential_energy_J"};
    rated.clear();
    if (in.exact)
      add_errors(in, *in.exact, in.u, "");
    if (in.exact_rest)
      add_errors(in, *in.exact_rest, in.forward.rest_displacement(), "rest_");
    if (in.parameters.inverse.enabled)
      {
        row.push_back(in.inverse_mean_error * mm_per_m);
        header.push_back("mean_error_mm");
      }
    row.push_back(in.wall_seconds);
    header.push_back("wall_seconds");
    rows.push_back(row);
    in.output.write_csv("convergence.csv", header, rows);
    if (rated.empty() || in.cycle == 0)
      return;
    ConvergenceTable with_rates = table;
    for (const std::string &key : rated)
      with_rates.evaluate_convergence_rates(
        key, ConvergenceTable::reduction_rate_log2);
    const std::string text = described_table(with_rates);
    in.output.write_text("convergence.txt",
                         [&](std::ostream &out) { out << text; });
    if (in.cycle == in.parameters.refinement.cycles)
      in.pcout << text;
  }

  std::string
  ConvergencePostprocessor::described_table(const ConvergenceTable &table)
  {
    // deal.II names a rate column KEY...red.rate.log2; each column is
    // described on a line "# N: name" before the aligned rows.
    std::ostringstream raw;
    table.write_text(raw, TableHandler::table_with_separate_column_description);
    const std::string  rate_suffix = "...red.rate.log2";
    std::istringstream lines(raw.str());
    std::ostringstream out;
    std::string        line;
    while (std::getline(lines, line))
      {
        const auto at = line.find(rate_suffix);
        if (line.rfind("# ", 0) == 0 && at != std::string::npos)
          line = line.substr(0, at) +
                 "_rate: log2 of its ratio to the previous cycle (the order "
                 "in h when each cycle halves the cells; '-' on cycle 0)";
        out << line << '\n';
      }
    return out.str();
  }

  void
  ConvergencePostprocessor::add_errors(const PostprocessInput  &in,
                                       const ExactDisplacement &exact,
                                       const VectorType        &field,
                                       const std::string       &key)
  {
    const DisplacementErrors errors = exact.errors(in.forward, field);
    table.add_value(key + "L2_rel", errors.l2_relative);
    table.add_value(key + "H1_rel", errors.h1_relative);
    table.add_value(key + "max_nodal_mm", errors.max_nodal_error * mm_per_m);
    for (const std::string k : {"L2_rel", "H1_rel", "max_nodal_mm"})
      {
        table.set_scientific(key + k, true);
        table.set_precision(key + k, 3);
      }
    rated.insert(rated.end(), {key + "L2_rel", key + "H1_rel"});
    row.insert(row.end(),
               {errors.l2_relative,
                errors.h1_relative,
                errors.max_nodal_error * mm_per_m});
    header.insert(header.end(),
                  {key + "l2_error_relative",
                   key + "h1_error_relative",
                   key + "max_nodal_error_mm"});
    in.summary.set(key + "l2_error_relative", errors.l2_relative);
    in.summary.set(key + "h1_error_relative", errors.h1_relative);
    in.summary.set(key + "max_nodal_error_mm",
                   errors.max_nodal_error * mm_per_m);
    in.pcout << "  Error of the "
             << (key.empty() ? "displacement" : "rest shape")
             << " against the exact one: L2 " << errors.l2_relative << ", H1 "
             << errors.h1_relative << " (relative), max nodal "
             << errors.max_nodal_error * mm_per_m << " mm" << std::endl;
  }
} // namespace RestShape
