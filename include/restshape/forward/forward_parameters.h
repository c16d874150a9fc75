// The forward problem's slice of a scene: what ForwardProblem, its
// discretisation and its load terms are built from (the subsections
// "Discretization", "Materials", "Boundary conditions", "Loads" and
// "Solver", and the registered load terms the scene enables).
#ifndef restshape_forward_forward_parameters_h
#define restshape_forward_forward_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/fem/discretization_parameters.h>
#include <restshape/forward/boundary_parameters.h>
#include <restshape/loads/load_parameters.h>
#include <restshape/material/material_parameters.h>
#include <restshape/solver/solver_parameters.h>

#include <functional>
#include <memory>
#include <vector>

namespace RestShape
{
  class LoadTerm;
  struct LoadContext;
  /// Makes a load term of the registry (loads/load_registry.h) that a scene
  /// enables, with its parameters' values, on a discretisation.
  using LoadTermFactory =
    std::function<std::unique_ptr<LoadTerm>(const LoadContext &)>;

  struct ForwardParameters
  {
    DiscretizationParameters discretization;
    MaterialParameters       materials;
    BoundaryParameters       boundary;
    LoadParameters           loads;
    SolverParameters         solver;
    /// The registry's load terms the scene enables
    /// (parse_registered_parameters()).
    std::vector<LoadTermFactory> load_terms;
    /// A later phase (a scenario) sets a pressure where the scene has none:
    /// a follower pressure's tangent is then not symmetric from the start.
    bool pressure_set_later = false;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// The five subsections; @p length_unit: metres per unit of the mesh
    /// file, in which Loads/Fluid level is given. Throws InputError.
    void
    parse_parameters(dealii::ParameterHandler &prm, const double length_unit);
  };
} // namespace RestShape

#endif
