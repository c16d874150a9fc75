// The reference contact solve of a load-carrying rest shape.
#include <restshape/base/input_error.h>
#include <restshape/contact/admissible_target.h>
#include <restshape/contact/contact_report.h>
#include <restshape/inverse/carried_load.h>

namespace RestShape
{
  using namespace dealii;

  CarriedLoad
  carried_load(ForwardProblem   &forward,
               ContactProblem   &contact,
               const VectorType &target_shift,
               const LoadState  &load,
               const double      share)
  {
    CarriedLoad result;
    result.share = share;
    result.touching_nodes =
      AdmissibleTarget(contact).keep_contacts(target_shift);
    contact.reset();
    if (result.touching_nodes == 0)
      {
        // Nothing can carry a load: the least-force rest shape.
        AdmissibleTarget(contact).restore_contacts();
        result.converged = true;
        result.forces    = forward.discretization().zero_vector();
        return result;
      }
    // Stress-free at the target: the rest shape is the target itself.
    forward.set_state(target_shift, target_shift, LoadState());
    const SolveStatistics stats = forward.solve(load, target_shift);
    result.converged            = stats.converged;
    result.failure              = stats.failure;
    result.newton_iterations    = stats.newton_iterations;
    if (stats.converged)
      {
        const VectorType &r    = forward.raw_residual();
        result.reference_force = ContactReport(contact).total_force(r);
        result.active_nodes    = ContactReport(contact).n_active();
        result.forces = AdmissibleTarget(contact).forces(r, target_shift);
        result.forces *= share;
        const MPI_Comm comm =
          forward.discretization().dof_handler().get_communicator();
        for (const Node &node : forward.discretization().owned_nodes())
          for (unsigned int k = 0; k < 3; ++k)
            result.stated_force[k] += result.forces[node.dofs[k]];
        result.stated_force = Utilities::MPI::sum(result.stated_force, comm);
      }
    AdmissibleTarget(contact).restore_contacts();
    contact.reset();
    return result;
  }

  std::string
  CarriedLoad::text() const
  {
    const std::string head =
      "Skull load: the body stress-free at the target, settling under the "
      "loads with contact at the " +
      std::to_string(touching_nodes) + " nodes touching the obstacle there";
    if (touching_nodes == 0)
      return "Skull load: no node touches the obstacle at the target: it "
             "carries nothing there (the least-force rest shape)";
    if (!converged)
      return head + ", did not converge (" + failure + ")";
    return head + ", rests on " + std::to_string(active_nodes) +
           " of them with " + number_text(reference_force.norm()) +
           " N; the rest shape carries " + number_text(share) +
           " of it: " + number_text(stated_force.norm()) + " N (" +
           std::to_string(newton_iterations) + " Newton steps)";
  }
} // namespace RestShape
