// Pressure loads on the surface: a uniform pressure and a fluid's
// hydrostatic pressure, as follower or dead loads.
#ifndef restshape_loads_surface_load_h
#define restshape_loads_surface_load_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/loads/load_parameters.h>
#include <restshape/loads/load_state.h>

namespace RestShape
{
  /**
   * The pressure on the pressure faces (Loads subsection):
   *
   *     p(x) = p0 + sum_k w_k rho_f max(0, a_k . (x - x_k))
   *
   * with p0 the uniform pressure (LoadState::pressure) and one term per
   * FluidColumn (LoadState::fluid: weight w_k, acceleration a_k pointing
   * down, x_k a point of its free surface), rho_f the fluid density when
   * Fluid load = hydrostatic pressure (else 0). Faces above a column's level
   * are drained of it. The faces of an opening of the skull carry p(x) less
   * the opening's part (LoadState::opening_pressure and opening_fluid).
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

    /// @p level: the scene fluid's free surface (m), also the reference
    /// point x_ref of the uniform pressure's potential.
    SurfaceLoad(const LoadParameters &loads, const dealii::Point<3> &level);

    /// Whether the pressure follows the current surface.
    bool
    follower() const
    {
      return is_follower;
    }
    /// Whether any pressure acts under @p load.
    bool
    acts(const LoadState &load) const;

    /// p(x) in Pa at the position @p x (m).
    double
    pressure(const LoadState        &load,
             const dealii::Point<3> &x,
             const Face              face = Face::covered) const;
    /// dp/dx in Pa/m.
    dealii::Tensor<1, 3>
    pressure_gradient(const LoadState        &load,
                      const dealii::Point<3> &x,
                      const Face              face = Face::covered) const;
    /// Q(x) (Pa m) with div Q = p: the potential's flux density.
    dealii::Tensor<1, 3>
    potential_flux(const LoadState        &load,
                   const dealii::Point<3> &x,
                   const Face              face = Face::covered) const;

    /// The scene's fluid under the acceleration @p a: one column through
    /// the level (none without a hydrostatic fluid).
    std::vector<FluidColumn>
    scene_fluid(const dealii::Tensor<1, 3> &a) const;

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
