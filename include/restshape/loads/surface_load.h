// Pressure loads on the surface: a uniform pressure and a fluid's
// hydrostatic pressure, as follower or dead loads.
#ifndef restshape_loads_surface_load_h
#define restshape_loads_surface_load_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/loads/load_state.h>

#include <vector>

namespace RestShape
{
  /**
   * A fluid's hydrostatic pressure field, weight rho_f max(0, a . (x -
   * level)) in Pa at x: a (m/s^2) the acceleration it is under, level (m)
   * a point of its free surface, rho_f the fluid's density.
   */
  struct FluidColumn
  {
    dealii::Tensor<1, 3> acceleration;
    dealii::Point<3>     level;
    double               weight = 1;
  };

  /**
   * The pressure loads of a LoadState as the pressure faces carry them:
   * the uniform pressure (Pa), the fluid's columns, and what an opening of
   * the skull takes off its faces (the LoadState's loads of the names
   * SurfaceLoad::pressure_name and the others).
   */
  struct PressureField
  {
    double                   pressure = 0;
    std::vector<FluidColumn> fluid;
    double                   opening_pressure = 0;
    std::vector<FluidColumn> opening_fluid;
  };

  /// The names of a surface pressure's loads in a LoadState: the uniform
  /// pressure (columns: p in Pa), the fluid's pressure (columns:
  /// acceleration and level), and what an opening takes off of each (empty
  /// names: none). By default the CSF's (SurfaceLoad::pressure_name ...).
  struct PressureNames
  {
    PressureNames();
    PressureNames(const std::string &pressure);
    std::string pressure, fluid, opening_pressure, opening_fluid;
  };

  /**
   * The pressure on the pressure faces (Loads subsection):
   *
   *     p(x) = p0 + sum_k w_k rho_f max(0, a_k . (x - x_k))
   *
   * with p0 the uniform pressure (PressureField::pressure) and one term
   * per FluidColumn (PressureField::fluid: weight w_k, acceleration a_k
   * pointing down, x_k a point of its free surface), rho_f the fluid
   * density when Fluid load = hydrostatic pressure (else 0). Faces above a
   * column's level are drained of it. The faces of an opening of the skull
   * carry p(x) less the opening's part (PressureField::opening_pressure and
   * opening_fluid).
   *
   * A follower pressure acts on the current surface: the force on a face
   * element is -p(x) cof(F) N dA (Nanson), F = I + grad d the deformation
   * gradient from the mesh geometry X (normal N, area dA) to x = X + d. It
   * is conservative where the loaded surface is closed or held at its
   * edges, with potential  Pi = int Q(x) . cof(F) N dA,  div Q = p:
   *
   *     Q(x) = p0 / 3 (x - x_ref) + sum_k w_k rho_f s+^2 / (2 |a_k|^2) a_k,
   *     s = a_k . (x - x_k),  s+ = max(0, s).
   */
  class SurfaceLoad
  {
  public:
    /// Which pressure a face carries: all of it, or what is left in an
    /// opening of the skull.
    enum class Face
    {
      covered,
      opened
    };

    /// The names of its loads in a LoadState: the uniform pressure
    /// (columns: p in Pa), the fluid's pressure (columns: acceleration and
    /// level), and what an opening takes off of each.
    static const std::string pressure_name, fluid_name, opening_pressure_name,
      opening_fluid_name;

    /// @p follower: whether the pressure follows the current surface;
    /// @p fluid_density: kg/m^3 of a hydrostatic fluid (0: none);
    /// @p level: the scene fluid's free surface (m), also the reference
    /// point x_ref of the uniform pressure's potential.
    SurfaceLoad(const bool              follower,
                const double            fluid_density,
                const dealii::Point<3> &level);

    /// The pressure loads of @p load, by @p names.
    static PressureField
    field(const LoadState &load, const PressureNames &names = PressureNames());

    /// Whether the pressure follows the current surface.
    bool
    follower() const
    {
      return is_follower;
    }
    /// Whether any pressure acts under @p load.
    bool
    acts(const PressureField &load) const;

    /// p(x) in Pa at the position @p x (m).
    double
    pressure(const PressureField    &load,
             const dealii::Point<3> &x,
             const Face              face = Face::covered) const;
    /// dp/dx in Pa/m.
    dealii::Tensor<1, 3>
    pressure_gradient(const PressureField    &load,
                      const dealii::Point<3> &x,
                      const Face              face = Face::covered) const;
    /// Q(x) (Pa m) with div Q = p: the potential's flux density.
    dealii::Tensor<1, 3>
    potential_flux(const PressureField    &load,
                   const dealii::Point<3> &x,
                   const Face              face = Face::covered) const;

    /// The fluid's load (columns of fluid_name) under the acceleration
    /// @p a with its free surface through @p level: one column (none
    /// without a hydrostatic fluid or an acceleration).
    LoadState::Columns
    fluid_columns(const dealii::Tensor<1, 3> &a,
                  const dealii::Point<3>     &level) const;

    const dealii::Point<3> level;

  private:
    const bool   is_follower;
    const double fluid_density; // kg/m^3; 0 unless hydrostatic
  };

  /// cof(F) N = det(F) F^-T N: the current area vector of the reference
  /// area vector N (columns of cof F: cross products of those of F).
  dealii::Tensor<1, 3>
  cofactor_times(const dealii::Tensor<2, 3> &F, const dealii::Tensor<1, 3> &N);

  /// The derivative of cof(F) N in the direction e_c (x) g:
  /// e_c x (F (N x g)).
  dealii::Tensor<1, 3>
  cofactor_derivative(const dealii::Tensor<2, 3> &F,
                      const dealii::Tensor<1, 3> &N,
                      const unsigned int          c,
                      const dealii::Tensor<1, 3> &g);

  /// |cof(I + grad w) N|: the rest area of a unit face area of the mesh
  /// with unit normal @p N, the rest shape being X + w.
  double
  rest_area(const dealii::Tensor<2, 3> &grad_w, const dealii::Tensor<1, 3> &N);
} // namespace RestShape

#endif
