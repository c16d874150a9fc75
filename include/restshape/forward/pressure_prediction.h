// The pressure of the mixed formulation's tangent, as the three-field
// Newton step predicts it (Simo, Taylor and Pister; deal.II's step-44
// keeps the cell's pressure as an unknown of its own). The condensed
// pressure U'(J_mean) of a state a Newton step has just reached carries
// K times the step's second-order change of volume: 5,000 times mu at
// nu = 0.4999, so that the tangent's geometric term p (dJ x F^-T - ...)
// there is nothing like the tissue's. The three-field step instead moves
// the pressure along its linearisation, p0 + U''/V g . (d - d0), from the
// state of the last tangent (d0, its pressure p0 and volume gradient g).
// The residual stays the condensed one, so an equilibrium is what it was;
// at convergence d = d0 and the tangent is the exact one again.
#ifndef restshape_forward_pressure_prediction_h
#define restshape_forward_pressure_prediction_h

#include <algorithm>
#include <cstddef>
#include <vector>

namespace RestShape
{
  class PressurePrediction
  {
  public:
    /// Forget every cell: @p n_cells active cells of @p n_dofs DoFs each.
    void
    reset(const unsigned int n_cells, const unsigned int n_dofs)
    {
      n = n_dofs;
      pressure0.assign(n_cells, 0.);
      stiffness.assign(n_cells, 0.);
      gradient.assign(std::size_t(n_cells) * n, 0.);
      d0.assign(std::size_t(n_cells) * n, 0.);
      w0.assign(std::size_t(n_cells) * n, 0.);
      known.assign(n_cells, 0);
    }

    /// Forget the recorded linearisations (the state jumped: a converged
    /// state is its own, consistent, linearisation).
    void
    forget()
    {
      std::fill(known.begin(), known.end(), 0);
    }

    /// The pressure the tangent of @p cell uses at its local coefficients
    /// @p d and @p w (n_dofs each): the linearisation recorded at the same
    /// rest shape @p w, else @p condensed (U'(J_mean) of this state).
    double
    pressure(const unsigned int cell,
             const double      *d,
             const double      *w,
             const double       condensed) const
    {
      if (cell >= known.size() || !known[cell])
        return condensed;
      const std::size_t at     = std::size_t(cell) * n;
      double            change = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          if (w[i] != w0[at + i])
            return condensed;
          change += gradient[at + i] * (d[i] - d0[at + i]);
        }
      return pressure0[cell] + stiffness[cell] * change;
    }

    /// Record the linearisation of @p cell at a tangent's state: its
    /// coefficients, the condensed pressure U'(J_mean) (Pa), U''/V
    /// (Pa/m^3) and the volume gradient g = dv/dd (m^2) in local DoF order.
    void
    record(const unsigned int         cell,
           const double              *d,
           const double              *w,
           const double               pressure,
           const double               d2U_over_V,
           const std::vector<double> &g)
    {
      if (cell >= known.size())
        return;
      const std::size_t at = std::size_t(cell) * n;
      for (unsigned int i = 0; i < n; ++i)
        {
          d0[at + i]       = d[i];
          w0[at + i]       = w[i];
          gradient[at + i] = g[i];
        }
      pressure0[cell] = pressure;
      stiffness[cell] = d2U_over_V;
      known[cell]     = 1;
    }

  private:
    unsigned int        n = 0;
    std::vector<double> pressure0, stiffness, gradient, d0, w0;
    std::vector<char>   known;
  };
} // namespace RestShape

#endif
