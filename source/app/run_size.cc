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
  estimate_run_size(const std::size_t cells_read, const Parameters &parameters)
  {
    RunSize size;
    size.cells = cells_read * std::pow(children_per_cell,
                                       parameters.mesh.global_refinements);
    size.dofs  = size.cells * dofs_per_cell(parameters);
    size.bytes = size.cells * bytes_per_cell + size.dofs * bytes_per_dof;
    return size;
  }

  void
  check_run_size(const std::size_t  cells_read,
                 const Parameters  &parameters,
                 const std::string &prm_file,
                 const bool         print)
  {
    const unsigned int refinements = parameters.mesh.global_refinements;
    if (refinements == 0)
      return;
    const RunSize      size = estimate_run_size(cells_read, parameters);
    std::ostringstream what;
    what << refinements << " uniform refinement" << (refinements > 1 ? "s" : "")
         << " of " << cells_read << " cells make " << size.text();
    if (exceeds_machine_memory(size.bytes, usable_share))
      throw InputError(prm_file,
                       "Mesh/Global refinements",
                       what.str() + ", more than this machine's " +
                         gibibytes_text(physical_memory_bytes()) +
                         "; expected fewer refinements (or a machine "
                         "with more memory)");
    if (print)
      std::cout << "Mesh/Global refinements: " << what.str() << std::endl;
  }
} // namespace RestShape
