// CellPressureModes: the linear pressure per cell (Q2-P1disc).
#include <restshape/forward/cell_pressure_modes.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  void
  CellPressureModes::reinit(const std::vector<Point<3>> &x,
                            const std::vector<double>   &JxW)
  {
    const unsigned int n = x.size();
    values.assign(n * n_modes, 0.);
    double   volume = 0;
    Point<3> centre;
    for (unsigned int q = 0; q < n; ++q)
      {
        volume += JxW[q];
        centre += JxW[q] * x[q];
      }
    centre /= volume;
    // Gram-Schmidt on 1, x, y, z (about the centre) in the inner product
    // <f, g> = int f g dV / V of the mesh cell.
    const auto inner = [&](const unsigned int a, const unsigned int b) {
      double s = 0;
      for (unsigned int q = 0; q < n; ++q)
        s += values[q * n_modes + a] * values[q * n_modes + b] * JxW[q];
      return s / volume;
    };
    for (unsigned int q = 0; q < n; ++q)
      {
        values[q * n_modes] = 1;
        for (unsigned int d = 0; d < 3; ++d)
          values[q * n_modes + 1 + d] = x[q][d] - centre[d];
      }
    for (unsigned int a = 1; a < n_modes; ++a)
      {
        for (unsigned int b = 0; b < a; ++b)
          {
            const double projection = inner(a, b);
            for (unsigned int q = 0; q < n; ++q)
              values[q * n_modes + a] -= projection * values[q * n_modes + b];
          }
        const double norm = std::sqrt(inner(a, a));
        for (unsigned int q = 0; q < n; ++q)
          values[q * n_modes + a] /= norm;
      }
  }

  double
  CellPressureModes::field_at(const unsigned int q,
                              const double      *coefficients) const
  {
    const double *N = at(q);
    double        s = 0;
    for (unsigned int a = 0; a < n_modes; ++a)
      s += N[a] * coefficients[a];
    return s;
  }

  double
  CellPressureModes::mean(const double *coefficients) const
  {
    // int N_a dV_rest = M_a0, the mode N_0 being 1.
    double s = 0;
    for (unsigned int a = 0; a < n_modes; ++a)
      s += mass(a, 0) * coefficients[a];
    return s / mass(0, 0);
  }

  bool
  CellPressureModes::condense(const MaterialLaw         &law,
                              const std::vector<double> &J,
                              const std::vector<double> &dV_rest)
  {
    const unsigned int          n = J.size();
    std::array<double, n_modes> c{};
    mass = 0;
    for (unsigned int q = 0; q < n; ++q)
      {
        const double *N = at(q);
        for (unsigned int a = 0; a < n_modes; ++a)
          {
            c[a] += N[a] * J[q] * dV_rest[q];
            for (unsigned int b = 0; b < n_modes; ++b)
              mass(a, b) += N[a] * N[b] * dV_rest[q];
          }
      }
    mass_inverse.invert(mass);
    for (unsigned int a = 0; a < n_modes; ++a)
      {
        dilatation[a] = 0;
        for (unsigned int b = 0; b < n_modes; ++b)
          dilatation[a] += mass_inverse(a, b) * c[b];
      }
    std::array<double, n_modes> r{};
    FullMatrix<double>          H(n_modes, n_modes);
    energy = 0;
    for (unsigned int q = 0; q < n; ++q)
      {
        const double J_projected = field_at(q, dilatation.data());
        if (!(J_projected > 0))
          return false;
        const MaterialLaw::Volumetric U = law.volumetric(J_projected);
        const double                 *N = at(q);
        energy += U.U * dV_rest[q];
        for (unsigned int a = 0; a < n_modes; ++a)
          {
            r[a] += N[a] * U.dU * dV_rest[q];
            for (unsigned int b = 0; b < n_modes; ++b)
              H(a, b) += N[a] * U.d2U * N[b] * dV_rest[q];
          }
      }
    FullMatrix<double> MinvH(n_modes, n_modes);
    mass_inverse.mmult(MinvH, H);
    MinvH.mmult(stiffness, mass_inverse);
    for (unsigned int a = 0; a < n_modes; ++a)
      {
        pressure[a] = 0;
        for (unsigned int b = 0; b < n_modes; ++b)
          pressure[a] += mass_inverse(a, b) * r[b];
        mode_stiffness[a] = MinvH(a, a);
      }
    return true;
  }
} // namespace RestShape
