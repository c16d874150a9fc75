// What surgery changes after the rest shape, applied to the pre-stressed
// model and to the model stress-free in the same geometry.
#ifndef restshape_app_scenario_h
#define restshape_app_scenario_h

#include <deal.II/base/conditional_ostream.h>

#include <restshape/app/parameters.h>
#include <restshape/contact/contact.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/io/output.h>
#include <restshape/mesh/labelled_mesh.h>

#include <map>

namespace RestShape
{
  /// How a displacement field moves one tissue (one label).
  struct TissueShift
  {
    double               volume = 0;    // m^3, mesh geometry
    dealii::Tensor<1, 3> centroid;      // mean displacement over the volume
    double               max_shift = 0; // largest nodal |displacement|, m
    dealii::Point<3>     max_where;     // that node, mesh geometry
  };

  /// TissueShift of every label of @p forward's mesh for the field @p u.
  std::map<Label, TissueShift>
  tissue_shifts(const ForwardProblem &forward, const VectorType &u);

  /// InputError (without file name) for a scenario that changes nothing it
  /// says: a fluid level above the whole body (nothing drained), an
  /// opening that contains no face of the body.
  void
  check_scenario(const Parameters   &parameters,
                 const LabelledMesh &mesh,
                 const MPI_Comm      comm);

  /**
   * Scenario/Enabled: from the pre-stressed model's equilibrium (the
   * forward problem's current state: displacement d_eq, rest shape w,
   * contact set C), solve
   *  (1) the pre-stressed model under the changed load, from d_eq;
   *  (2) the model stress-free in the geometry X + d_eq (rest shape =
   *      equilibrium, the same contact set C) under the change of load
   *      alone (changed - scene), as the paper's Table 1 does;
   * and report the shift of each from X + d_eq, tissue by tissue. The
   * forward problem (and the contact) are left at the equilibrium again,
   * for the next scenario, whether this one converged or not: a scenario
   * fails alone.
   */
  class Scenario
  {
  public:
    Scenario(const Parameters                 &parameters,
             const ScenarioParameters         &scenario,
             ForwardProblem                   &forward,
             ContactProblem                   *contact,
             OutputWriter                     &output,
             Summary                          &summary,
             const dealii::ConditionalOStream &pcout);

    /// Solves both models and reports them; false if a solve failed (it
    /// is recorded in summary.json as NAME_converged = false with
    /// NAME_failure, and failure() says which model and why).
    bool
    run();

    /// "pre-stressed model: gave up at ...", empty after a success.
    const std::string &
    failure() const;

  private:
    /// The pre-stressed model from its equilibrium (displacement @p w_rest
    /// from the rest shape) under @p changed; with no change and no
    /// opening it stays.
    SolveStatistics
    solve_pre_stressed(const LoadState  &changed,
                       const LoadState  &change,
                       const VectorType &w_rest);
    /// The stress-free model, resting at the equilibrium @p d_eq with the
    /// contact set @p start_set, under the change alone: its shift from
    /// @p d_eq into @p shift. With no change it stays (shift 0).
    SolveStatistics
    solve_stress_free(const LoadState             &change,
                      const VectorType            &d_eq,
                      const ContactProblem::State &start_set,
                      VectorType                  &shift);
    /// forward.solve(), with a linear solver's failure (SolverFailure) as
    /// a failed solve.
    SolveStatistics
    solve(const LoadState &load, const VectorType &rest);
    /// Records the failed solve @p s of @p model; returns false.
    bool
    failed(const SolveStatistics &s, const std::string &model);
    /// The CSV, the VTU (with the pre-stressed model's @p contact_fields),
    /// the summary and the screen table.
    void
    report(const VectorType &prestressed,
           const VectorType &stress_free,
           const VectorType &contact_fields);
    /// One line that says what the scenario changes.
    std::string
    description(const LoadState &scene, const LoadState &changed) const;

    const Parameters                 &parameters;
    const ScenarioParameters         &scenario;
    ForwardProblem                   &forward;
    ContactProblem                   *contact;
    OutputWriter                     &output;
    Summary                          &summary;
    const dealii::ConditionalOStream &pcout;
    /// Contact nodes and pressure faces in the craniotomy.
    unsigned int opened_nodes = 0, opened_faces = 0;
    std::string  failure_text;
  };
} // namespace RestShape

#endif
