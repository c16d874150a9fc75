// SurfaceLoad: the uniform and the hydrostatic pressure, and Nanson's
// area vector with its derivative.
#include <deal.II/base/symmetric_tensor.h>

#include <restshape/forward/surface_load.h>

namespace RestShape
{
  using namespace dealii;

  SurfaceLoad::SurfaceLoad(const LoadParameters &loads, const Point<3> &level)
    : level(level)
    , is_follower(loads.follower)
    , fluid_density(loads.hydrostatic ? loads.fluid_density : 0.)
  {}

  double
  SurfaceLoad::pressure(const LoadState &load, const Point<3> &x) const
  {
    const double s = load.acceleration * (x - level);
    return load.pressure + fluid_density * std::max(0., s);
  }

  Tensor<1, 3>
  SurfaceLoad::pressure_gradient(const LoadState &load, const Point<3> &x) const
  {
    const double s = load.acceleration * (x - level);
    return s > 0 ? fluid_density * load.acceleration : Tensor<1, 3>();
  }

  Tensor<1, 3>
  SurfaceLoad::potential_flux(const LoadState &load, const Point<3> &x) const
  {
    Tensor<1, 3> q  = load.pressure / 3. * (x - level);
    const double a2 = load.acceleration.norm_square();
    const double s  = load.acceleration * (x - level);
    if (fluid_density > 0 && a2 > 0 && s > 0)
      q += fluid_density * s * s / (2 * a2) * load.acceleration;
    return q;
  }

  Tensor<1, 3>
  cofactor_times(const Tensor<2, 3> &F, const Tensor<1, 3> &N)
  {
    // Column J of cof F is (column J+1) x (column J+2) of F.
    const Tensor<2, 3> Ft = transpose(F); // rows of Ft: columns of F
    Tensor<1, 3>       a;
    for (unsigned int J = 0; J < 3; ++J)
      a += N[J] * cross_product_3d(Ft[(J + 1) % 3], Ft[(J + 2) % 3]);
    return a;
  }

  Tensor<1, 3>
  cofactor_derivative(const Tensor<2, 3> &F,
                      const Tensor<1, 3> &N,
                      const unsigned int  c,
                      const Tensor<1, 3> &g)
  {
    Tensor<1, 3> e;
    e[c] = 1;
    return cross_product_3d(e, F * cross_product_3d(N, g));
  }

  double
  rest_area(const Tensor<2, 3> &grad_w, const Tensor<1, 3> &N)
  {
    return cofactor_times(Tensor<2, 3>(unit_symmetric_tensor<3>()) + grad_w, N)
      .norm();
  }
} // namespace RestShape
