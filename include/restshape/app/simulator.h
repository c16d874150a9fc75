// A scene run from start to end, in a fixed order (as in step-42):
// mesh, materials, checks, then for every refinement cycle setup, solve
// (forward, or the inverse rest-shape iteration), postprocess; finally the
// summary and the timing table.
#ifndef restshape_simulator_h
#define restshape_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <restshape/app/parameters.h>
#include <restshape/contact/contact.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/inverse/inverse_problem.h>
#include <restshape/io/output.h>
#include <restshape/material/material_table.h>
#include <restshape/mesh/labelled_mesh.h>
#include <restshape/postprocess/error_estimator.h>
#include <restshape/postprocess/postprocessor.h>
#include <restshape/postprocess/verification.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace RestShape
{
  class Simulator
  {
  public:
    /**
     * @p prm holds the effective parameters (written to parameters.prm),
     * @p prm_file is the scene file (for messages).
     */
    Simulator(const Parameters               &parameters,
              const dealii::ParameterHandler &prm,
              const std::string              &prm_file,
              const MPI_Comm                  comm);

    /**
     * Run the scene. Input errors throw InputError before anything is
     * written; a solver that fails writes summary.json (converged = false,
     * with its figures) and throws SolverFailure.
     */
    void
    run();

  private:
    /// The phases of run(), in their fixed order.
    void
    run_phases();
    /// summary.json of a run stopped by @p what (exit codes 2 and 3).
    void
    record_failure(const std::string &what);
    void
    make_mesh();
    /// The scene's checks that need only the mesh: labels, refinement,
    /// scenarios.
    void
    check_scene_on_mesh() const;
    /// InputError when every label is fixed in all directions.
    void
    check_something_is_free() const;
    /// InputError when a fixed boundary plane holds no boundary face.
    void
    check_fixed_planes() const;
    /// Those that need the forward problem: stability with a
    /// non-symmetric tangent, unheld pieces, unfixed components.
    void
    check_scene_on_problem() const;
    /// The labels Boundary conditions/Fixed labels holds (any component),
    /// and those with a boundary face in a fixed boundary plane.
    std::set<Label>
    held_labels() const;
    /// The pieces of the mesh that only a vertex or an edge joins to the
    /// held body, for the message of a failed solve ("" if none).
    std::string
    unheld_pieces_text() const;
    void
    setup_problems();
    /// AdmissibleTarget::check_placement(), on the target of a rest shape
    /// that carries one (rest_shape.msh).
    void
    check_obstacle_placement() const;
    /// The body's size, mass and the strains its loads impose, with
    /// warnings (LoadScales).
    void
    report_load_scales() const;
    VectorType
    initial_rest_shape() const;
    void
    prepare_output();
    /// Refine (cycle > 0), set up again and, with Adaptive
    /// refinement/Transfer solution, carry the displacement into @p guess
    /// and the rest displacement into @p rest; otherwise @p rest = 0 and
    /// @p guess is empty.
    /// The target of a rest mesh that carries one, as the first guess of
    /// a forward run's Newton (none in inverse runs or without a target).
    std::optional<VectorType>
    target_guess() const;
    void
    refine(VectorType &rest, std::optional<VectorType> &guess);
    /// @p guess: Newton's initial displacement at the full load (nullptr:
    /// load from the unloaded mesh).
    SolveStatistics
    solve_forward(const VectorType &rest, const VectorType *guess);
    SolveStatistics
    solve_inverse(const unsigned int cycle,
                  const VectorType  &initial_rest,
                  const VectorType  *guess);
    /// rest_shape.msh: the rest shape (vertices only: the edge nodes of
    /// quadratic elements are not in a linear mesh file), with the target
    /// and the image's masses it carries (gmsh_io.h).
    void
    write_rest_shape() const;
    /// With Solver/Check stability: the stability of the current
    /// equilibrium into summary.json and on screen; "" if stable, else
    /// the instability with its mode.
    std::string
    stability_text();
    /// With Solver/Check stability: stop (summary.json, SolverFailure) if
    /// the equilibrium of the cycle is unstable.
    void
    check_stability_of_equilibrium(const SolveStatistics &stats);
    /// Why the stability check does not run ("" if it does): Check
    /// stability = false, or a tangent that is not symmetric.
    std::string
    stability_not_checked_because() const;
    /// Every scenario, each from the equilibrium; the sections of those
    /// that did not converge. summary.json: scenarios_converged.
    std::vector<std::string>
    run_scenarios();
    /// One line for ScenarioFailure: which scenarios failed.
    std::string
    scenario_failure_text(const std::vector<std::string> &failed) const;
    /// Scenario/Enabled: both models under what the scenario changes;
    /// false if it did not converge (the next one still runs).
    bool
    run_scenario(const ScenarioParameters &scenario);
    void
    postprocess(const unsigned int cycle, const SolveStatistics &stats);
    void
    write_summary(const SolveStatistics &stats);

    const Parameters               &parameters;
    const PostprocessParameters     postprocess_parameters;
    const dealii::ParameterHandler &prm;
    const std::string               prm_file;
    const MPI_Comm                  comm;
    dealii::ConditionalOStream      pcout;
    dealii::TimerOutput             timer;
    dealii::Timer                   wall_timer;

    std::unique_ptr<LabelledMesh>      mesh;
    std::unique_ptr<MaterialTable>     materials;
    std::unique_ptr<ForwardProblem>    forward;
    std::unique_ptr<ContactProblem>    contact;
    std::unique_ptr<OutputWriter>      output;
    std::unique_ptr<ExactDisplacement> exact, exact_rest;

    Summary                                     summary;
    std::vector<std::unique_ptr<Postprocessor>> postprocessors;
    std::vector<std::vector<double>>            iteration_rows;
    unsigned int                                next_step = 0; // VTU numbering
    InverseResult                               inverse_result;
    /// The inverse iteration of the last cycle (its final VTU record gets
    /// the error estimate).
    std::unique_ptr<InverseProblem> inverse;
    ErrorEstimate                   estimate; // of the last cycle
  };
} // namespace RestShape

#endif
