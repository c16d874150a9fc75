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
    /// Forget every cell: @p n_cells active cells of @p n_dofs DoFs each,
    /// @p n_modes pressure modes per cell (1: a constant pressure).
    void
    reset(const unsigned int n_cells,
          const unsigned int n_dofs,
          const unsigned int n_modes)
    {
      n = n_dofs;
      m = n_modes;
      pressure0.assign(std::size_t(n_cells) * m, 0.);
      stiffness.assign(std::size_t(n_cells) * m * m, 0.);
      gradient.assign(std::size_t(n_cells) * m * n, 0.);
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

    /// The pressures (one per mode) the tangent of @p cell uses at its
    /// local coefficients @p d and @p w (n_dofs each), into @p out: the
    /// linearisation recorded at the same rest shape @p w, else @p
    /// condensed (U'(J_mean) of this state, or the modes' projection).
    void
    pressure(const unsigned int cell,
             const double      *d,
             const double      *w,
             const double      *condensed,
             double            *out) const
    {
      std::copy(condensed, condensed + m, out);
      if (cell >= known.size() || !known[cell])
        return;
      const std::size_t at = std::size_t(cell) * n;
      for (unsigned int i = 0; i < n; ++i)
        if (w[i] != w0[at + i])
          return;
      for (unsigned int a = 0; a < m; ++a)
        out[a] = pressure0[std::size_t(cell) * m + a];
      for (unsigned int b = 0; b < m; ++b)
        {
          const double *g      = &gradient[(std::size_t(cell) * m + b) * n];
          double        change = 0;
          for (unsigned int i = 0; i < n; ++i)
            change += g[i] * (d[i] - d0[at + i]);
          for (unsigned int a = 0; a < m; ++a)
            out[a] += stiffness[(std::size_t(cell) * m + a) * m + b] * change;
        }
    }

    /// Record the linearisation of @p cell at a tangent's state: its
    /// coefficients, the condensed pressures (Pa, one per mode), their
    /// derivatives in the modes' volumes (m x m, row-major; with one mode
    /// U''/V, Pa/m^3) and the volume gradients (m^2) in local DoF order,
    /// mode after mode.
    void
    record(const unsigned int         cell,
           const double              *d,
           const double              *w,
           const double              *pressures,
           const double              *derivatives,
           const std::vector<double> &g)
    {
      if (cell >= known.size())
        return;
      const std::size_t at = std::size_t(cell) * n;
      for (unsigned int i = 0; i < n; ++i)
        {
          d0[at + i] = d[i];
          w0[at + i] = w[i];
        }
      std::copy(g.begin(),
                g.begin() + std::size_t(m) * n,
                gradient.begin() + std::size_t(cell) * m * n);
      std::copy(pressures, pressures + m, pressure0.begin() + cell * m);
      std::copy(derivatives,
                derivatives + m * m,
                stiffness.begin() + std::size_t(cell) * m * m);
      known[cell] = 1;
    }

  private:
    unsigned int        n = 0, m = 1;
    std::vector<double> pressure0, stiffness, gradient, d0, w0;
    std::vector<char>   known;
  };
} // namespace RestShape

#endif
