// nodes.csv: per node its position, displacement and rest shift.
#include <deal.II/base/mpi.h>

#include <restshape/base/units.h>
#include <restshape/postprocess/nodal_csv.h>

namespace RestShape
{
  using namespace dealii;

  void
  NodalCsv::execute(const PostprocessInput &in)
  {
    TimerOutput::Scope scope(in.timer, "Output");
    const VectorType   w =
      in.forward.discretization().owned_copy(in.forward.rest_displacement());
    std::vector<std::vector<double>> rows;
    for (const Node &node : in.forward.discretization().owned_nodes())
      {
        std::vector<double> row;
        for (unsigned int c = 0; c < 3; ++c)
          row.push_back(node.position[c] * in.output.length_scale());
        for (unsigned int c = 0; c < 3; ++c)
          row.push_back(in.u[node.dofs[c]] * mm_per_m);
        for (unsigned int c = 0; c < 3; ++c)
          row.push_back(w[node.dofs[c]] * mm_per_m);
        rows.push_back(row);
      }
    std::vector<std::vector<double>> all_rows;
    for (const auto &part :
         Utilities::MPI::gather(in.mesh.triangulation().get_communicator(),
                                rows))
      all_rows.insert(all_rows.end(), part.begin(), part.end());
    const std::string unit = in.parameters.mesh.length_unit_name;
    in.output.write_csv("nodes.csv",
                        {"x_" + unit,
                         "y_" + unit,
                         "z_" + unit,
                         "u_x_mm",
                         "u_y_mm",
                         "u_z_mm",
                         "rest_shift_x_mm",
                         "rest_shift_y_mm",
                         "rest_shift_z_mm"},
                        all_rows);
  }
} // namespace RestShape
