// The rest-shape (inverse) iteration of Sellier (2011) and Morin et al.
// (2015), optionally Anderson-accelerated, on top of the forward problem.
#ifndef restshape_inverse_problem_h
#define restshape_inverse_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <restshape/contact/contact.h>
#include <restshape/contact/target_relaxation.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/inverse/anderson.h>
#include <restshape/inverse/carried_load.h>
#include <restshape/inverse/direct_inverse.h>
#include <restshape/inverse/inverse_parameters.h>
#include <restshape/io/output.h>

#include <string>
#include <vector>

namespace RestShape
{
  /// One row of iterations.csv.
  struct InverseIterationRecord
  {
    unsigned int iteration;
    double       mean_error;       // m, against the admissible target
    double       max_error;        // m
    double       mean_image_error; // m, against the image (the mesh)
    double       max_image_error;  // m
    unsigned int newton_iterations;
    unsigned int active_contact_nodes;
    double       wall_seconds;
    bool         anderson; // the rest shape came from an Anderson step
  };

  struct InverseResult
  {
    bool         converged = false;
    std::string  reason;                        // why it stopped unconverged
    unsigned int iterations        = 0;         // accepted rest-shape updates
    unsigned int forward_solves    = 0;         // including rejected ones
    unsigned int newton_iterations = 0;         // all forward solves
    unsigned int rejected_steps    = 0;         // rejected Anderson steps
    unsigned int partial_updates   = 0;         // plain updates taken in part
    double       mean_error = 0, max_error = 0; // m, admissible target
    double       mean_image_error = 0, max_image_error = 0; // m, the image
    /// The unreachable part of the target: the nodes the admissible
    /// target moves off the image (contact candidates beyond the obstacle,
    /// and the nodes a relaxation moved), and their largest and mean
    /// distance to the image (m).
    unsigned int unreachable_nodes = 0;
    double       unreachable_max = 0, unreachable_mean = 0;
    /// Where the projection inverted cells: how the target was relaxed.
    TargetRelaxationResult relaxation;
    /// The direct inverse before the fixed point (Method = direct).
    DirectInverseResult direct;
    /// Skull load share > 0: the reference contact solve and the load the
    /// rest shape carries.
    CarriedLoad carried;
  };

  /**
   * Find w = X_rest - X (X: the mesh = target geometry) such that the
   * equilibrium x = X + d from X_rest under the scene's loads and contact
   * matches the target: d = 0 at every node. With contact, the target is
   * the admissible one: contact candidates of the image beyond the
   * obstacle are projected onto it (d = t there), since no equilibrium can
   * reach them. Fixed point (Sellier): e = t - d (the nodal error
   * X_target - X_equilibrium), w <- w + e. Each forward
   * solve starts from the previous equilibrium; the mass stays that of the
   * target geometry.
   *
   * Safeguards: a rest shape with an inverted or degenerate cell is never
   * used (an Anderson step falls back to the plain update, a plain update is
   * shortened, at most 6 halvings); an Anderson step that increases the
   * error, or whose forward solve fails, is rejected (the plain update from
   * the last iterate follows); when the forward solve of a plain update runs
   * out of load-step halvings part of the way, the fraction it reached is
   * taken as the update, and when it reached none the iteration stops;
   * divergence (error above twice the initial one, or growing for three
   * iterations), stagnation (no 1 % improvement of the best error in 10
   * iterations) and a stall (three partial updates in a row without such
   * an improvement) stop the iteration with the figures.
   */
  class InverseProblem
  {
  public:
    InverseProblem(const InverseParameters    &parameters,
                   ForwardProblem             &forward,
                   ContactProblem             *contact,
                   OutputWriter               *output,
                   dealii::TimerOutput        &timer,
                   dealii::ConditionalOStream &pcout,
                   const dealii::Timer        &wall_timer);

    /**
     * Run from the rest displacement @p initial_rest (owned; zero: the
     * target is the first rest shape). VTU output steps are numbered from
     * @p first_step. If @p guess is given (owned; e.g. the equilibrium
     * displacement of the previous refinement cycle), the first forward
     * solve starts Newton from it at the full load. Leaves the forward
     * problem at the last accepted equilibrium.
     */
    InverseResult
    run(const VectorType  &initial_rest,
        const unsigned int first_step,
        const VectorType  *guess = nullptr);

    const std::vector<InverseIterationRecord> &
    records() const;

    /// Write the last VTU record of the iteration again, with the cell
    /// fields @p cells (the error estimate of the final equilibrium).
    void
    rewrite_final_output(const std::vector<CellField> &cells);

  private:
    double
    measure(const std::pair<double, double> &errors) const;
    /// Mean and max over the nodes of |X_admissible - X_equilibrium|.
    std::pair<double, double>
    target_errors() const;
    /// Whether @p errors (mean, max) meet Tolerance and Maximum error
    /// tolerance.
    bool
    converged(const std::pair<double, double> &errors) const;
    /// The admissible target (AdmissibleTarget::shift()),
    /// with its figures in @p result.
    void
    set_admissible_target(InverseResult &result);
    /// Where the projection inverts cells, smooth the target there
    /// (TargetRelaxation); whether it did.
    bool
    relax_admissible_target(InverseResult &result);
    /// The unreachable part's figures in @p result: the nodes the target
    /// moves off the image, and how far.
    void
    set_unreachable(InverseResult &result) const;
    void
    record(const unsigned int     iteration,
           const SolveStatistics &stats,
           const bool             anderson);
    /// The VTU record @p step of the series (its time value too).
    void
    write_output(const unsigned int            step,
                 const std::vector<CellField> &cells = {});
    /// The step of the last record written (-1: none).
    unsigned int last_step = static_cast<unsigned int>(-1);
    /// The errors of the last equilibrium into @p result, and @p reason
    /// (empty: converged) on screen.
    InverseResult
    finish(InverseResult &result, const std::string &reason) const;
    /// Iteration 0: the forward solve from @p initial_rest (or, where the
    /// image crosses the obstacle, from the admissible target), loaded from
    /// zero or started from @p guess; @p start: the rest shape it used.
    SolveStatistics
    first_solve(const VectorType &initial_rest,
                const VectorType *guess,
                const LoadState  &load,
                InverseResult    &result,
                VectorType       &start);
    /// One direct inverse from @p rest (updated) under @p load, aiming at
    /// the admissible target where @p result's carried load says so.
    DirectInverseResult
    solve_direct_inverse(const LoadState     &load,
                         const InverseResult &result,
                         VectorType          &rest);
    /// Method = direct: the direct inverse from @p initial_rest into
    /// @p rest (its figures in @p result.direct), for the image without
    /// contact even where the image crosses the obstacle; whether it
    /// converged. Skipped (false) where only the obstacle holds the body
    /// in some direction (directions_only_contact_holds()). From a rest
    /// shape other than the target's (a previous cycle's), a failure
    /// tries again from the target.
    bool
    direct_inverse(const VectorType &initial_rest,
                   const LoadState  &load,
                   InverseResult    &result,
                   VectorType       &rest);
    /// The displacement components ("x, z") in which no node is fixed and
    /// no elastic support acts, where there is an obstacle: without
    /// contact the tangent is singular in them. Empty if none.
    std::string
    directions_only_contact_holds() const;
    /// The next rest shape from the iterate @p w and its residual @p f:
    /// Anderson's (if @p accelerate) or the plain w + f, shortened until
    /// no cell inverts. Returns "" or why there is none.
    std::string
    next_rest_shape(const VectorType    &w,
                    const VectorType    &f,
                    AndersonAccelerator &anderson,
                    const bool           accelerate,
                    const unsigned int   iteration,
                    const double         last_error,
                    VectorType          &candidate,
                    bool                &accelerated) const;

    const InverseParameters             parameters;
    ForwardProblem                     &forward;
    ContactProblem                     *contact;
    OutputWriter                       *output;
    dealii::TimerOutput                &timer;
    dealii::ConditionalOStream         &pcout;
    const dealii::Timer                &wall_timer;
    std::vector<InverseIterationRecord> history;
    /// X_admissible - X at every DoF (owned, m): zero but at contact
    /// candidates of the image beyond the obstacle.
    VectorType target_shift;
  };
} // namespace RestShape

#endif
