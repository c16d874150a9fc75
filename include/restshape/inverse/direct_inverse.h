// The direct inverse: Newton's method on the equilibrium at the target
// geometry with the rest shape as the unknown.
#ifndef restshape_direct_inverse_h
#define restshape_direct_inverse_h

#include <deal.II/base/conditional_ostream.h>

#include <restshape/forward/forward_problem.h>
#include <restshape/inverse/three_field_pressures.h>
#include <restshape/solver/newton_watchdog.h>

#include <string>
#include <utility>

namespace RestShape
{
  /// What the direct inverse did.
  struct DirectInverseResult
  {
    bool         converged = false;
    std::string  failure;               // why not
    unsigned int newton_steps      = 0; // accepted Newton steps
    unsigned int jacobian_products = 0; // one residual assembly each
    unsigned int factorisations    = 0; // of the forward tangent
    double       relative_residual = 0; // |R| / |R(initial rest)|
  };

  /**
   * Find the rest displacement w = X_rest - X (X: the mesh, which is the
   * target) for which the target is in equilibrium under @p load:
   * R(d = 0; w) = 0 (or at the target of set_target()), R the forward residual
   * (external minus internal forces, with every load, support and constraint of
   * the forward problem; contact is not part of it). Newton's method in w,
   * Jacobian-free: the product with dR/dw is a finite difference (one
   * residual assembly), solved by right-preconditioned flexible GMRES
   * (FlexibleGmres) with the forward tangent dR/dd (factorised, or an
   * inner CG + AMG solve; for small strains dR/dw = -dR/dd, so GMRES needs
   * a few iterations) only as far as Eisenstat and Walker's forcing term
   * asks (loosely far from the solution); a backtracking line search on |R|
   * that never accepts a rest shape with an inverted cell, except that a
   * full step above its target is taken on trial (NewtonWatchdog, Solver/
   * Watchdog steps: the cantilever's large rotations); continuation in
   * the load (a failed increment is halved; after three failed increments
   * it gives up). A load step fails after 15 Newton steps or two in a row
   * (not on trial) that keep more than 90 % of the residual (the Newton
   * step in the rest shape is then a poor model).
   */
  class DirectInverse
  {
  public:
    DirectInverse(ForwardProblem &forward, dealii::ConditionalOStream &pcout);

    /// Start from @p rest (owned) and leave the result there; the forward
    /// problem is left in the state of the last residual assembly.
    DirectInverseResult
    solve(const LoadState &load, VectorType &rest);

    /**
     * Aim solve() at the target X + @p displacement (owned, m; by default
     * the mesh, zero), where the obstacle holds the body with the nodal
     * forces @p obstacle_force (owned, N; scaled with the load in the
     * continuation, zero at the fixed DoFs): R(d; w) + f_obstacle = 0.
     */
    void
    set_target(const VectorType &displacement,
               const VectorType &obstacle_force);

  private:
    /// The finite-difference step e along @p v.
    double
    difference_step(const VectorType &v) const;
    /// J @p v = (R(w + e v) - R(w)) / e into @p product, one residual
    /// assembly (@p r = R(w); @p trial: work space); counts the product.
    void
    jacobian_product(const VectorType &w,
                     const VectorType &r,
                     const VectorType &v,
                     VectorType       &trial,
                     VectorType       &product);

    /// R(d; w) at @p w (owned) into @p r; false if a cell inverts.
    bool
    residual(const VectorType &w, VectorType &r);
    /// Newton at the current load (fraction @p s of the scene's) from
    /// @p w until |R| <= @p tolerance |R0|; false (result.failure) if not.
    bool
    newton(VectorType &w, const double tolerance, const double s);
    /// A Newton update and how GMRES found it.
    struct Direction
    {
      VectorType   delta;
      unsigned int products = 0;    // GMRES iterations
      bool         solved   = true; // |J delta + r| <= eta |r| reached
    };
    /// The Newton update at @p w with residual @p r: flexible GMRES on
    /// J delta = -r to |J delta + r| <= @p eta |r|, right-preconditioned
    /// by the forward tangent.
    Direction
    newton_direction(const VectorType &w, const VectorType &r, double eta);
    /// The steps a full step on trial has to reach its target.
    unsigned int
    trial_steps() const;
    enum class Step
    {
      accepted, // |R| decreased (Armijo)
      on_trial, // the full step, let through by the watchdog
      failed    // no step decreased |R| without an inverted cell
    };
    /// Backtrack along @p delta until |R| decreases (Armijo) with no
    /// inverted cell, or take the full step on trial where @p watchdog
    /// lets it through; updates @p w and @p r.
    Step
    line_search(VectorType       &w,
                VectorType       &r,
                const VectorType &delta,
                NewtonWatchdog   &watchdog);
    /// Why a load step failed whose full step was on trial.
    static std::string
    trial_failure(const NewtonWatchdog &watchdog);

    ForwardProblem             &forward;
    dealii::ConditionalOStream &pcout;
    ThreeFieldPressures         pressures; // mixed, a pressure per cell
    LoadState                   load;
    VectorType                  d; // the displacement at the target
    VectorType                  target_displacement, obstacle_force;
    double                      fraction  = 1; // of the load, in continuation
    double                      reference = 1; // |R| at the start, full load
    DirectInverseResult         result;
  };
} // namespace RestShape

#endif
