// Pressure loads on the surface: a uniform pressure and a fluid's
// hydrostatic pressure, as follower or dead loads.
#ifndef restshape_forward_surface_load_h
#define restshape_forward_surface_load_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/base/parameters.h>
#include <restshape/forward/load_state.h>

namespace RestShape
{
  /**
   * The pressure on the pressure faces (Loads subsection):
   *
   *     p(x) = p0 + rho_f max(0, a . (x - x_level))
   *
   * with p0 the Surface pressure, a the body acceleration (m/s^2, pointing
   * down: the depth below the level is a . (x - x_level) / |a|), rho_f the
   * fluid density when Fluid load = hydrostatic pressure (else 0), x_level a
   * point of the free surface. Faces above the level are drained.
   *
   * A follower pressure acts on the current surface: the force on a face
   * element is -p(x) cof(F) N dA (Nanson), F = I + grad d the deformation
   * gradient from the mesh geometry X (normal N, area dA) to x = X + d. It
   * is conservative where the loaded surface is closed or held at its
   * edges, with potential  Pi = int Q(x) . cof(F) N dA,  div Q = p:
   *
   *     Q(x) = p0 / 3 (x - x_level) + rho_f s+^2 / (2 |a|^2) a,
   *     s = a . (x - x_level),  s+ = max(0, s).
   */
  class SurfaceLoad
  {
  public:
    /// @p level: a point of the free surface (m).
    SurfaceLoad(const LoadParameters &loads, const dealii::Point<3> &level);

    /// Whether the pressure follows the current surface.
    bool
    follower() const
    {
      return is_follower;
    }
    /// Whether any pressure acts under @p load.
    bool
    acts(const LoadState &load) const
    {
      return load.pressure != 0 || load.opening_pressure != 0 ||
             (fluid_density > 0 && load.acceleration.norm_square() > 0);
    }

    /// p(x) in Pa at the position @p x (m).
    double
    pressure(const LoadState &load, const dealii::Point<3> &x) const;
    /// dp/dx in Pa/m.
    dealii::Tensor<1, 3>
    pressure_gradient(const LoadState &load, const dealii::Point<3> &x) const;
    /// Q(x) (Pa m) with div Q = p: the potential's flux density.
    dealii::Tensor<1, 3>
    potential_flux(const LoadState &load, const dealii::Point<3> &x) const;

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
