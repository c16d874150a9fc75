#include <deal.II/base/mpi.h>

#include <restshape/app/run_size.h>
#include <restshape/base/input_error.h>
#include <restshape/base/machine_memory.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// Cells made from one by a uniform refinement (tetrahedra and hexahedra).
    constexpr double children_per_cell = 8;
    /// Measured on prm/brain.prm (P1 and P2, 5k and 43k cells): about 1 KB
    /// per cell for the triangulation and 3 KB per DoF for the vectors, the
    /// sparse tangent and its AMG or factorisation.
    constexpr double bytes_per_cell = 1024;
    constexpr double bytes_per_dof  = 3072;
    /// The share of the machine's memory a run may plan to take.
    constexpr double usable_share = 0.9;

    /// DoFs per cell of a large mesh: 3 per node, nodes per cell of a
    /// tetrahedral mesh about 0.2 (P1) and 1.47 (P2, vertices and edges);
    /// of its split into hexahedra about 1.1 (Q1) and 8 (Q2).
    double
    dofs_per_cell(const Parameters &parameters)
    {
      const bool linear = parameters.forward.discretization.degree == 1;
      if (parameters.mesh.cell_type == CellType::tetrahedra)
        return 3 * (linear ? 0.2 : 1.47);
      return 3 * (linear ? 1.1 : 8.0);
    }
  } // namespace

  std::string
  RunSize::text() const
  {
    std::ostringstream out;
    out.precision(2);
    out << cells << " cells, about " << dofs << " DoFs and "
        << bytes / bytes_per_gibibyte << " GiB";
    return out.str();
  }

  RunSize
  estimate_run_size(const std::size_t  cells_read,
                    const Parameters  &parameters,
                    const unsigned int cycles)
  {
    const RefinementParameters &r = parameters.refinement;
    // Each cycle refines every cell (global) or the refine fraction of
    // them (adaptive: 8 children each, so 1 + 7 f times the cells).
    const double growth = r.strategy == RefinementParameters::Strategy::global ?
                            children_per_cell :
                            1 + (children_per_cell - 1) * r.refine_fraction;
    RunSize      size;
    size.cells =
      cells_read *
      std::pow(children_per_cell, parameters.mesh.global_refinements) *
      std::pow(growth, cycles);
    // The mixed formulations add no global DoF (their pressure is
    // condensed per cell or per vertex).
    size.dofs  = size.cells * dofs_per_cell(parameters);
    size.bytes = size.cells * bytes_per_cell + size.dofs * bytes_per_dof;
    // Every rank holds the mesh as read before it keeps its own part.
    const unsigned int ranks =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    size.bytes += (ranks - 1) * double(cells_read) * bytes_per_cell;
    return size;
  }

  void
  check_run_size(const std::size_t  cells_read,
                 const Parameters  &parameters,
                 const std::string &prm_file,
                 const bool         print)
  {
    const unsigned int refinements = parameters.mesh.global_refinements;
    const unsigned int cycles      = parameters.refinement.cycles;
    if (refinements == 0 && cycles == 0)
      return;
    const RunSize      size = estimate_run_size(cells_read, parameters, cycles);
    std::ostringstream what;
    what << cells_read << " cells";
    if (refinements > 0)
      what << ", " << refinements << " uniform refinement"
           << (refinements > 1 ? "s" : "");
    if (cycles > 0)
      what << ", " << cycles << " refinement cycle" << (cycles > 1 ? "s" : "")
           << " ("
           << (parameters.refinement.strategy ==
                   RefinementParameters::Strategy::global ?
                 "global" :
                 "adaptive, refine fraction " +
                   number_text(parameters.refinement.refine_fraction))
           << ")";
    const unsigned int ranks =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    what << (ranks > 1 ? " on " + std::to_string(ranks) + " ranks" : "")
         << " make " << size.text();
    if (exceeds_machine_memory(size.bytes, usable_share))
      {
        // Blame the cycles if the mesh fits without them.
        const bool cycles_too_many =
          cycles > 0 &&
          !exceeds_machine_memory(
            estimate_run_size(cells_read, parameters, 0).bytes, usable_share);
        throw InputError(prm_file,
                         cycles_too_many ? "Adaptive refinement/Cycles" :
                                           "Mesh/Global refinements",
                         what.str() + ", more than " +
                           available_memory().text() + "; expected fewer " +
                           (cycles_too_many ? "cycles" : "refinements") +
                           " (or a machine with more memory)");
      }
    if (print)
      std::cout << "Run size: " << what.str() << std::endl;
  }
} // namespace RestShape
