// LoadPath: the loads' resultant against what holds the target.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/base/input_error.h>
#include <restshape/contact/admissible_target.h>
#include <restshape/contact/contact.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/forward/forward_results.h>
#include <restshape/inverse/load_path.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Lawson-Hanson iterations (the active set holds at most 3 normals).
    constexpr unsigned int max_cone_iterations = 30;

    /// The least-squares combination with non-negative weights of the
    /// @p normals closest to @p target: the part of @p target the cone of
    /// the normals reaches (Lawson and Hanson's NNLS in 3D).
    Tensor<1, 3>
    projection_onto_cone(const std::vector<Tensor<1, 3>> &normals,
                         const Tensor<1, 3>              &target)
    {
      std::vector<unsigned int> active;
      std::vector<double>       weights;
      Tensor<1, 3>              reached;
      for (unsigned int it = 0; it < max_cone_iterations; ++it)
        {
          const Tensor<1, 3> rest = target - reached;
          // The normal that reduces what is left the most.
          unsigned int best  = normals.size();
          double       slope = 1e-12 * target.norm();
          for (unsigned int i = 0; i < normals.size(); ++i)
            if (normals[i] * rest > slope &&
                std::find(active.begin(), active.end(), i) == active.end())
              {
                slope = normals[i] * rest;
                best  = i;
              }
          if (best == normals.size() || active.size() == 3)
            break;
          active.push_back(best);
          // Least squares on the active normals; drop those whose weight
          // would turn negative.
          for (;;)
            {
              const unsigned int m = active.size();
              FullMatrix<double> gram(m, m);
              Vector<double>     rhs(m), w(m);
              for (unsigned int a = 0; a < m; ++a)
                {
                  rhs[a] = normals[active[a]] * target;
                  for (unsigned int b = 0; b < m; ++b)
                    gram(a, b) = normals[active[a]] * normals[active[b]];
                }
              if (std::abs(gram.determinant()) < 1e-12)
                {
                  active.pop_back();
                  break;
                }
              gram.gauss_jordan();
              gram.vmult(w, rhs);
              unsigned int negative = m;
              for (unsigned int a = 0; a < m; ++a)
                if (w[a] < 0)
                  negative = a;
              if (negative == m)
                {
                  weights.assign(w.begin(), w.end());
                  break;
                }
              active.erase(active.begin() + negative);
              if (active.empty())
                {
                  weights.clear();
                  break;
                }
            }
          reached = Tensor<1, 3>();
          for (unsigned int a = 0; a < weights.size() && a < active.size(); ++a)
            reached += weights[a] * normals[active[a]];
        }
      return reached;
    }

    /// Per component, the area (m^2) of the faces between cells fixed in
    /// it and cells that are not, seen from the free cells, and of the
    /// boundary faces in a plane fixed in it; and whether any cell or
    /// plane face is fixed in it.
    std::pair<std::array<double, 3>, std::array<bool, 3>>
    support_faces(const ForwardProblem &forward)
    {
      std::map<Label, std::array<bool, 3>> fixed;
      for (const FixedLabel &f :
           forward.scene_parameters().discretization.fixed_labels)
        fixed[f.label] = f.components;
      const auto is_fixed = [&](const Label label, const unsigned int c) {
        const auto it = fixed.find(label);
        return it != fixed.end() && it->second[c];
      };
      const std::vector<FixedPlane> &planes =
        forward.scene_parameters().discretization.fixed_planes;
      const double length_unit = forward.discretization().mesh().length_unit();
      std::array<double, 3> area{{0, 0, 0}};
      std::array<bool, 3>   any{{false, false, false}};
      for (const auto &cell :
           forward.discretization().dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          for (unsigned int c = 0; c < 3; ++c)
            {
              if (is_fixed(cell->material_id(), c))
                {
                  any[c] = true;
                  continue;
                }
              for (const unsigned int f : cell->face_indices())
                if (!cell->at_boundary(f) &&
                    is_fixed(cell->neighbor(f)->material_id(), c))
                  area[c] += cell->face(f)->measure();
                else if (cell->at_boundary(f) &&
                         fixed_plane_components(planes,
                                                *cell->face(f),
                                                length_unit)[c])
                  {
                    area[c] += cell->face(f)->measure();
                    any[c] = true;
                  }
            }
      const MPI_Comm comm = forward.discretization()
                              .dof_handler()
                              .get_triangulation()
                              .get_communicator();
      for (unsigned int c = 0; c < 3; ++c)
        {
          area[c] = Utilities::MPI::sum(area[c], comm);
          any[c]  = Utilities::MPI::max(any[c] ? 1 : 0, comm) == 1;
        }
      return {area, any};
    }

    /// The largest Young's modulus among the labels not fixed in every
    /// component (the tissue the load strains).
    double
    free_youngs_modulus(const ForwardProblem &forward)
    {
      std::set<Label> held;
      for (const FixedLabel &f :
           forward.scene_parameters().discretization.fixed_labels)
        if (f.components[0] && f.components[1] && f.components[2])
          held.insert(f.label);
      double E = 0;
      for (const Label label : forward.discretization().mesh().labels())
        if (held.count(label) == 0)
          E = std::max(E, forward.materials().youngs_modulus(label));
      return E;
    }
  } // namespace

  LoadPath
  assess_load_path(const ForwardProblem &forward,
                   const ContactProblem *contact,
                   const LoadState      &load)
  {
    LoadPath path;
    if (forward.loads().has_support())
      return path;
    path.assessed = true;
    path.load     = total_external_force(forward, load);
    std::vector<Tensor<1, 3>> normals;
    if (contact != nullptr)
      normals = AdmissibleTarget(*contact).normals();
    path.contact_nodes = normals.size();
    // The obstacle pushes along its normals: it balances -F where it can.
    path.through_supports =
      path.load + projection_onto_cone(normals, -path.load);
    const auto [area, any] = support_faces(forward);
    path.support_area      = area;
    const double E         = free_youngs_modulus(forward);
    double       sum       = 0;
    for (unsigned int c = 0; c < 3; ++c)
      {
        const double f = std::abs(path.through_supports[c]);
        if (f <= 1e-9 * path.load.norm())
          continue;
        // Fixed cells with no free neighbour in c: the whole body is held.
        if (any[c] && area[c] == 0)
          continue;
        if (area[c] == 0)
          {
            sum = std::numeric_limits<double>::infinity();
            break;
          }
        sum += std::pow(f / (area[c] * E), 2);
      }
    path.strain = std::sqrt(sum);
    return path;
  }

  std::string
  LoadPath::text() const
  {
    char buffer[600];
    std::snprintf(buffer,
                  sizeof(buffer),
                  "the loads' resultant (%.3g, %.3g, %.3g) N; the obstacle "
                  "can push back at %u contact nodes of the target, which "
                  "leaves (%.3g, %.3g, %.3g) N to the fixed labels, whose "
                  "faces with the free tissue (%.3g, %.3g, %.3g mm^2 for "
                  "x, y, z) it strains by about %.3g (force / (area E))",
                  load[0],
                  load[1],
                  load[2],
                  contact_nodes,
                  through_supports[0],
                  through_supports[1],
                  through_supports[2],
                  support_area[0] * 1e6,
                  support_area[1] * 1e6,
                  support_area[2] * 1e6,
                  strain);
    return buffer;
  }

  std::string
  LoadPath::remedy()
  {
    return "tethers between the tissue and the skull (Boundary "
           "conditions/Elastic support stiffness, e.g. 1000 N/m^3 = 1 Pa of "
           "traction per mm, as in prm/brain.prm), more fixed tissue "
           "(Boundary conditions/Fixed labels), or a target that rests on "
           "the obstacle where the load pushes it";
  }
} // namespace RestShape
