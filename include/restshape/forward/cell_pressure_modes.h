// The linear pressure per cell of the mixed formulation on quadratic
// hexahedra (Q2-P1disc, the element of deal.II's step-44 after Simo,
// Taylor and Pister 1985): the dilatation J~ and the pressure p~ are
// linear on each cell, discontinuous across cells, and condensed. J~ is
// the L2 projection of J = det F onto the cell's linear functions over
// its rest volume; the volumetric energy is int U(J~) dV_rest; p~ is the
// projection of U'(J~). With the modes N_a, M_ab = int N_a N_b dV_rest and
// c_a = int N_a J dV_rest, J~ = N . M^-1 c; the residual is
// int p~ J F^-T : grad(v) dV_rest with p~ = N . M^-1 r, r_a = int N_a
// U'(J~) dV_rest; the tangent adds G^T M^-1 H M^-1 G to the law's, G_a =
// dc_a/dd and H_ab = int N_a U''(J~) N_b dV_rest. With one mode, N = 1,
// this is the mean dilatation (Q1-P0, Q2-P0).
#ifndef restshape_forward_cell_pressure_modes_h
#define restshape_forward_cell_pressure_modes_h

#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>

#include <restshape/material/material_law.h>

#include <array>
#include <vector>

namespace RestShape
{
  class CellPressureModes
  {
  public:
    /// 1 and three linear functions.
    static constexpr unsigned int n_modes = 4;

    /// The modes at the cell's quadrature points @p x (mesh coordinates,
    /// weights @p JxW): 1 and three linear functions of x orthogonal to it
    /// and to each other over the cell's mesh volume, each of mean square
    /// 1 (so that M is close to the rest volume times the identity).
    void
    reinit(const std::vector<dealii::Point<3>> &x,
           const std::vector<double>           &JxW);

    /// The same at the points of @p values (an FEValues of the cell).
    template <typename Values>
    void
    reinit(const Values &values)
    {
      points.resize(values.n_quadrature_points);
      weights.resize(values.n_quadrature_points);
      for (unsigned int q = 0; q < points.size(); ++q)
        {
          points[q]  = values.quadrature_point(q);
          weights[q] = values.JxW(q);
        }
      reinit(points, weights);
    }

    /// The modes' values at point @p q (n_modes of them).
    const double *
    at(const unsigned int q) const
    {
      return &values[q * n_modes];
    }

    /// From each point's J = det F and rest volume weight, the projected
    /// dilatation, its energy, pressure and stiffness under @p law; false
    /// where J~ is not positive at some point (an inverted cell).
    bool
    condense(const MaterialLaw         &law,
             const std::vector<double> &J,
             const std::vector<double> &dV_rest);

    /// sum_a N_a(x_q) coefficients[a]: a linear field at point @p q.
    double
    field_at(const unsigned int q, const double *coefficients) const;

    /// The mean of the linear field of @p coefficients over the rest volume.
    double
    mean(const double *coefficients) const;

    /// After condense(): int U(J~) dV_rest (J).
    double energy = 0;
    /// After condense(): the coefficients of J~ (M^-1 c) and of p~ (M^-1 r,
    /// Pa; U'(J~) is minus the pressure in compression).
    std::array<double, n_modes> dilatation{}, pressure{};
    /// After condense(): (M^-1 H)_aa (Pa), each mode's pressure per unit
    /// change of its dilatation, the others held.
    std::array<double, n_modes> mode_stiffness{};
    /// After condense(): M^-1 H M^-1 (Pa/m^6 in SI), the pressure's
    /// derivative in c = int N J dV_rest.
    dealii::FullMatrix<double> stiffness{n_modes, n_modes};

  private:
    std::vector<double>           values;  // N_a(x_q) at [q * n_modes + a]
    std::vector<dealii::Point<3>> points;  // reinit(Values)'s
    std::vector<double>           weights; // reinit(Values)'s
    dealii::FullMatrix<double>    mass{n_modes, n_modes}; // M (m^3)
    dealii::FullMatrix<double>    mass_inverse{n_modes, n_modes};
  };
} // namespace RestShape

#endif
