// Subsection "Discretization": the element degree and the tangent; and the
// fixed labels and planes of subsection "Boundary conditions".
#ifndef restshape_fem_discretization_parameters_h
#define restshape_fem_discretization_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/label_values.h>
#include <restshape/base/tangent_type.h>
#include <restshape/fem/fixed_planes.h>

#include <string>
#include <vector>

namespace RestShape
{
  struct DiscretizationParameters
  {
    unsigned int degree;
    TangentType  tangent;
    std::string  tangent_name; // as in the .prm, for summary.json
    /// Boundary conditions/Fixed labels.
    std::vector<FixedLabel> fixed_labels;
    /// Boundary conditions/Fixed boundary planes.
    std::vector<FixedPlane> fixed_planes;
    /// Discretization/Formulation as written (auto|displacement|mixed).
    std::string formulation_name = "auto";
    /// Discretization/Cell pressure as written (auto|constant|linear).
    std::string cell_pressure_name = "auto";
    /// Discretization/Nodal pressure at the boundary: whether a boundary
    /// vertex's share of each cell's volume goes to the cell's interior
    /// vertices (interior) or stays its own (own, Bonet and Burton).
    bool boundary_shares_to_interior = true;
    /// After resolve_formulation(): whether the volume change is the
    /// cell's mean dilatation or the vertices' (mixed) or the pointwise
    /// one.
    bool mixed = false;
    /// After resolve_formulation(): mixed on linear tetrahedra, the
    /// averaged nodal pressure (NodalVolumes).
    bool nodal_pressure = false;
    /// After resolve_formulation(): mixed on Q2 hexahedra with a linear
    /// pressure per cell (Q2-P1disc, CellPressureModes).
    bool linear_cell_pressure = false;
    /// The pressure modes per cell of the mixed formulation (1: constant).
    unsigned int
    cell_pressure_modes() const
    {
      return linear_cell_pressure ? 4 : 1;
    }
    /// After resolve_formulation(): what the run says about the choice
    /// (empty: nothing to say).
    std::string formulation_warning;
    /// After resolve_formulation(): a note on the accuracy of the chosen
    /// element at this Poisson's ratio (empty: nothing to say).
    std::string formulation_note;

    /// Resolve Formulation = auto (mixed where @p max_poissons_ratio is
    /// nearly_incompressible or above and the element has a mixed form)
    /// and check an explicit choice; @p simplex: tetrahedra. Throws an
    /// InputError (without the file) for a linear cell pressure on an
    /// element that has none.
    void
    resolve_formulation(const double max_poissons_ratio, const bool simplex);
    /// From this Poisson's ratio on, displacement elements lock.
    static constexpr double nearly_incompressible = 0.49;
    /// From this Poisson's ratio on, the averaged nodal pressure's error
    /// stops falling under refinement (doc/model.md, "Under refinement").
    static constexpr double nodal_pressure_stalls = 0.495;

    /// Whether every component of @p label is fixed.
    bool
    fully_fixed(const Label label) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
