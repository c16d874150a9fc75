// What the contact problem reports: contact conditions, counts, forces,
// pressures and the nodal fields for output (the active set itself is in
// contact.cc).
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <restshape/base/units.h>
#include <restshape/contact/contact_report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

namespace RestShape
{
  using namespace dealii;

  MPI_Comm
  ContactProblem::communicator() const
  {
    return discretization.dof_handler().get_triangulation().get_communicator();
  }

  template <typename Predicate>
  unsigned int
  ContactProblem::count_owned(const Predicate &predicate) const
  {
    unsigned int n = 0;
    for (const Candidate &c : candidates)
      n += (c.owned && predicate(c));
    return Utilities::MPI::sum(n, communicator());
  }

  ContactProblem::Violations
  ContactProblem::violations() const
  {
    Violations v;
    for (const Candidate &c : candidates)
      if (c.owned && c.eligible)
        {
          const double gap = constrained_gap(c);
          if (gap < -gap_tolerance)
            ++v.through;
          else if (c.active && std::abs(gap) > gap_tolerance)
            ++v.off;
          else
            continue;
          v.worst = std::max(v.worst, std::abs(gap));
        }
    const MPI_Comm comm = communicator();
    v.through           = Utilities::MPI::sum(v.through, comm);
    v.off               = Utilities::MPI::sum(v.off, comm);
    v.worst             = Utilities::MPI::max(v.worst, comm);
    return v;
  }

  bool
  ContactProblem::is_satisfied() const
  {
    const Violations v = violations();
    return v.through + v.off == 0;
  }

  bool
  ContactProblem::moves_nodes_onto_surface() const
  {
    return count_owned([&](const Candidate &c) {
             return c.active && c.follow_surface &&
                    std::abs(c.gap) > gap_tolerance;
           }) > 0;
  }

  std::string
  ContactProblem::unsettled_text() const
  {
    const Violations v = violations();
    char             buffer[128];
    std::snprintf(buffer, sizeof(buffer), "%.2e", v.worst * mm_per_m);
    return "the contact conditions do not settle: " +
           std::to_string(v.through) + " nodes through the obstacle, " +
           std::to_string(v.off) + " active nodes off it (by up to " + buffer +
           " mm); the last update made " + std::to_string(n_added) +
           " nodes active and released " + std::to_string(n_released);
  }

  std::string
  ContactProblem::progress_text() const
  {
    return ", contact " + std::to_string(ContactReport(*this).n_active()) +
           " active (+" + std::to_string(n_added) + " new, -" +
           std::to_string(n_released) + " released)" +
           (releases_frozen ? " [frozen: only nodes that pull are released]" :
                              "");
  }

  // ------------------------------------------------------------------
  // ContactReport

  ContactReport::ContactReport(const ContactProblem &contact)
    : contact(contact)
  {}

  unsigned int
  ContactReport::n_active() const
  {
    return contact.count_owned(
      [](const ContactProblem::Candidate &c) { return c.active; });
  }

  unsigned int
  ContactReport::n_held() const
  {
    return contact.count_owned([](const ContactProblem::Candidate &c) {
      return c.active && c.planes.planes().size() > 1;
    });
  }

  ContactReport::Adhesion
  ContactReport::adhesion(const VectorType &raw_residual) const
  {
    // Pulls within round-off of the total contact force (1e-9 of it) are
    // not counted.
    std::vector<double> pulls;
    double              push = 0;
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active)
        {
          const double force = contact.contact_force(c, raw_residual);
          if (force < 0)
            pulls.push_back(-force);
          else
            push += force;
        }
    const MPI_Comm comm = contact.communicator();
    push                = Utilities::MPI::sum(push, comm);
    unsigned int n      = 0;
    double       pull   = 0;
    for (const double f : pulls)
      if (f > 1e-9 * push)
        {
          ++n;
          pull += f;
        }
    pull = Utilities::MPI::sum(pull, comm);
    return {Utilities::MPI::sum(n, comm), pull, push > 0 ? pull / push : 0.};
  }

  std::pair<unsigned int, double>
  ContactReport::fixed_plane_nodes() const
  {
    unsigned int n        = 0;
    double       distance = 0;
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active && c.planes.fixed())
        {
          ++n;
          distance = std::max(distance, std::abs(c.gap));
        }
    const MPI_Comm comm = contact.communicator();
    return {Utilities::MPI::sum(n, comm), Utilities::MPI::max(distance, comm)};
  }

  unsigned int
  ContactReport::n_candidates() const
  {
    return contact.count_owned(
      [](const ContactProblem::Candidate &) { return true; });
  }

  unsigned int
  ContactReport::n_cavity_wall_faces() const
  {
    return Utilities::MPI::sum(contact.n_cavity_wall_faces,
                               contact.communicator());
  }

  unsigned int
  ContactReport::n_outside() const
  {
    return contact.count_owned([this](const ContactProblem::Candidate &c) {
      return !c.removed && c.gap < -contact.gap_tolerance;
    });
  }

  Tensor<1, 3>
  ContactReport::total_force(const VectorType &raw_residual) const
  {
    Tensor<1, 3> force;
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active)
        force += contact.reaction(c, raw_residual);
    const MPI_Comm comm = contact.communicator();
    for (unsigned int k = 0; k < 3; ++k)
      force[k] = Utilities::MPI::sum(force[k], comm);
    return force;
  }

  std::map<Label, Tensor<1, 3>>
  ContactReport::force_by_label(const VectorType &raw_residual) const
  {
    // The labels of the cells around each active node (by its x DoF).
    std::map<types::global_dof_index, std::set<Label>> labels;
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active)
        labels[c.node.dofs[0]];
    std::vector<types::global_dof_index> dofs(
      contact.discretization.fe().n_dofs_per_cell());
    for (const auto &cell :
         contact.discretization.dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          for (const auto dof : dofs)
            if (const auto it = labels.find(dof); it != labels.end())
              it->second.insert(cell->material_id());
        }
    std::map<Label, Tensor<1, 3>> force;
    for (const Label label : contact.discretization.mesh().labels())
      force[label];
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active)
        {
          const std::set<Label> &around = labels[c.node.dofs[0]];
          const Tensor<1, 3>     f      = contact.reaction(c, raw_residual);
          for (const Label label : around)
            force[label] += f / double(around.size());
        }
    const MPI_Comm comm = contact.communicator();
    for (auto &[label, f] : force)
      for (unsigned int k = 0; k < 3; ++k)
        f[k] = Utilities::MPI::sum(f[k], comm);
    return force;
  }

  double
  ContactReport::max_penetration(const bool eligible_only) const
  {
    double p = -std::numeric_limits<double>::max();
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && !c.removed && (c.eligible || !eligible_only))
        p = std::max(p, -c.gap);
    return Utilities::MPI::max(p, contact.communicator()) + 0.;
  }

  std::vector<double>
  ContactReport::pressures(const VectorType &raw_residual) const
  {
    // The pressure of an active node is its contact force over int phi dA
    // on the faces that face the obstacle (outward normal against the
    // obstacle's normal at the node: n_f . n < -1/2), which makes a uniform
    // pressure exact and leaves out faces at an angle to the obstacle (the
    // sides of a block on a floor). Where int phi dA vanishes (corners of
    // quadratic triangles carry no force under a smooth pressure) the
    // pressure is the mean of the other nodes of those faces; an active node
    // without such a face uses its lumped area.
    const unsigned int  n = contact.candidates.size();
    std::vector<double> lumped(n, 0.), integral(n, 0.), pressure(n, 0.);
    std::vector<bool>   in_face(n, false);
    for (const ContactProblem::Face &face : contact.faces)
      for (unsigned int k = 0; k < face.nodes.size(); ++k)
        {
          const ContactProblem::Candidate &c =
            contact.candidates[face.nodes[k]];
          if (!c.active || face.normal * c.normal > -0.5)
            continue;
          lumped[face.nodes[k]] += face.lumped[k];
          integral[face.nodes[k]] += face.integral[k];
          in_face[face.nodes[k]] = true;
        }
    const auto direct = [&](const unsigned int i) {
      return in_face[i] && integral[i] >= 0.1 * lumped[i];
    };
    // Owned nodes: their own pressure; with it, whether it is direct, on
    // the neighbouring ranks (their faces hold only part of it).
    VectorType shared = contact.discretization.zero_vector();
    for (unsigned int i = 0; i < n; ++i)
      if (contact.candidates[i].owned && contact.candidates[i].active)
        {
          const double force =
            contact.contact_force(contact.candidates[i], raw_residual);
          if (direct(i))
            pressure[i] = force / integral[i];
          else if (!in_face[i])
            pressure[i] = force / contact.candidates[i].area_lumped;
          shared[contact.candidates[i].node.dofs[0]] = pressure[i];
          shared[contact.candidates[i].node.dofs[1]] = direct(i) ? 1 : 0;
        }
    shared.compress(VectorOperation::insert);
    const VectorType  ghosted = contact.discretization.ghosted_copy(shared);
    std::vector<bool> is_direct(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto &dofs = contact.candidates[i].node.dofs;
        is_direct[i] =
          contact.candidates[i].owned ? direct(i) : ghosted[dofs[1]] > 0;
        if (!contact.candidates[i].owned)
          pressure[i] = ghosted[dofs[0]];
      }
    std::vector<double>       sum(n, 0.);
    std::vector<unsigned int> count(n, 0);
    for (const ContactProblem::Face &face : contact.faces)
      for (const unsigned int i : face.nodes)
        if (in_face[i] && !is_direct[i] &&
            face.normal * contact.candidates[i].normal <= -0.5)
          for (const unsigned int j : face.nodes)
            if (is_direct[j])
              {
                sum[i] += pressure[j];
                ++count[i];
              }
    for (unsigned int i = 0; i < n; ++i)
      if (contact.candidates[i].owned && contact.candidates[i].active &&
          count[i] > 0)
        pressure[i] = sum[i] / count[i];
    return pressure;
  }

  std::vector<double>
  ContactReport::recovered_pressures(const VectorType &raw_residual) const
  {
    const Discretization &discretization = contact.discretization;
    const auto            facing         = [&](const ContactProblem::Face &face,
                            const unsigned int          i) {
      return face.normal * contact.candidates[i].normal <= -0.5;
    };
    // Summed over all ranks (the faces of a node may lie on several):
    // vectors that take additions at ghost DoFs, read back ghosted.
    const auto writable = [&]() {
      VectorType v;
      v.reinit(discretization.locally_owned_dofs(),
               discretization.locally_relevant_dofs(),
               discretization.communicator(),
               true);
      return v;
    };
    const auto summed = [&](VectorType &v) {
      v.compress(VectorOperation::add);
      return discretization.ghosted_copy(discretization.owned_copy(v));
    };
    // Each node's force (x slot) and the lumped area of its faces that
    // face the obstacle (y slot).
    VectorType node_sums = writable();
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active)
        node_sums[c.node.dofs[0]] += contact.contact_force(c, raw_residual);
    for (const ContactProblem::Face &face : contact.faces)
      for (unsigned int k = 0; k < face.nodes.size(); ++k)
        if (facing(face, face.nodes[k]))
          node_sums[contact.candidates[face.nodes[k]].node.dofs[1]] +=
            face.lumped[k];
    const VectorType nodes = summed(node_sums);
    // Each face's traction times its area (x slot) and area (y slot) at
    // its nodes that it faces the obstacle at.
    VectorType face_sums = writable();
    for (const ContactProblem::Face &face : contact.faces)
      {
        double received = 0, area = 0;
        for (unsigned int k = 0; k < face.nodes.size(); ++k)
          {
            const auto  &dofs  = contact.candidates[face.nodes[k]].node.dofs;
            const double share = nodes[dofs[1]];
            area += face.lumped[k];
            if (facing(face, face.nodes[k]) && share > 0)
              received += nodes[dofs[0]] * face.lumped[k] / share;
          }
        for (unsigned int k = 0; k < face.nodes.size(); ++k)
          if (facing(face, face.nodes[k]))
            {
              const auto &dofs = contact.candidates[face.nodes[k]].node.dofs;
              face_sums[dofs[0]] += received;
              face_sums[dofs[1]] += area;
            }
      }
    const VectorType    faces = summed(face_sums);
    std::vector<double> pressure(contact.candidates.size(), 0.);
    for (unsigned int i = 0; i < contact.candidates.size(); ++i)
      {
        const ContactProblem::Candidate &c = contact.candidates[i];
        if (!c.owned || !c.active)
          continue;
        if (faces[c.node.dofs[1]] > 0)
          pressure[i] = faces[c.node.dofs[0]] / faces[c.node.dofs[1]];
        else if (c.active)
          pressure[i] = nodes[c.node.dofs[0]] / c.area_lumped;
      }
    return pressure;
  }

  std::pair<double, double>
  ContactReport::pressure_range(const VectorType &raw_residual) const
  {
    const std::vector<double> pressure = pressures(raw_residual);
    double low = std::numeric_limits<double>::max(), high = -low;
    for (unsigned int i = 0; i < contact.candidates.size(); ++i)
      if (contact.candidates[i].owned && contact.candidates[i].active)
        {
          low  = std::min(low, pressure[i]);
          high = std::max(high, pressure[i]);
        }
    const MPI_Comm comm = contact.communicator();
    low                 = Utilities::MPI::min(low, comm);
    high                = Utilities::MPI::max(high, comm);
    return high < low ? std::make_pair(0., 0.) : std::make_pair(low, high);
  }

  double
  ContactReport::contact_radius(const Point<3>     &point,
                                const Tensor<1, 3> &direction) const
  {
    const Tensor<1, 3> axis   = direction / direction.norm();
    double             radius = 0;
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active)
        {
          const Tensor<1, 3> r = c.node.position - point;
          radius = std::max(radius, (r - (r * axis) * axis).norm());
        }
    return Utilities::MPI::max(radius, contact.communicator());
  }

  double
  ContactReport::patch_radius(const Tensor<1, 3> &direction) const
  {
    const MPI_Comm comm = contact.communicator();
    Tensor<1, 3>   sum;
    double         n = 0;
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active)
        {
          sum += c.node.position;
          n += 1;
        }
    sum = Utilities::MPI::sum(sum, comm);
    n   = Utilities::MPI::sum(n, comm);
    if (n == 0 || direction.norm() == 0)
      return 0;
    return contact_radius(Point<3>(sum / n), direction);
  }

  VectorType
  ContactReport::nodal_fields(const VectorType &raw_residual,
                              const double      length_scale) const
  {
    const std::vector<double> pressure = recovered_pressures(raw_residual);
    VectorType                fields   = contact.discretization.zero_vector();
    // Off the contact candidates: the signed distance of the node to the
    // obstacle and no pressure. (Not NaN: the writer evaluates each field
    // as sum u_i phi_i, and a NaN at one node of a cell, times phi_i = 0,
    // blanked every node of that cell: all of them at P2.)
    for (const Node &node : contact.discretization.owned_nodes())
      fields[node.dofs[1]] =
        contact.obstacle
          ->gap(contact.position(node, contact.forward_state.displacement()))
          .gap *
        length_scale;
    for (unsigned int i = 0; i < contact.candidates.size(); ++i)
      if (contact.candidates[i].owned)
        {
          const auto &dofs = contact.candidates[i].node.dofs;
          fields[dofs[0]]  = contact.candidates[i].active ? 1 : 0;
          fields[dofs[1]]  = contact.candidates[i].gap * length_scale;
          fields[dofs[2]]  = pressure[i];
        }
    fields.compress(VectorOperation::insert);
    return fields;
  }

} // namespace RestShape
