// ContactProblem: candidates, the primal-dual active set, thaws of pulling
// nodes and the constraints for Newton (the held planes of crease nodes are
// in held_planes.cc, what it reports in contact_report.cc).
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/base/input_error.h>
#include <restshape/contact/contact.h>
#include <restshape/mesh/cavity_walls.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// The secant slope of a node that follows the surface is at least this
    /// (its move at most 5 times its gap; Candidate::surface_slope).
    constexpr double min_surface_slope = 0.2;
    /// Moves along the normal at most this long (m) leave the slope as it
    /// was (the distance to the obstacle carries round-off of 1e-17 m).
    constexpr double smallest_measured_move = 1e-14;
  } // namespace

  ContactProblem::ContactProblem(const ContactParameters &parameters,
                                 const Discretization    &discretization,
                                 const StateReader       &state,
                                 const double             newton_tolerance,
                                 const double             max_youngs_modulus,
                                 TimerOutput             &timer)
    : gap_tolerance(parameters.gap_tolerance > 0 ?
                      parameters.gap_tolerance :
                      std::max(1e-10, newton_tolerance) *
                        discretization.mesh().diameter())
    , parameters(parameters)
    , discretization(discretization)
    , forward_state(state)
    , max_youngs_modulus(max_youngs_modulus)
    , timer(timer)
  {
    TimerOutput::Scope scope(timer, "Contact search");
    obstacle = std::make_unique<Obstacle>(parameters.obstacle_file,
                                          parameters.length_unit,
                                          parameters.inside);
  }

  ContactProblem::~ContactProblem() = default;

  void
  ContactProblem::setup()
  {
    TimerOutput::Scope scope(timer, "Contact search");
    const auto        &fe = discretization.fe();
    std::map<types::global_dof_index, unsigned int> node_of_dof;
    const auto &nodes = discretization.relevant_nodes();
    for (unsigned int n = 0; n < nodes.size(); ++n)
      node_of_dof[nodes[n].dofs[0]] = n;

    candidates.clear();
    faces.clear();
    std::map<types::global_dof_index, unsigned int> candidate_of_dof;
    FEFaceValues<3>                                 fv(discretization.mapping(),
                       fe,
                       discretization.face_quadrature(),
                       update_values | update_JxW_values |
                         update_normal_vectors);
    std::vector<types::global_dof_index>            dofs(fe.n_dofs_per_cell());
    const auto &constraints = discretization.base_constraints();
    // The walls of cavities inside the body (ventricles) can never touch
    // an obstacle around it: they are no candidates (nor searched).
    const CavityWalls cavities(discretization.mesh());
    n_cavity_wall_faces = 0;

    for (const auto &cell :
         discretization.dof_handler().active_cell_iterators())
      {
        if (cell->is_artificial() ||
            (!parameters.labels.empty() &&
             !parameters.labels.count(cell->material_id())))
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            if (!discretization.mesh().at_surface(*cell, f))
              continue;
            if (cavities.n_cavities() > 0 && cavities.contains(*cell, f))
              {
                n_cavity_wall_faces += cell->is_locally_owned();
                continue;
              }
            cell->get_dof_indices(dofs);
            fv.reinit(cell, f);
            double              face_area = 0, mass_sum = 0;
            Face                face;
            std::vector<double> mass;
            for (const unsigned int q : fv.quadrature_point_indices())
              {
                face_area += fv.JxW(q);
                face.normal += fv.normal_vector(q) * fv.JxW(q);
              }
            face.normal /= face.normal.norm();
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                if (fe.system_to_component_index(i).first != 0)
                  continue;
                // A shape function without support on the face vanishes
                // there (FE_SimplexP::has_support_on_face() answers true for
                // every shape function in deal.II 9.4).
                double m = 0, a = 0;
                for (const unsigned int q : fv.quadrature_point_indices())
                  {
                    m +=
                      fv.shape_value(i, q) * fv.shape_value(i, q) * fv.JxW(q);
                    a += fv.shape_value(i, q) * fv.JxW(q);
                  }
                if (m <= 1e-12 * face_area)
                  continue;
                const Node &node = nodes[node_of_dof.at(dofs[i])];
                // Fully fixed nodes, and hanging nodes (their parents carry
                // the contact), are not candidates.
                std::array<bool, 3> fixed;
                bool                hanging = false;
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    fixed[c] = discretization.is_fixed(node.dofs[c]);
                    hanging |=
                      constraints.is_constrained(node.dofs[c]) && !fixed[c];
                  }
                if (hanging || (fixed[0] && fixed[1] && fixed[2]))
                  continue;
                auto it = candidate_of_dof.find(dofs[i]);
                if (it == candidate_of_dof.end())
                  {
                    Candidate c;
                    c.node  = node;
                    c.fixed = fixed;
                    c.owned = discretization.locally_owned_dofs().is_element(
                      node.dofs[0]);
                    it = candidate_of_dof.emplace(dofs[i], candidates.size())
                           .first;
                    candidates.push_back(c);
                  }
                face.nodes.push_back(it->second);
                mass.push_back(m);
                face.integral.push_back(a);
                mass_sum += m;
              }
            // HRZ lumping: the diagonal of the face mass matrix, scaled to
            // the face area (positive for every element type).
            for (unsigned int k = 0; k < face.nodes.size(); ++k)
              {
                face.lumped.push_back(mass[k] * face_area / mass_sum);
                candidates[face.nodes[k]].area_lumped += face.lumped.back();
              }
            if (!face.nodes.empty())
              faces.push_back(face);
          }
      }

    h_min    = discretization.mesh().minimum_cell_diameter();
    c_scaled = parameters.active_set_constant * max_youngs_modulus / h_min;
    history.clear();
  }

  Point<3>
  ContactProblem::position(const Candidate &c, const VectorType &d) const
  {
    return position(c.node, d);
  }

  Point<3>
  ContactProblem::position(const Node &node, const VectorType &d)
  {
    Point<3> x = node.position;
    for (unsigned int k = 0; k < 3; ++k)
      x[k] += d[node.dofs[k]];
    return x;
  }

  double
  ContactProblem::contact_force(const Candidate  &c,
                                const VectorType &raw_residual) const
  {
    return reaction(c, raw_residual) * c.normal;
  }

  Tensor<1, 3>
  ContactProblem::reaction(const Candidate     &c,
                           const VectorType    &raw_residual,
                           std::vector<double> *multipliers) const
  {
    // At equilibrium f_ext - f_int + sum_i lambda_i n_i = 0 at the node:
    // lambda = -r . n on one plane, least squares over held planes.
    Tensor<1, 3> r;
    for (unsigned int k = 0; k < 3; ++k)
      r[k] = -raw_residual[c.node.dofs[k]];
    const std::vector<Plane> &held = c.planes.planes();
    if (held.empty())
      return (r * c.normal) * c.normal;
    const unsigned int m = held.size();
    FullMatrix<double> gram(m, m);
    Vector<double>     rhs(m), lambda(m);
    for (unsigned int i = 0; i < m; ++i)
      {
        rhs[i] = held[i].normal * r;
        for (unsigned int j = 0; j < m; ++j)
          gram(i, j) = held[i].normal * held[j].normal;
      }
    gram.gauss_jordan();
    gram.vmult(lambda, rhs);
    Tensor<1, 3> force;
    for (unsigned int i = 0; i < m; ++i)
      force += lambda[i] * held[i].normal;
    if (multipliers != nullptr)
      multipliers->assign(lambda.begin(), lambda.end());
    return force;
  }

  void
  ContactProblem::share_flags()
  {
    // The owner of a node decides; ghost copies follow, so that every
    // process builds the same constraints.
    const MPI_Comm comm = communicator();
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      {
        for (Candidate &c : candidates)
          c.dropped = 0;
        return;
      }
    VectorType flags(discretization.locally_owned_dofs(), comm);
    for (const Candidate &c : candidates)
      if (c.owned)
        flags[c.node.dofs[0]] = (c.active ? 1 : 0) + (c.eligible ? 2 : 0) +
                                4 * c.dropped +
                                (c.follow_surface ? follow_surface_flag : 0);
    flags.compress(VectorOperation::insert);
    const VectorType ghosted = discretization.ghosted_copy(flags);
    for (Candidate &c : candidates)
      if (!c.owned)
        {
          const int f = static_cast<int>(std::lround(ghosted[c.node.dofs[0]]));
          c.active    = (f & 1) != 0;
          c.eligible  = (f & 2) != 0;
          if ((f & follow_surface_flag) != 0 && !c.follow_surface)
            follow_surface(c);
          // Held planes its owner let go (thaw_if_adhesive()).
          drop_planes(c, (f % follow_surface_flag) / 4);
        }
    for (Candidate &c : candidates)
      c.dropped = 0;
  }

  void
  ContactProblem::drop_planes(Candidate &c, const unsigned int mask)
  {
    if (c.planes.drop(mask))
      c.normal = c.planes.normal();
  }

  void
  ContactProblem::begin_solve(const VectorType &d)
  {
    TimerOutput::Scope scope(timer, "Contact search");
    history.clear();
    releases_frozen = false;
    n_added = n_released = 0;
    n_updates = n_thaws = 0;
    constraints_changed = false;
    cycle.clear();
    rounds.clear();
    for (Candidate &c : candidates)
      {
        c.follow_surface    = false;
        const Point<3> x    = position(c, d);
        const Gap      g    = obstacle->gap(x);
        c.gap               = g.gap;
        c.normal            = g.normal;
        c.previous_position = x;
        // Warm start: the active set of the last solve, for nodes that are
        // on the allowed side and within a cell size of the obstacle now.
        // A forward simulation brings every node onto the allowed side; the
        // one-sided rule of the inverse iteration lets a node that starts
        // beyond the obstacle free until it has been on the allowed side.
        c.eligible = !c.removed && (!one_sided || g.gap >= -gap_tolerance);
        c.active   = c.active && c.eligible && g.gap < h_min;
        c.pulled   = false;
        c.grazing  = false;
        let_go(c);
        c.planes.reset();
      }
    share_flags();
  }

  void
  ContactProblem::follow_surface(Candidate &c)
  {
    c.normal         = c.planes.normal();
    c.follow_surface = true;
    c.surface_slope  = 1;
    let_go(c);
  }

  bool
  ContactProblem::carried_off_surface(const Candidate &c) const
  {
    // Planes (held or fixed) that carried the node off the surface or
    // through it: the strict check lets them go (enforce_conditions()),
    // and so does the active-set update for fixed planes once releases are
    // frozen (held ones it re-planes itself).
    return !c.planes.planes().empty() && std::abs(c.gap) > gap_tolerance;
  }

  void
  ContactProblem::measure_surface_slope(Candidate      &c,
                                        const Point<3> &x,
                                        const double    gap)
  {
    // Its constraint moves it along the fixed normal, while the gap is the
    // distance to a surface at an angle to it (a crease): the node slides
    // along the surface as it moves and keeps a part of its gap, by about
    // 0.4 per Newton step (the P1 brain onto the cutting skull at 1 g
    // along +x: 11 linear steps after the strict check). The gap's change
    // per unit of the move (a secant) scales the next move instead.
    const double move = c.normal * (x - c.previous_position);
    if (std::abs(move) <= smallest_measured_move)
      return; // no move since the last update
    // A slope outside (0, 1] is not the surface's angle (the node slid
    // onto other faces, or the body around it moved it): no scaling.
    const double slope = (gap - c.gap) / move;
    c.surface_slope =
      slope > 0 && slope <= 1 ? std::max(slope, min_surface_slope) : 1;
  }

  void
  ContactProblem::let_go(Candidate &c)
  {
    c.planes.let_go();
    c.planes_imposed = true;
  }

  double
  ContactProblem::constrained_gap(const Candidate &c)
  {
    if (!(c.planes.fixed() && c.active && !c.planes.planes().empty()))
      return c.gap;
    return c.planes.constrained_gap(!c.planes_imposed);
  }

  ContactProblem::State
  ContactProblem::state() const
  {
    State s(candidates.size());
    for (unsigned int i = 0; i < candidates.size(); ++i)
      s[i] = {candidates[i].active, candidates[i].eligible};
    return s;
  }

  void
  ContactProblem::set_state(const State &s)
  {
    if (s.size() != candidates.size())
      return;
    for (unsigned int i = 0; i < candidates.size(); ++i)
      {
        Candidate &c                   = candidates[i];
        std::tie(c.active, c.eligible) = s[i];
        c.active                       = c.active && !c.removed;
        c.eligible                     = c.eligible && !c.removed;
      }
  }

  void
  ContactProblem::reset()
  {
    for (Candidate &c : candidates)
      c.active = false;
  }

  bool
  ContactProblem::update_active_set(const VectorType &d,
                                    const VectorType &raw_residual,
                                    const bool        first_iteration)
  {
    TimerOutput::Scope scope(timer, "Contact search");
    const MPI_Comm     comm = communicator();
    n_added = n_released = 0;
    std::size_t hash     = 0;
    for (Candidate &c : candidates)
      {
        const Point<3> x = position(c, d);
        const Gap      g = obstacle->gap(x);
        if (c.follow_surface && c.active)
          measure_surface_slope(c, x, g.gap);
        c.gap = g.gap;
        // An active node follows the closest face (the exact gradient of
        // its gap), or holds the planes of a crease; an inactive node has
        // the smoothed normal. (Active nodes on the smoothed normal while
        // releases were free, switched to the faces when they froze: 239
        // Newton steps in the 16 P1 cases of doc/changes/contact-steps.md
        // against 220 on the faces throughout, and every constraint
        // changed at the switch.)
        if (c.follow_surface && c.active)
          ; // its normal stays (follow_surface())
        else if (c.active)
          {
            c.planes.update(
              x, g, gap_tolerance, parameters.plane_changes, c.normal);
            // Left to the strict check of the converged state, each such
            // node cost a round of 2 to 4 Newton steps (the P1 brain on
            // the cutting skull, 48 cases of benchmarks/contact_stress: 83
            // of 596 steps after a round of the check, 39 with this).
            if (releases_frozen && c.planes.fixed() && carried_off_surface(c))
              follow_surface(c);
          }
        else
          {
            c.normal         = g.normal;
            c.follow_surface = false;
            let_go(c);
          }
        c.planes.set_closest_face(x, g);
        if (c.owned && !c.eligible && !c.removed &&
            (g.gap >= -gap_tolerance ||
             obstacle->n_crossings(c.previous_position, x) >= 2))
          c.eligible = true;
        c.previous_position = x;
        if (!c.owned)
          continue;

        bool now_active = false;
        if (c.eligible)
          {
            // Pressure of an active node; no release on the first iteration
            // (the residual is that of another state).
            const double p =
              !c.active       ? 0. :
              first_iteration ? std::numeric_limits<double>::max() :
                                contact_force(c, raw_residual) / c.area_lumped;
            now_active = p - c_scaled * (c.gap - gap_tolerance) > 0;
            // A node released for pulling (thaw_if_adhesive) comes back
            // only if it goes through the obstacle.
            if (c.pulled && !c.active)
              {
                now_active = c.gap < -gap_tolerance;
                c.grazing  = c.grazing || now_active;
              }
            if (releases_frozen && c.active)
              now_active = true;
          }
        n_added += (now_active && !c.active);
        n_released += (!now_active && c.active);
        c.active = now_active;
        if (now_active)
          hash +=
            std::hash<types::global_dof_index>()(c.node.dofs[0]) * 2654435761u;
      }
    share_flags();
    n_added    = Utilities::MPI::sum(n_added, comm);
    n_released = Utilities::MPI::sum(n_released, comm);
    hash       = Utilities::MPI::sum(hash, comm);
    // A release or plane change since the last update (thaw_if_adhesive(),
    // enforce_conditions()) changed the constraints too: the next step is
    // taken whole, as after any change of the set.
    const bool changed  = n_added + n_released > 0 || constraints_changed;
    constraints_changed = false;
    // Cycling: an active set seen before in this solve comes back. Then
    // nodes may still be added but no longer released, which ends the cycle.
    if (changed && history.count(hash) && !releases_frozen)
      releases_frozen = true;
    // A soft body pivoting against a curved obstacle can wander through
    // many active sets without repeating one: after Free active-set updates the
    // set only grows, which ends in a converged state; thaw_if_adhesive()
    // then releases nodes that pull.
    if (++n_updates >= parameters.free_updates)
      releases_frozen = true;
    history.insert(hash);
    return changed;
  }

  bool
  ContactProblem::thaw_if_adhesive(const VectorType &raw_residual)
  {
    if (!releases_frozen || n_thaws >= 5)
      return false;
    // Each node's own multiplier decides (its contact force, or those of
    // its held planes), as in update_active_set(); not the recovered
    // pressure, which at the corners of quadratic faces is the mean of the
    // neighbours' (pressures()) and could release a corner that pushes.
    // Nodal contact forces scatter around zero at the rim of a contact
    // zone (P1 especially): a pull below 0.1 % of the total contact force
    // is accepted; a larger one releases exactly the pulling nodes and the
    // pulling planes of crease nodes (the rest of the set stays, releases
    // stay frozen). A node released before that came back through the
    // obstacle (grazing) pulls when held and penetrates when free:
    // releasing it again here would only repeat that; it is held, and the
    // strict check of the converged state decides (enforce_conditions()).
    double                    push = 0, pull = 0;
    std::vector<unsigned int> pulling;
    std::vector<double>       lambda;
    for (unsigned int i = 0; i < candidates.size(); ++i)
      if (candidates[i].owned && candidates[i].active)
        {
          Candidate &c = candidates[i];
          if (c.grazing)
            {
              push += std::max(0., contact_force(c, raw_residual));
              continue;
            }
          if (c.planes.planes().size() > 1)
            {
              reaction(c, raw_residual, &lambda);
              for (unsigned int k = 0; k < lambda.size(); ++k)
                if (lambda[k] < 0)
                  {
                    pull -= lambda[k];
                    c.dropped |= 1u << k;
                  }
                else
                  push += lambda[k];
              // Every plane pulls: the node is released.
              if (c.dropped + 1 == (1u << lambda.size()))
                {
                  c.dropped = 0;
                  pulling.push_back(i);
                }
              continue;
            }
          const double force = contact_force(c, raw_residual);
          if (force < 0)
            {
              pull -= force;
              pulling.push_back(i);
            }
          else
            push += force;
        }
    const MPI_Comm comm = communicator();
    push                = Utilities::MPI::sum(push, comm);
    pull                = Utilities::MPI::sum(pull, comm);
    if (pull <= 1e-3 * push)
      {
        for (Candidate &c : candidates)
          c.dropped = 0;
        return false;
      }
    for (Candidate &c : candidates)
      drop_planes(c, c.dropped);
    for (const unsigned int i : pulling)
      {
        candidates[i].active = false;
        candidates[i].pulled = true;
      }
    share_flags();
    n_released =
      Utilities::MPI::sum(static_cast<unsigned int>(pulling.size()), comm);
    n_added = 0;
    ++n_thaws;
    constraints_changed = true;
    return true;
  }

  double
  ContactProblem::max_step(const VectorType &delta) const
  {
    double alpha = 1;
    for (const Candidate &c : candidates)
      if (c.owned && c.eligible && !c.active)
        {
          double rate = 0;
          for (unsigned int k = 0; k < 3; ++k)
            rate += c.normal[k] * delta[c.node.dofs[k]];
          if (rate < 0)
            alpha = std::min(alpha, std::max(c.gap + 0.25 * h_min, 0.) / -rate);
        }
    return Utilities::MPI::min(alpha, communicator());
  }

  void
  ContactProblem::add_constraints(AffineConstraints<double>       &constraints,
                                  const AffineConstraints<double> &base) const
  {
    // Planes that cannot be imposed (too few free components, or nearly
    // tangential ones) give way to one plane: for a node on fixed planes
    // their mean plane (a linear constraint too), else the closest face's
    // normal with the distance to the surface.
    for (const Candidate &c : candidates)
      if (c.active)
        {
          c.planes_imposed =
            !c.planes.planes().empty() &&
            add_plane_constraints(c, c.planes.planes(), constraints, base);
          if (c.planes_imposed)
            continue;
          const bool   mean = c.planes.fixed() && !c.planes.planes().empty();
          const double gap = c.follow_surface ? c.gap / c.surface_slope : c.gap;
          add_plane_constraints(c,
                                {mean ? c.planes.mean_plane() :
                                        Plane{c.normal, Point<3>(), gap}},
                                constraints,
                                base);
        }
  }

  bool
  ContactProblem::add_plane_constraints(
    const Candidate                 &c,
    const std::vector<Plane>        &planes,
    AffineConstraints<double>       &constraints,
    const AffineConstraints<double> &base) const
  {
    // N delta = -g for the m planes (rows n_i), solved for the m free
    // components S whose block of N is best conditioned (largest |det|):
    // delta_S = N_S^-1 (-g - N_R delta_R) over the other free components R.
    const auto               &dofs = c.node.dofs;
    std::vector<unsigned int> free;
    for (unsigned int j = 0; j < 3; ++j)
      if (!c.fixed[j] && !base.is_constrained(dofs[j]))
        free.push_back(j);
    const unsigned int m = planes.size();
    if (m > free.size())
      return false;
    std::vector<unsigned int> best, subset;
    double                    best_det = 0;
    FullMatrix<double>        block(m, m);
    // Every m-subset of the free components, by bitmask.
    for (unsigned int mask = 0; mask < (1u << free.size()); ++mask)
      {
        subset.clear();
        for (unsigned int b = 0; b < free.size(); ++b)
          if (mask & (1u << b))
            subset.push_back(free[b]);
        if (subset.size() != m)
          continue;
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int q = 0; q < m; ++q)
            block(i, q) = planes[i].normal[subset[q]];
        const double det = std::abs(block.determinant());
        if (det > best_det)
          {
            best_det = det;
            best     = subset;
          }
      }
    // A node that can only move (almost) tangentially to a plane cannot be
    // pushed back by its free components.
    if (best_det < (m == 1 ? 0.2 : 0.05))
      return false;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int q = 0; q < m; ++q)
        block(i, q) = planes[i].normal[best[q]];
    block.gauss_jordan();
    for (unsigned int r = 0; r < m; ++r)
      {
        constraints.add_line(dofs[best[r]]);
        double inhomogeneity = 0;
        for (unsigned int q = 0; q < m; ++q)
          inhomogeneity -= block(r, q) * planes[q].gap;
        constraints.set_inhomogeneity(dofs[best[r]], inhomogeneity);
        for (const unsigned int j : free)
          if (std::find(best.begin(), best.end(), j) == best.end())
            {
              double coefficient = 0;
              for (unsigned int q = 0; q < m; ++q)
                coefficient -= block(r, q) * planes[q].normal[j];
              constraints.add_entry(dofs[best[r]], dofs[j], coefficient);
            }
      }
    return true;
  }
} // namespace RestShape
