// The forward problem's slice of a scene: what ForwardProblem, its
// discretisation and its load terms are built from (the subsections
// "Discretization" with the fixed labels, "Materials", the environment of
// "Loads" and "Solver", and the load terms of the registry the scene
// enables, each with its own parameters).
#ifndef restshape_forward_forward_parameters_h
#define restshape_forward_forward_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/fem/discretization_parameters.h>
#include <restshape/loads/environment_parameters.h>
#include <restshape/loads/load_term.h>
#include <restshape/material/material_parameters.h>
#include <restshape/solver/solver_parameters.h>

#include <set>
#include <string>
#include <vector>

namespace RestShape
{
  struct ForwardParameters
  {
    DiscretizationParameters discretization;
    MaterialParameters       materials;
    EnvironmentParameters    environment;
    SolverParameters         solver;
    /// The registry's load terms the scene enables
    /// (parse_registered_parameters()).
    std::vector<LoadTermFactory> load_terms;
    /// The scenario entries of the load terms that a later phase (a
    /// scenario) sets to a value other than zero (LoadContext::set_later).
    std::set<std::string> set_later;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// The subsections; @p length_unit: metres per unit of the mesh
    /// file, in which Loads/Fluid level is given. Throws InputError.
    void
    parse_parameters(dealii::ParameterHandler &prm, const double length_unit);
  };
} // namespace RestShape

#endif
