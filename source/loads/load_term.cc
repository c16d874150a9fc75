#include <deal.II/fe/mapping_fe.h>

#include <restshape/loads/load_term.h>

namespace RestShape
{
  using namespace dealii;

  std::set<Label>
  LoadContext::labels_or_unfixed(const std::set<Label> &given) const
  {
    std::set<Label> result = given;
    if (result.empty())
      for (const Label label : mesh.labels())
        if (!fully_fixed(label))
          result.insert(label);
    return result;
  }

  FaceScratch::FaceScratch(const Mapping<3>       &mapping,
                           const FiniteElement<3> &fe,
                           const Quadrature<2>    &face_quadrature)
    : fe(fe)
    , fe_face_values(mapping,
                     fe.base_element(0),
                     face_quadrature,
                     update_values | update_gradients |
                       update_quadrature_points | update_normal_vectors |
                       update_JxW_values)
    , face_d(face_quadrature.size())
    , face_w(face_quadrature.size())
    , face_grad_d(face_quadrature.size())
    , face_grad_w(face_quadrature.size())
    , face_matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
    , scalar(fe.n_dofs_per_cell())
  {
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      scalar[i] = fe.system_to_component_index(i).second;
    const auto *mapping_fe = dynamic_cast<const MappingFE<3> *>(&mapping);
    if (fe.reference_cell() == ReferenceCells::Tetrahedron &&
        mapping_fe != nullptr && mapping_fe->get_degree() == 1)
      simplex = std::make_unique<SimplexFaceValues>(fe.base_element(0),
                                                    face_quadrature);
  }

  FaceScratch::FaceScratch(const FaceScratch &other)
    : FaceScratch(other.fe_face_values.get_mapping(),
                  other.fe,
                  other.fe_face_values.get_quadrature())
  {}

  void
  FaceScratch::reinit(const CellIterator &cell,
                      const unsigned int  f,
                      const LocalField   &d,
                      const LocalField   &w)
  {
    if (f == current_face)
      return;
    // As a cell of the mesh: the DoFHandler's cell is of the vector element.
    const Triangulation<3>::cell_iterator mesh_cell = cell;
    const auto                            fields    = [&](const auto &values) {
      d.values(values, face_d);
      w.values(values, face_w);
      d.gradients(values, face_grad_d);
      w.gradients(values, face_grad_w);
    };
    if (simplex)
      {
        simplex->reinit(mesh_cell, f);
        fields(*simplex);
      }
    else
      {
        fe_face_values.reinit(mesh_cell, f);
        fields(fe_face_values);
      }
    current_face = f;
  }
} // namespace RestShape
