// The direct inverse's cell pressures in the mixed formulation with a
// pressure per cell (P2-P0 tetrahedra, Q1-P0 and Q2-P0 hexahedra): its
// Newton steps keep each cell's pressure as the three-field step of
// Simo, Taylor and Pister (deal.II's step-44) moves it, not the condensed
// U'(J_mean) of the rest shape a step has reached (see cell_pressures.h).
#ifndef restshape_inverse_three_field_pressures_h
#define restshape_inverse_three_field_pressures_h

#include <restshape/forward/forward_problem.h>

#include <vector>

namespace RestShape
{
  /**
   * A Newton step in the rest shape w moves the cells' mean dilatations
   * J_mean(w) by their linearisation plus a second-order change; in
   * U'(J_mean) that change is multiplied by the bulk modulus K, and the
   * tangent (and the Jacobian products of the direct inverse) built with
   * that pressure describe no nearby state (at nu = 0.4999 the direct
   * inverse of the inflated shell gave up at a quarter of its load). The
   * three-field step keeps the pressure p of each cell as an unknown of
   * its own: p_k+1 = U'(J_k) + U''(J_k) alpha dJ, where dJ is the change
   * of J_mean along the step's direction (linearised, a finite
   * difference) and alpha the line search's step. The products and the
   * preconditioner of the next step use the residual whose pressure is
   * U'(J_mean) + (p_k+1 - U'(J_k+1)): its derivative at w_k+1 is the
   * three-field tangent. The right-hand side stays the condensed
   * residual, so the rest shape found is the same.
   */
  class ThreeFieldPressures
  {
  public:
    explicit ThreeFieldPressures(ForwardProblem &forward);

    /// Whether the forward problem is mixed (a pressure per cell, or per
    /// vertex: the averaged nodal pressure of linear tetrahedra).
    bool
    enabled() const;
    /// The next step starts from the condensed pressures (a new load, a
    /// rest shape restored).
    void
    forget();
    /// At the start of a step, right after the residual assembly at its
    /// rest shape w_k: set the forward problem's pressure offsets.
    void
    begin_step();
    /// After the assembly at w_k + @p e delta (delta: the step's
    /// direction): the change of each cell's J_mean per unit step.
    void
    record_direction(const double e);
    /// Remove the offsets (trial states of the line search are judged by
    /// the condensed residual).
    void
    end_products();
    /// The line search took the step @p alpha along the direction.
    void
    accept(const double alpha);

  private:
    ForwardProblem            &forward;
    std::vector<PressurePoint> at_step; // the cells at w_k
    std::vector<double>        pressure, change;
    bool                       known = false; // pressure is a step's
  };
} // namespace RestShape

#endif
