// What a run reports after each solve, as a list of small postprocessors
// (as in ASPECT): each gets the state of the solve and the reductions that
// several of them need, computed once.
#ifndef restshape_postprocess_postprocessor_h
#define restshape_postprocess_postprocessor_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <restshape/contact/contact.h>
#include <restshape/contact/contact_report.h>
#include <restshape/forward/forward_parameters.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/inverse/inverse_parameters.h>
#include <restshape/io/output.h>
#include <restshape/io/output_parameters.h>
#include <restshape/mesh/labelled_mesh.h>
#include <restshape/mesh/mesh_parameters.h>
#include <restshape/postprocess/error_estimator.h>
#include <restshape/postprocess/refinement_parameters.h>
#include <restshape/postprocess/verification.h>
#include <restshape/postprocess/verification_parameters.h>

#include <memory>
#include <vector>

namespace RestShape
{
  /// The collective reductions of a solve (each an MPI sum or maximum).
  struct SolveReductions
  {
    /// Displacement from the rest shape: nodal mean and largest (mm).
    double mean_displacement_mm = 0, max_displacement_mm = 0;
    double n_nodes = 0;
    /// Forces (N): the loads, the fixed supports' reaction, the obstacle,
    /// the elastic support, and the resultant of the surface loads.
    dealii::Tensor<1, 3> external, reaction, contact, support, surface;
    /// The obstacle's force by label (ContactReport::force_by_label()).
    std::map<Label, dealii::Tensor<1, 3>> contact_by_label;
    /// With an obstacle: active nodes that pull (accepted), and the nodes
    /// on fixed crease planes with their largest distance (m) from it.
    ContactReport::Adhesion         adhesion;
    std::pair<unsigned int, double> fixed_planes{0, 0.};

    /// |external + reaction + contact + support| (N).
    double
    imbalance() const
    {
      return (external + reaction + contact + support).norm();
    }
  };

  /// What every postprocessor sees after the solve of a cycle.
  /// The scene's parameters the postprocessors read (the parts' slices
  /// of the scene's Parameters, app/parameters.h).
  struct PostprocessParameters
  {
    const MeshParameters         &mesh;
    const ForwardParameters      &forward;
    const InverseParameters      &inverse;
    const RefinementParameters   &refinement;
    const VerificationParameters &verification;
    const OutputParameters       &output;
  };

  struct PostprocessInput
  {
    const PostprocessParameters &parameters;
    const LabelledMesh          &mesh;
    ForwardProblem              &forward;
    ContactProblem              *contact; // nullptr without an obstacle
    const SolveStatistics       &stats;
    const unsigned int           cycle;
    const VectorType            &u; // displacement from the rest shape, owned
    const SolveReductions       &reductions;
    const ErrorEstimate         &estimate;
    const ExactDisplacement     *exact;      // Verification, or nullptr
    const ExactDisplacement     *exact_rest; // of the rest shape, or nullptr
    const double                 inverse_mean_error; // m (inverse runs)
    const double                 wall_seconds;
    Summary                     &summary;
    OutputWriter                &output;
    dealii::ConditionalOStream  &pcout;
    dealii::TimerOutput         &timer;
  };

  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    virtual void
    execute(const PostprocessInput &in) = 0;
  };

  /// The reductions of the current solve; the obstacle's force by label
  /// with @p by_label (inverse runs report it at the target only).
  SolveReductions
  compute_reductions(const ForwardProblem &forward,
                     const ContactProblem *contact,
                     const VectorType     &u,
                     const bool            by_label,
                     const MPI_Comm        comm);

  /**
   * The postprocessors of a run, in the order they print: summary.json,
   * convergence table, screen report, nodal CSV (if asked for), VTU (if
   * asked for). @p next_step numbers the VTU records (shared with the
   * inverse iteration's records).
   */
  std::vector<std::unique_ptr<Postprocessor>>
  make_postprocessors(const PostprocessParameters &parameters,
                      unsigned int                &next_step);
} // namespace RestShape

#endif
