// The discretisation: finite element, quadrature, DoFs, nodes, the
// hanging-node and fixed-label constraints, and vectors of its layout.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

#include <restshape/base/units.h>
#include <restshape/fem/discretization.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace RestShape
{
  using namespace dealii;

  std::string
  cell_location_text(const types::material_id label, const Point<3> &center)
  {
    char text[100];
    std::snprintf(text,
                  sizeof(text),
                  "label %u at (%.1f, %.1f, %.1f) mm of the mesh",
                  static_cast<unsigned int>(label),
                  mm_per_m * center[0],
                  mm_per_m * center[1],
                  mm_per_m * center[2]);
    return text;
  }

  using Tensor2 = Tensor<2, 3>;

  namespace
  {
    std::unique_ptr<FiniteElement<3>>
    scalar_element(const bool simplex, const unsigned int degree)
    {
      if (simplex)
        return std::make_unique<FE_SimplexP<3>>(degree);
      return std::make_unique<FE_Q<3>>(degree);
    }
  } // namespace

  Discretization::Discretization(const DiscretizationParameters &parameters,
                                 LabelledMesh                   &mesh)
    : settings(parameters)
    , labelled_mesh(mesh)
    , comm(mesh.triangulation().get_communicator())
    , fe_(*scalar_element(mesh.is_simplex(), parameters.degree), 3)
    , dof_handler_(mesh.triangulation())
  {
    const unsigned int degree = parameters.degree;
    if (mesh.is_simplex())
      {
        mapping_ = std::make_unique<MappingFE<3>>(FE_SimplexP<3>(1));
        // On the (affine) P1 tetrahedron the gradients, hence F, P and the
        // tangent, are constant and the body force is linear: the centroid
        // rule integrates everything exactly, at a quarter of the cost of
        // the 4-point rule.
        cell_quadrature  = QGaussSimplex<3>(degree == 1 ? 1 : degree + 1);
        face_quadrature_ = QGaussSimplex<2>(degree + 1);
      }
    else
      {
        mapping_         = std::make_unique<MappingQ<3>>(1);
        cell_quadrature  = QGauss<3>(degree + 1);
        face_quadrature_ = QGauss<2>(degree + 1);
      }
  }


  Discretization::~Discretization()
  {
    dof_handler_.clear();
  }

  void
  Discretization::setup_dofs()
  {
    dof_handler_.reinit(labelled_mesh.triangulation());
    dof_handler_.distribute_dofs(fe_);
    owned_dofs = dof_handler_.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler_, relevant_dofs);
    setup_nodes();
    setup_constraints();
  }

  bool
  Discretization::is_held(const types::global_dof_index dof) const
  {
    // A hanging DoF on the edge of a fixed cell follows that edge's DoFs.
    if (is_fixed(dof))
      return true;
    if (!constraints_hanging.is_constrained(dof))
      return false;
    const auto *entries = constraints_hanging.get_constraint_entries(dof);
    return entries != nullptr && !entries->empty() &&
           std::all_of(entries->begin(), entries->end(), [this](const auto &e) {
             return is_fixed(e.first);
           });
  }

  void
  Discretization::setup_nodes()
  {
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(*mapping_,
                                         dof_handler_,
                                         support_points);
    owned_nodes_.clear();
    relevant_nodes_.clear();
    std::set<types::global_dof_index>    seen;
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < fe_.n_dofs_per_cell(); ++i)
          {
            const auto [component, base] = fe_.system_to_component_index(i);
            if (component != 0 || !seen.insert(dofs[i]).second)
              continue;
            Node node;
            for (unsigned int c = 0; c < 3; ++c)
              node.dofs[c] = dofs[fe_.component_to_system_index(c, base)];
            node.position = support_points.at(dofs[i]);
            relevant_nodes_.push_back(node);
            if (owned_dofs.is_element(dofs[i]))
              owned_nodes_.push_back(node);
          }
      }
  }

  void
  Discretization::setup_constraints()
  {
    constraints_hanging.clear();
    constraints_hanging.reinit(relevant_dofs);
    // deal.II 9.4 has no hanging nodes on simplices (and crashes when asked
    // for them); tetrahedral meshes are only refined globally.
    if (!labelled_mesh.is_simplex())
      DoFTools::make_hanging_node_constraints(dof_handler_,
                                              constraints_hanging);
    constraints_hanging.close();

    constraints_base.clear();
    constraints_base.reinit(relevant_dofs);
    constraints_base.merge(constraints_hanging);
    fixed_dof.assign(relevant_dofs.n_elements(), false);
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        for (const auto &fixed : settings.fixed_labels)
          if (fixed.label == cell->material_id())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (fixed.components[fe_.system_to_component_index(i).first])
                  {
                    fixed_dof[relevant_dofs.index_within_set(dofs[i])] = true;
                    if (!constraints_base.is_constrained(dofs[i]))
                      constraints_base.add_line(dofs[i]);
                  }
            }
        add_plane_constraints(cell);
      }
    constraints_base.close();
  }

  void
  Discretization::add_plane_constraints(
    const DoFHandler<3>::active_cell_iterator &cell)
  {
    if (settings.fixed_planes.empty())
      return;
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_face());
    for (const unsigned int f : cell->face_indices())
      {
        if (!cell->at_boundary(f))
          continue;
        const std::array<bool, 3> held =
          fixed_plane_components(settings.fixed_planes,
                                 *cell->face(f),
                                 labelled_mesh.length_unit());
        if (!held[0] && !held[1] && !held[2])
          continue;
        cell->face(f)->get_dof_indices(dofs, cell->active_fe_index());
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (held[fe_.face_system_to_component_index(i, f).first])
            {
              fixed_dof[relevant_dofs.index_within_set(dofs[i])] = true;
              if (!constraints_base.is_constrained(dofs[i]))
                constraints_base.add_line(dofs[i]);
            }
      }
  }

  VectorType
  Discretization::zero_vector() const
  {
    VectorType v(owned_dofs, comm);
    return v;
  }

  VectorType
  Discretization::owned_copy(const VectorType &v) const
  {
    VectorType copy(owned_dofs, comm);
    copy = v;
    return copy;
  }

  VectorType
  Discretization::ghosted_copy(const VectorType &v) const
  {
    VectorType copy(owned_dofs, relevant_dofs, comm);
    copy = v;
    return copy;
  }

  std::vector<std::vector<double>>
  Discretization::vertex_weights() const
  {
    const auto linear = scalar_element(labelled_mesh.is_simplex(), 1);
    std::vector<std::vector<double>> weights;
    for (const Point<3> &p : fe_.base_element(0).get_unit_support_points())
      {
        weights.emplace_back(linear->n_dofs_per_cell());
        for (unsigned int v = 0; v < weights.back().size(); ++v)
          weights.back()[v] = linear->shape_value(v, p);
      }
    return weights;
  }

  double
  Discretization::smallest_jacobian(const FEValues<3> &fe_values,
                                    const VectorType  &w)
  {
    std::vector<Tensor2> grad_w(fe_values.n_quadrature_points);
    fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(w, grad_w);
    double least = std::numeric_limits<double>::max();
    for (const Tensor2 &g : grad_w)
      {
        const double d = determinant(Tensor2(unit_symmetric_tensor<3>()) + g);
        if (std::isnan(d))
          return d;
        least = std::min(least, d);
      }
    return least;
  }

  VectorType
  Discretization::interpolate_vertex_field(
    const std::vector<Tensor<1, 3>> &values) const
  {
    VectorType                           result  = zero_vector();
    const auto                           weights = vertex_weights();
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              if (!owned_dofs.is_element(dofs[i]))
                continue;
              const auto [component, base] = fe_.system_to_component_index(i);
              double value                 = 0;
              for (unsigned int v = 0; v < cell->n_vertices(); ++v)
                value +=
                  weights[base][v] * values[cell->vertex_index(v)][component];
              result[dofs[i]] = value;
            }
        }
    result.compress(VectorOperation::insert);
    return result;
  }

  const DoFHandler<3> &
  Discretization::dof_handler() const
  {
    return dof_handler_;
  }

  const Mapping<3> &
  Discretization::mapping() const
  {
    return *mapping_;
  }

  const FESystem<3> &
  Discretization::fe() const
  {
    return fe_;
  }

  const Quadrature<2> &
  Discretization::face_quadrature() const
  {
    return face_quadrature_;
  }

  const AffineConstraints<double> &
  Discretization::base_constraints() const
  {
    return constraints_base;
  }

  const IndexSet &
  Discretization::locally_owned_dofs() const
  {
    return owned_dofs;
  }

  const IndexSet &
  Discretization::locally_relevant_dofs() const
  {
    return relevant_dofs;
  }

  const std::vector<Node> &
  Discretization::owned_nodes() const
  {
    return owned_nodes_;
  }

  const std::vector<Node> &
  Discretization::relevant_nodes() const
  {
    return relevant_nodes_;
  }

  bool
  Discretization::is_fixed(const types::global_dof_index dof) const
  {
    return fixed_dof[relevant_dofs.index_within_set(dof)];
  }

  std::array<bool, 3>
  Discretization::fixed_components() const
  {
    std::array<double, 3> n_fixed{{0, 0, 0}};
    for (const Node &node : owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        n_fixed[c] += is_fixed(node.dofs[c]);
    const MPI_Comm      comm = dof_handler_.get_communicator();
    std::array<bool, 3> result;
    for (unsigned int c = 0; c < 3; ++c)
      result[c] = Utilities::MPI::sum(n_fixed[c], comm) > 0;
    return result;
  }

  const LabelledMesh &
  Discretization::mesh() const
  {
    return labelled_mesh;
  }

} // namespace RestShape
