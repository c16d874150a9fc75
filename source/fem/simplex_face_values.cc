// SimplexFaceValues: FEFaceValues of a scalar element on affine tetrahedra.
#include <deal.II/base/qprojector.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/hp/q_collection.h>

#include <restshape/fem/simplex_face_values.h>

namespace RestShape
{
  using namespace dealii;

  SimplexFaceValues::SimplexFaceValues(const FiniteElement<3> &fe,
                                       const Quadrature<2>    &quadrature)
    : n_quadrature_points(quadrature.size())
    , dofs_per_cell(fe.n_dofs_per_cell())
    , JxW_values(n_quadrature_points)
    , normals(n_quadrature_points)
  {
    const ReferenceCell tetrahedron = ReferenceCells::Tetrahedron;
    AssertThrow(fe.reference_cell() == tetrahedron,
                ExcMessage(
                  "SimplexFaceValues: expected a tetrahedral element"));
    const Quadrature<3> all =
      QProjector<3>::project_to_all_faces(tetrahedron,
                                          hp::QCollection<2>(quadrature));
    const unsigned int n = n_quadrature_points;
    AssertThrow(all.size() % n == 0, ExcInternalError());
    // One reference-cell evaluation for all of them, then a rule each.
    const SimplexValues all_values(fe, all);
    for (unsigned int start = 0; start < all.size(); start += n)
      {
        sets.emplace_back(all_values, start, n);
        weights.emplace_back(all.get_weights().begin() + start,
                             all.get_weights().begin() + start + n);
      }
    for (unsigned int f = 0; f < n_faces; ++f)
      for (unsigned int d = 0; d < 2; ++d)
        tangentials[f][d] = tetrahedron.unit_tangential_vectors<3>(f, d);
  }

  void
  SimplexFaceValues::reinit(const Triangulation<3>::cell_iterator &cell,
                            const unsigned int                     face)
  {
    const unsigned int start =
      QProjector<3>::DataSetDescriptor::face(ReferenceCells::Tetrahedron,
                                             face,
                                             cell->face_orientation(face),
                                             cell->face_flip(face),
                                             cell->face_rotation(face),
                                             n_quadrature_points);
    current = &sets[start / n_quadrature_points];
    current->reinit(cell);
    // The boundary form (J t_0) x (J t_1), as MappingFE computes it.
    const DerivativeForm<1, 3, 3> &J = current->jacobian();
    const Tensor<1, 3>             boundary_form =
      cross_product_3d(apply_transformation(J, tangentials[face][0]),
                       apply_transformation(J, tangentials[face][1]));
    const std::vector<double> &w = weights[start / n_quadrature_points];
    for (unsigned int q = 0; q < n_quadrature_points; ++q)
      {
        JxW_values[q] = boundary_form.norm() * w[q];
        normals[q]    = boundary_form / boundary_form.norm();
      }
  }
} // namespace RestShape
