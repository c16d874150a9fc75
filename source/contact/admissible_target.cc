// AdmissibleTarget: the obstacle's placement, the admissible target, its
// normals, forces and the contacts it keeps.
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <restshape/base/input_error.h>
#include <restshape/base/mpi_reductions.h>
#include <restshape/base/units.h>
#include <restshape/contact/admissible_target.h>
#include <restshape/contact/contact_report.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

namespace RestShape
{
  using namespace dealii;

  AdmissibleTarget::AdmissibleTarget(ContactProblem &contact)
    : contact(contact)
    , changeable(&contact)
  {}

  AdmissibleTarget::AdmissibleTarget(const ContactProblem &contact)
    : contact(contact)
  {}

  void
  AdmissibleTarget::check_placement(const VectorType *shift) const
  {
    // Nodes beyond the obstacle by more than this fraction of the body's
    // size count as misplaced; a segmented skull that cuts a millimetre
    // into a brain does not.
    constexpr double deep_fraction = 0.05;
    const double     size          = contact.discretization.mesh().diameter();
    unsigned int     outside       = 0;
    double           clearance     = std::numeric_limits<double>::max();
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned)
        {
          const Point<3> x   = shift != nullptr ?
                                 contact.position(c.node, *shift) :
                                 c.node.position;
          const double   gap = contact.obstacle->gap(x).gap;
          outside += (gap < -deep_fraction * size);
          clearance = std::min(clearance, std::abs(gap));
        }
    const MPI_Comm     comm = contact.communicator();
    const unsigned int n    = ContactReport(contact).n_candidates();
    outside                 = Utilities::MPI::sum(outside, comm);
    clearance               = Utilities::MPI::min(clearance, comm);
    const bool too_many =
      outside > contact.parameters.max_outside_fraction * std::max(n, 1u);
    if (!too_many && clearance <= size)
      {
        check_fixed_labels_enclosed(deep_fraction * size);
        if (!contact.parameters.inside && shift == nullptr)
          check_obstacle_outside_body();
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
    for (const Node &node : contact.discretization.relevant_nodes())
      positions.push_back(node.position);
    const BoundingBox<3> mesh_box(positions);
    const auto [low, high]  = contact.obstacle->bounding_box();
    const std::string boxes = "; mesh box " +
                              box(mesh_box.get_boundary_points().first,
                                  mesh_box.get_boundary_points().second) +
                              ", obstacle box " + box(low, high);
    if (too_many)
      throw InputError(
        contact.parameters.obstacle_file,
        "Contact/Obstacle file",
        std::to_string(outside) + " of " + std::to_string(n) +
          " contact candidates lie on the wrong side of the obstacle, deeper "
          "than " +
          number_text(mm_per_m * deep_fraction * size) +
          " mm (5 % of the body), in the " +
          std::string(shift != nullptr ? "target the mesh carries" :
                                         "mesh geometry") +
          " (more than Contact/Maximum outside fraction = " +
          number_text(contact.parameters.max_outside_fraction) + boxes +
          "); expected the obstacle around the body (check Contact/Side and "
          "Contact/Length unit; raise the fraction for an obstacle meant to "
          "cut into the body)");
    throw InputError(contact.parameters.obstacle_file,
                     "Contact/Obstacle file",
                     "every contact candidate is farther from the obstacle "
                     "than the body's size (nearest " +
                       number_text(mm_per_m * clearance) + " mm, body " +
                       number_text(mm_per_m * size) + " mm" + boxes +
                       "): no contact can occur; expected the obstacle near "
                       "the body (check Contact/Length unit)");
  }

  void
  AdmissibleTarget::check_obstacle_outside_body() const
  {
    // Each vertex is tested a little (this fraction of the body's size)
    // towards the obstacle's centroid: a vertex on the body's surface (a
    // floor it stands on) then lies outside the body, one on a face
    // between two cells inside one of them.
    constexpr double        nudge = 1e-6;
    const Triangulation<3> &tria =
      contact.discretization.dof_handler().get_triangulation();
    std::vector<Point<3>> positions;
    for (const Node &node : contact.discretization.relevant_nodes())
      positions.push_back(node.position);
    if (positions.empty())
      positions.push_back(Point<3>());
    const BoundingBox<3>        body(positions);
    GridTools::Cache<3>         cache(tria, contact.discretization.mapping());
    double                      found[4] = {0, 0, 0, 0}; // count, x, y, z
    const std::vector<Point<3>> vertices = contact.obstacle->vertices();
    Point<3>                    centroid;
    for (const Point<3> &v : vertices)
      centroid += v / double(vertices.size());
    const double step = nudge * contact.discretization.mesh().diameter();
    for (const Point<3> &vertex : vertices)
      {
        const Tensor<1, 3> to_centre = centroid - vertex;
        const Point<3>     p         = to_centre.norm() > 0 ?
                                         vertex + step * to_centre / to_centre.norm() :
                                         vertex;
        if (!body.point_inside(p))
          continue;
        std::pair<Triangulation<3>::active_cell_iterator, Point<3>> hit;
        try
          {
            hit = GridTools::find_active_cell_around_point(cache, p);
          }
        catch (const std::exception &)
          {
            continue; // not in this rank's cells
          }
        const auto &[cell, unit] = hit;
        if (cell.state() == IteratorState::valid && cell->is_locally_owned() &&
            cell->reference_cell().contains_point(unit))
          {
            if (found[0] == 0)
              for (unsigned int d = 0; d < 3; ++d)
                found[1 + d] = vertex[d];
            ++found[0];
          }
      }
    const MPI_Comm comm = contact.communicator();
    const double   n    = Utilities::MPI::sum(found[0], comm);
    if (n == 0)
      return;
    // The first rank's vertex, on every rank.
    const auto all = Utilities::MPI::all_gather(
      comm, std::array<double, 4>{{found[0], found[1], found[2], found[3]}});
    Point<3> where;
    for (const auto &a : all)
      if (a[0] > 0)
        {
          where = Point<3>(a[1], a[2], a[3]);
          break;
        }
    char buffer[200];
    std::snprintf(buffer,
                  sizeof(buffer),
                  "%.0f of its %zu vertices lie inside the body, the first at "
                  "(%.4g, %.4g, %.4g) mm",
                  n,
                  vertices.size(),
                  mm_per_m * where[0],
                  mm_per_m * where[1],
                  mm_per_m * where[2]);
    throw InputError(contact.parameters.obstacle_file,
                     "Contact/Obstacle file",
                     std::string(buffer) +
                       ": with Contact/Side = outside the body must start "
                       "outside the obstacle; expected an obstacle that "
                       "does not overlap the mesh (or Side = inside)");
  }

  void
  AdmissibleTarget::check_fixed_labels_enclosed(const double depth) const
  {
    // A fixed node beyond the obstacle can never come back: the obstacle
    // is misplaced (or the wrong side is allowed). A node fixed in some
    // components only comes back if its free ones lead inside: along the
    // obstacle's normal by at least free_normal_fraction.
    constexpr double free_normal_fraction = 0.5;
    const auto      &fixed = contact.discretization.parameters().fixed_labels;
    for (const FixedLabel &f : fixed)
      {
        std::set<unsigned int> all, outside;
        double                 worst = 0;
        for (const auto &cell :
             contact.discretization.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned() && cell->material_id() == f.label)
            for (const unsigned int v : cell->vertex_indices())
              if (all.insert(cell->vertex_index(v)).second)
                {
                  const Gap g         = contact.obstacle->gap(cell->vertex(v));
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
        const MPI_Comm comm = contact.communicator();
        beyond              = Utilities::MPI::sum(beyond, comm);
        n                   = Utilities::MPI::sum(n, comm);
        worst               = Utilities::MPI::max(worst, comm);
        if (beyond > 0)
          throw InputError(
            contact.parameters.obstacle_file,
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
  AdmissibleTarget::shift() const
  {
    VectorType shift = contact.discretization.zero_vector();
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned)
        {
          const Gap g = contact.obstacle->gap(c.node.position);
          if (g.gap < -contact.gap_tolerance)
            for (unsigned int k = 0; k < 3; ++k)
              shift[c.node.dofs[k]] = -g.gap * g.gradient[k];
        }
    shift.compress(VectorOperation::insert);
    return shift;
  }

  unsigned int
  AdmissibleTarget::keep_contacts(const VectorType &target_shift)
  {
    AssertThrow(changeable != nullptr, ExcInternalError());
    const VectorType t    = contact.discretization.ghosted_copy(target_shift);
    unsigned int     kept = 0;
    for (ContactProblem::Candidate &c : changeable->candidates)
      {
        if (c.removed)
          continue;
        if (contact.obstacle->gap(contact.position(c.node, t)).gap <=
            contact.gap_tolerance)
          {
            kept += c.owned;
            continue;
          }
        ContactProblem::take_out(c);
        c.set_aside = true;
      }
    changeable->constraints_changed = true;
    return Utilities::MPI::sum(kept, contact.communicator());
  }

  void
  AdmissibleTarget::restore_contacts()
  {
    AssertThrow(changeable != nullptr, ExcInternalError());
    changeable->put_back(&ContactProblem::Candidate::set_aside);
    changeable->constraints_changed = true;
  }

  VectorType
  AdmissibleTarget::forces(const VectorType &raw_residual,
                           const VectorType &target_shift) const
  {
    const VectorType t      = contact.discretization.ghosted_copy(target_shift);
    VectorType       forces = contact.discretization.zero_vector();
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned && c.active)
        {
          const double lambda =
            std::max(0., contact.contact_force(c, raw_residual));
          const Gap g = contact.obstacle->gap(contact.position(c.node, t));
          for (unsigned int k = 0; k < 3; ++k)
            forces[c.node.dofs[k]] = lambda * g.gradient[k];
        }
    forces.compress(VectorOperation::insert);
    return forces;
  }

  std::vector<Tensor<1, 3>>
  AdmissibleTarget::normals() const
  {
    std::vector<double> mine;
    for (const ContactProblem::Candidate &c : contact.candidates)
      if (c.owned)
        {
          const Gap g = contact.obstacle->gap(c.node.position);
          if (g.gap <= contact.gap_tolerance)
            for (unsigned int k = 0; k < 3; ++k)
              mine.push_back(g.gradient[k]);
        }
    std::vector<Tensor<1, 3>> normals;
    for (const auto &part :
         Utilities::MPI::all_gather(contact.communicator(), mine))
      for (unsigned int i = 0; i + 2 < part.size(); i += 3)
        normals.push_back(Tensor<1, 3>({part[i], part[i + 1], part[i + 2]}));
    return normals;
  }

} // namespace RestShape
