// SurfaceLoad: the uniform and the hydrostatic pressure, and Nanson's
// area vector with its derivative.
#include <deal.II/base/symmetric_tensor.h>

#include <restshape/loads/surface_load.h>

namespace RestShape
{
  using namespace dealii;

  const std::string SurfaceLoad::pressure_name = "Surface pressure",
                    SurfaceLoad::fluid_name    = "Fluid pressure",
                    SurfaceLoad::opening_pressure_name =
                      "Surface pressure off the opening",
                    SurfaceLoad::opening_fluid_name =
                      "Fluid pressure off the opening";

  SurfaceLoad::SurfaceLoad(const bool      follower,
                           const double    fluid_density,
                           const Point<3> &level)
    : level(level)
    , is_follower(follower)
    , fluid_density(fluid_density)
  {}

  namespace
  {
    std::vector<FluidColumn>
    fluid_of(const LoadState::Columns &columns)
    {
      std::vector<FluidColumn> fluid;
      for (const LoadColumn &c : columns)
        fluid.push_back(
          {column_vector(c, 0), Point<3>(column_vector(c, 3)), c.weight});
      return fluid;
    }
  } // namespace

  PressureNames::PressureNames()
    : pressure(SurfaceLoad::pressure_name)
    , fluid(SurfaceLoad::fluid_name)
    , opening_pressure(SurfaceLoad::opening_pressure_name)
    , opening_fluid(SurfaceLoad::opening_fluid_name)
  {}

  PressureNames::PressureNames(const std::string &pressure)
    : pressure(pressure)
  {}

  PressureField
  SurfaceLoad::field(const LoadState &load, const PressureNames &names)
  {
    PressureField f;
    f.pressure = load.weighted(names.pressure);
    if (!names.fluid.empty())
      f.fluid = fluid_of(load.columns(names.fluid));
    if (!names.opening_pressure.empty())
      f.opening_pressure = load.weighted(names.opening_pressure);
    if (!names.opening_fluid.empty())
      f.opening_fluid = fluid_of(load.columns(names.opening_fluid));
    return f;
  }

  namespace
  {
    /// s = a . (x - level) of column @p c at @p x (m^2/s^2; > 0: wetted).
    double
    depth(const FluidColumn &c, const Point<3> &x)
    {
      return c.acceleration * (x - c.level);
    }

    /// The uniform pressure a face carries.
    double
    uniform(const PressureField &load, const SurfaceLoad::Face face)
    {
      return face == SurfaceLoad::Face::covered ?
               load.pressure :
               load.pressure - load.opening_pressure;
    }

    /// @p f(column, weight) for each column a face carries (those of an
    /// opening with their weight negated on its faces).
    template <typename Function>
    void
    for_each_column(const PressureField    &load,
                    const SurfaceLoad::Face face,
                    const Function         &f)
    {
      for (const FluidColumn &c : load.fluid)
        f(c, c.weight);
      if (face == SurfaceLoad::Face::opened)
        for (const FluidColumn &c : load.opening_fluid)
          f(c, -c.weight);
    }
  } // namespace

  bool
  SurfaceLoad::acts(const PressureField &load) const
  {
    const auto wets = [](const std::vector<FluidColumn> &columns) {
      for (const FluidColumn &c : columns)
        if (c.weight != 0 && c.acceleration.norm_square() > 0)
          return true;
      return false;
    };
    return load.pressure != 0 || load.opening_pressure != 0 ||
           (fluid_density > 0 &&
            (wets(load.fluid) || wets(load.opening_fluid)));
  }

  double
  SurfaceLoad::pressure(const PressureField &load,
                        const Point<3>      &x,
                        const Face           face) const
  {
    double p = uniform(load, face);
    for_each_column(load, face, [&](const FluidColumn &c, const double w) {
      p += w * fluid_density * std::max(0., depth(c, x));
    });
    return p;
  }

  Tensor<1, 3>
  SurfaceLoad::pressure_gradient(const PressureField &load,
                                 const Point<3>      &x,
                                 const Face           face) const
  {
    Tensor<1, 3> g;
    for_each_column(load, face, [&](const FluidColumn &c, const double w) {
      if (depth(c, x) > 0)
        g += w * fluid_density * c.acceleration;
    });
    return g;
  }

  Tensor<1, 3>
  SurfaceLoad::potential_flux(const PressureField &load,
                              const Point<3>      &x,
                              const Face           face) const
  {
    Tensor<1, 3> q = uniform(load, face) / 3. * (x - level);
    for_each_column(load, face, [&](const FluidColumn &c, const double w) {
      const double a2 = c.acceleration.norm_square();
      const double s  = depth(c, x);
      if (fluid_density > 0 && a2 > 0 && s > 0)
        q += w * fluid_density * s * s / (2 * a2) * c.acceleration;
    });
    return q;
  }

  LoadState::Columns
  SurfaceLoad::fluid_columns(const Tensor<1, 3> &a, const Point<3> &at) const
  {
    if (fluid_density == 0 || a.norm_square() == 0)
      return {};
    std::vector<double> p = vector_parameters(a);
    for (unsigned int d = 0; d < 3; ++d)
      p.push_back(at[d]);
    return {{p, 1.}};
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
