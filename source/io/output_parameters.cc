// The parameters of subsection Output.
#include <deal.II/base/utilities.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/io/output_parameters.h>

#include <cmath>
#include <cstdlib>

namespace RestShape
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Directory for all results (created if missing). "
                      "Files are written under a temporary name and renamed, "
                      "so an interrupted run never leaves half a file.");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write the VTU/PVTU fields and the .pvd/.visit "
                      "records. Turn off for benchmarks; summary.json and "
                      "the .csv files are always written.");
    prm.declare_entry("Write nodal CSV",
                      "false",
                      Patterns::Bool(),
                      "Also write nodes.csv: one row per node (every support "
                      "point of the element) with its mesh position (mesh "
                      "length unit), its displacement from the rest shape "
                      "and the shift from the mesh to the rest shape (both "
                      "in mm), for post-processing and for comparing meshes "
                      "node by node (benchmarks/time_vs_error/brain.sh).");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory       = prm.get("Directory");
    write_vtu       = prm.get_bool("Write VTU");
    write_nodal_csv = prm.get_bool("Write nodal CSV");
    prm.leave_subsection();
    if (directory.empty())
      throw InputError("", "Output/Directory", "no directory given");
  }
} // namespace RestShape
