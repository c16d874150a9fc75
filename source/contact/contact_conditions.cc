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
  ContactProblem::check_placement(const VectorType *shift) const
  {
    // Nodes beyond the obstacle by more than this fraction of the body's
    // size count as misplaced; a segmented skull that cuts a millimetre
    // into a brain does not.
    constexpr double deep_fraction = 0.05;
    const double     size          = forward.mesh().diameter();
    unsigned int     outside       = 0;
    double           clearance     = std::numeric_limits<double>::max();
    for (const Candidate &c : candidates)
      if (c.owned)
        {
          const Point<3> x =
            shift != nullptr ? position(c.node, *shift) : c.node.position;
          const double gap = obstacle->gap(x).gap;
          outside += (gap < -deep_fraction * size);
          clearance = std::min(clearance, std::abs(gap));
        }
    const MPI_Comm     comm = communicator();
    const unsigned int n    = n_candidates();
    outside                 = Utilities::MPI::sum(outside, comm);
    clearance               = Utilities::MPI::min(clearance, comm);
    const bool too_many =
      outside > parameters.max_outside_fraction * std::max(n, 1u);
    if (!too_many && clearance <= size)
      {
        check_fixed_labels_enclosed(deep_fraction * size);
        return;
      }
    const auto box = [](const Point<3> &a, const Point<3> &b) {
      char buffer[160];
      std::snprintf(buffer,
                    sizeof(buffer),
                    "(%.4g, %.4g, %.4g)-(%.4g, %.4g, %.4g) mm",
                    mm_per_m * a[0],
                    mm_per_m * a[1],
                    mm_per_m * a[2],
                    mm_per_m * b[0],
                    mm_per_m * b[1],
                    mm_per_m * b[2]);
      return std::string(buffer);
    };
    std::vector<Point<3>> positions;
    for (const Node &node : forward.relevant_nodes())
      positions.push_back(node.position);
    const BoundingBox<3> mesh_box(positions);
    const auto [low, high]  = obstacle->bounding_box();
    const std::string boxes = "; mesh box " +
                              box(mesh_box.get_boundary_points().first,
                                  mesh_box.get_boundary_points().second) +
                              ", obstacle box " + box(low, high);
    if (too_many)
      throw InputError(
        parameters.obstacle_file,
        "Contact/Obstacle file",
        std::to_string(outside) + " of " + std::to_string(n) +
          " contact candidates lie on the wrong side of the obstacle, deeper "
          "than " +
          number_text(mm_per_m * deep_fraction * size) +
          " mm (5 % of the body), in the " +
          std::string(shift != nullptr ? "target the mesh carries" :
                                         "mesh geometry") +
          " (more than Contact/Maximum outside fraction = " +
          number_text(parameters.max_outside_fraction) + boxes +
          "); expected the obstacle around the body (check Contact/Side and "
          "Contact/Length unit; raise the fraction for an obstacle meant to "
          "cut into the body)");
    throw InputError(parameters.obstacle_file,
                     "Contact/Obstacle file",
                     "every contact candidate is farther from the obstacle "
                     "than the body's size (nearest " +
                       number_text(mm_per_m * clearance) + " mm, body " +
                       number_text(mm_per_m * size) + " mm" + boxes +
                       "): no contact can occur; expected the obstacle near "
                       "the body (check Contact/Length unit)");
  }

  void
  ContactProblem::check_fixed_labels_enclosed(const double depth) const
  {
    // A fixed node beyond the obstacle can never come back: the obstacle
    // is misplaced (or the wrong side is allowed). A node fixed in some
    // components only comes back if its free ones lead inside: along the
    // obstacle's normal by at least free_normal_fraction.
    constexpr double free_normal_fraction = 0.5;
    const auto      &fixed = forward.scene_parameters().boundary.fixed_labels;
    for (const FixedLabel &f : fixed)
      {
        std::set<unsigned int> all, outside;
        double                 worst = 0;
        for (const auto &cell : forward.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned() && cell->material_id() == f.label)
            for (const unsigned int v : cell->vertex_indices())
              if (all.insert(cell->vertex_index(v)).second)
                {
                  const Gap g         = obstacle->gap(cell->vertex(v));
                  double    free_part = 0;
                  for (unsigned int c = 0; c < 3; ++c)
                    free_part +=
                      f.components[c] ? 0. : g.gradient[c] * g.gradient[c];
                  if (std::sqrt(free_part) >= free_normal_fraction)
                    continue;
                  if (g.gap < -depth)
                    outside.insert(cell->vertex_index(v));
                  worst = std::max(worst, -g.gap);
                }
        unsigned int   beyond = outside.size(), n = all.size();
        const MPI_Comm comm = communicator();
        beyond              = Utilities::MPI::sum(beyond, comm);
        n                   = Utilities::MPI::sum(n, comm);
        worst               = Utilities::MPI::max(worst, comm);
        if (beyond > 0)
          throw InputError(
            parameters.obstacle_file,
            "Contact/Obstacle file",
            "the obstacle does not enclose fixed label " +
              std::to_string(f.label) + ": " + std::to_string(beyond) +
              " of its " + std::to_string(n) +
              " vertices lie on the wrong side, by up to " +
              number_text(mm_per_m * worst) +
              " mm; expected the fixed labels on the allowed side (check "
              "Contact/Side, Contact/Length unit and the obstacle's "
              "placement)");
      }
  }

  VectorType
  ContactProblem::admissible_target_shift() const
  {
    VectorType shift = forward.zero_vector();
    for (const Candidate &c : candidates)
      if (c.owned)
        {
          const Gap g = obstacle->gap(c.node.position);
          if (g.gap < -gap_tolerance)
            for (unsigned int k = 0; k < 3; ++k)
              shift[c.node.dofs[k]] = -g.gap * g.gradient[k];
        }
    shift.compress(VectorOperation::insert);
    return shift;
  }

  namespace
  {
    /// A candidate that may no longer take contact.
    template <typename Candidate>
    void
    take_out(Candidate &c)
    {
      c.removed  = true;
      c.eligible = false;
      c.active   = false;
    }

    /// The candidates of @p candidates taken out for the reason @p why
    /// (a flag of theirs) may take contact again.
    template <typename Candidates, typename Flag>
    void
    put_back(Candidates &candidates, const Flag why)
    {
      for (auto &c : candidates)
        if (c.*why)
          c.removed = c.*why = false;
    }
  } // namespace

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
    put_back(candidates, &Candidate::opened);
    constraints_changed = true;
  }

  unsigned int
  ContactProblem::keep_target_contacts(const VectorType &target_shift)
  {
    const VectorType t    = forward.ghosted_copy(target_shift);
    unsigned int     kept = 0;
    for (Candidate &c : candidates)
      {
        if (c.removed)
          continue;
        if (obstacle->gap(position(c.node, t)).gap <= gap_tolerance)
          {
            kept += c.owned;
            continue;
          }
        take_out(c);
        c.set_aside = true;
      }
    constraints_changed = true;
    return Utilities::MPI::sum(kept, communicator());
  }

  void
  ContactProblem::restore_contact()
  {
    put_back(candidates, &Candidate::set_aside);
    constraints_changed = true;
  }


  VectorType
  ContactProblem::target_forces(const VectorType &raw_residual,
                                const VectorType &target_shift) const
  {
    const VectorType t      = forward.ghosted_copy(target_shift);
    VectorType       forces = forward.zero_vector();
    for (const Candidate &c : candidates)
      if (c.owned && c.active)
        {
          const double lambda = std::max(0., contact_force(c, raw_residual));
          const Gap    g      = obstacle->gap(position(c.node, t));
          for (unsigned int k = 0; k < 3; ++k)
            forces[c.node.dofs[k]] = lambda * g.gradient[k];
        }
    forces.compress(VectorOperation::insert);
    return forces;
  }

  std::vector<Tensor<1, 3>>
  ContactProblem::target_normals() const
  {
    std::vector<double> mine;
    for (const Candidate &c : candidates)
      if (c.owned)
        {
          const Gap g = obstacle->gap(c.node.position);
          if (g.gap <= gap_tolerance)
            for (unsigned int k = 0; k < 3; ++k)
              mine.push_back(g.gradient[k]);
        }
    std::vector<Tensor<1, 3>> normals;
    for (const auto &part : Utilities::MPI::all_gather(communicator(), mine))
      for (unsigned int i = 0; i + 2 < part.size(); i += 3)
        normals.push_back(Tensor<1, 3>({part[i], part[i + 1], part[i + 2]}));
    return normals;
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
