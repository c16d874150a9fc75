// What Newton's method asks of the constraints of an active set (contact
// with an obstacle: ContactProblem implements it). The forward solver
// knows this interface only, so forward/ does not depend on contact/.
#ifndef restshape_solver_active_set_constraints_h
#define restshape_solver_active_set_constraints_h

#include <deal.II/lac/affine_constraints.h>

#include <restshape/solver/active_set_conditions.h>
#include <restshape/solver/linear_solver.h>

#include <string>
#include <utility>
#include <vector>

namespace RestShape
{
  /**
   * Inequality constraints that Newton's method of ForwardProblem handles
   * as an active set: at every iterate the set is updated from the state
   * and its forces, its nodes are constrained, the step is limited so that
   * no free node passes the obstacle, and a converged state is checked
   * against the conditions themselves before it is accepted. The methods
   * are documented at ContactProblem, the implementation.
   */
  class ActiveSetConstraints
  {
  public:
    virtual ~ActiveSetConstraints() = default;

    /// A new solve starts from displacement @p d (ghosted).
    virtual void
    begin_solve(const VectorType &d) = 0;

    /// The active and eligible flags of every node: saved with an
    /// equilibrium, restored with it when a step is taken back.
    using State = std::vector<std::pair<bool, bool>>;
    virtual State
    state() const = 0;
    virtual void
    set_state(const State &state) = 0;
    /// Forget the active set (a new problem starts).
    virtual void
    reset() = 0;

    /// A new active set at @p d; whether it changed.
    virtual bool
    update_active_set(const VectorType &d,
                      const VectorType &raw_residual,
                      const bool        first_iteration) = 0;
    /// The largest step length (<= 1) along the update @p delta.
    virtual double
    max_step(const VectorType &delta) const = 0;
    /// Add the constraints of the active set (not touching @p base's).
    virtual void
    add_constraints(dealii::AffineConstraints<double>       &constraints,
                    const dealii::AffineConstraints<double> &base) const = 0;

    /// After convergence with releases frozen: release adhesive nodes;
    /// whether Newton goes on.
    virtual bool
    thaw_if_adhesive(const VectorType &raw_residual) = 0;
    /// Whether the state of the last update meets the conditions.
    virtual bool
    is_satisfied() const = 0;
    /// Whether the constraints of the last update move nodes along the
    /// obstacle's surface by more than its gap tolerance (a node that
    /// follows the surface): the step is then taken whole, as after a
    /// change of the set.
    virtual bool
    moves_nodes_onto_surface() const = 0;
    /// The conditions at @p d against the obstacle itself.
    virtual ContactConditions
    check_conditions(const VectorType &d,
                     const VectorType &raw_residual,
                     const double      force_tolerance) const = 0;
    /// Release what @p violated names; whether Newton goes on.
    virtual bool
    enforce_conditions(const ContactConditions &violated,
                       const VectorType        &raw_residual,
                       const double             force_tolerance) = 0;

    /// What repeats when the rounds of enforce_conditions() cycle ("" else).
    virtual const std::string &
    cycle_text() const = 0;
    /// Why the conditions are not met at the state of the last update.
    virtual std::string
    unsettled_text() const = 0;
    /// ", contact N active (+a new, -r released)" for the progress line.
    virtual std::string
    progress_text() const = 0;
  };
} // namespace RestShape

#endif
