// ContactProblem: the strict check of the contact conditions against the
// obstacle's surface, and what Newton does when a converged state fails it.
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <restshape/base/input_error.h>
#include <restshape/base/mpi_reductions.h>
#include <restshape/base/units.h>
#include <restshape/contact/contact.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    using Violation = ContactConditions::Violation;

    void
    add(Violation &v, const double value, const Point<3> &where)
    {
      ++v.nodes;
      if (value > v.worst)
        {
          v.worst = value;
          v.where = where;
        }
    }

    /// Sum the counts and take the worst over the ranks.
    void
    reduce(Violation &v, const MPI_Comm comm)
    {
      std::tie(v.worst, v.where) = largest_with_place(v.worst, v.where, comm);
      v.nodes                    = Utilities::MPI::sum(v.nodes, comm);
    }

  } // namespace



  void
  ContactProblem::take_out(Candidate &c)
  {
    c.removed  = true;
    c.eligible = false;
    c.active   = false;
  }

  void
  ContactProblem::put_back(bool Candidate::*why)
  {
    for (Candidate &c : candidates)
      if (c.*why)
        c.removed = c.*why = false;
  }

  unsigned int
  ContactProblem::remove_contact(const Region &opening)
  {
    unsigned int removed = 0;
    for (Candidate &c : candidates)
      if (opening.contains(c.node.position))
        {
          take_out(c);
          c.opened = true;
          removed += c.owned;
        }
    constraints_changed = true;
    return Utilities::MPI::sum(removed, communicator());
  }

  void
  ContactProblem::close_openings()
  {
    put_back(&Candidate::opened);
    constraints_changed = true;
  }



  double
  ContactProblem::node_force_tolerance(const Candidate &c,
                                       const double     force_tolerance) const
  {
    return std::max(force_tolerance, parameters.pull_tolerance * c.area_lumped);
  }

  ContactConditions
  ContactProblem::check_conditions(const VectorType &d,
                                   const VectorType &raw_residual,
                                   const double      force_tolerance) const
  {
    TimerOutput::Scope  scope(timer, "Contact search");
    ContactConditions   result;
    double              penetration = -std::numeric_limits<double>::max();
    std::vector<double> lambda;
    for (const Candidate &c : candidates)
      {
        if (!c.owned || c.removed)
          continue;
        const Point<3> x   = position(c, d);
        const double   gap = obstacle->gap(x).gap;
        result.outside += (gap < -gap_tolerance);
        if (!c.eligible)
          continue;
        penetration = std::max(penetration, -gap);
        if (gap < -gap_tolerance)
          add(result.through, -gap, x);
        if (!c.active)
          continue;
        if (gap > gap_tolerance)
          add(result.off, gap, x);
        // The node's own multipliers: one, or one per held plane.
        if (c.planes.planes().size() > 1)
          reaction(c, raw_residual, &lambda);
        else
          lambda = {contact_force(c, raw_residual)};
        const double least = *std::min_element(lambda.begin(), lambda.end());
        if (least < -node_force_tolerance(c, force_tolerance))
          add(result.pulling, -least / c.area_lumped, x);
      }
    const MPI_Comm comm = communicator();
    for (Violation *v : {&result.through, &result.off, &result.pulling})
      reduce(*v, comm);
    result.outside         = Utilities::MPI::sum(result.outside, comm);
    result.max_penetration = Utilities::MPI::max(penetration, comm) + 0.;
    return result;
  }

  std::size_t
  ContactProblem::round_signature(const ContactConditions &violated) const
  {
    std::size_t hash = 0;
    for (const Candidate &c : candidates)
      if (c.owned && c.active)
        hash += std::hash<types::global_dof_index>()(c.node.dofs[0]) *
                (2654435761u + c.planes.planes().size());
    hash = Utilities::MPI::sum(hash, communicator());
    for (const Violation *v :
         {&violated.through, &violated.off, &violated.pulling})
      hash =
        hash * 31 + std::hash<std::string>()(
                      std::to_string(v->nodes) + ' ' +
                      std::to_string(std::lround(1e9 * v->where[0])) + ' ' +
                      std::to_string(std::lround(1e9 * v->where[1])));
    return hash;
  }

  bool
  ContactProblem::enforce_conditions(const ContactConditions &violated,
                                     const VectorType        &raw_residual,
                                     const double             force_tolerance)
  {
    if (violated.satisfied())
      return false;
    // A converged state seen before in this solve (the same active nodes
    // and the same violations) would only lead to the same rounds again.
    if (!rounds.insert(round_signature(violated)).second)
      {
        cycle = "the same converged state comes back (" + violated.text() + ")";
        return false;
      }
    unsigned int        changed = 0, released = 0;
    std::vector<double> lambda;
    for (Candidate &c : candidates)
      {
        if (!c.owned || !c.active)
          continue;
        // Planes (held or fixed) that carried the node off the surface or
        // through it, past the end of their faces: for the rest of the
        // solve it follows the surface itself (its distance, which is
        // continuous) along the planes' mean normal, still active. (Let go
        // to follow the faces again, it would alternate between them, hold
        // their planes again and come back here: a cycle of rounds.)
        if (carried_off_surface(c))
          {
            follow_surface(c);
            ++changed;
            continue;
          }
        if (c.planes.planes().size() > 1)
          {
            reaction(c, raw_residual, &lambda);
            for (unsigned int k = 0; k < lambda.size(); ++k)
              if (lambda[k] < -node_force_tolerance(c, force_tolerance))
                c.dropped |= 1u << k;
            if (c.dropped == 0)
              continue;
            ++changed;
            if (c.dropped + 1 != (1u << lambda.size()))
              continue; // some planes stay
            c.dropped = 0;
          }
        else if (!(contact_force(c, raw_residual) <
                   -node_force_tolerance(c, force_tolerance)))
          continue;
        else
          ++changed;
        c.active = false;
        c.pulled = true;
        ++released;
      }
    for (Candidate &c : candidates)
      drop_planes(c, c.dropped);
    share_flags();
    const MPI_Comm comm = communicator();
    n_released          = Utilities::MPI::sum(released, comm);
    n_added             = 0;
    constraints_changed = true;
    // Releases stay frozen: the nodes released here come back only through
    // the obstacle, the other pulling nodes are released at the Newton
    // steps below the load (thaw_if_adhesive(); a lift-off front moves by a
    // row per release). A free phase after each round lets the whole set wander
    // again for 10-12 Newton steps to release 1-9 nodes: P2 brain on the
    // skulls, benchmarks/contact_stress, 260 Newton steps in 6 cases with
    // such phases, 145 without (doc/changes/contact-steps.md).
    releases_frozen = true;
    return Utilities::MPI::sum(changed, comm) > 0;
  }
} // namespace RestShape
