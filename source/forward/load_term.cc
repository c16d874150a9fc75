#include <restshape/forward/load_term.h>

namespace RestShape
{
  using namespace dealii;

  std::set<Label>
  LoadContext::labels_or_unfixed(const std::set<Label> &given) const
  {
    std::set<Label> result = given;
    if (result.empty())
      for (const Label label : mesh.labels())
        {
          bool fully_fixed = false;
          for (const auto &f : parameters.boundary.fixed_labels)
            if (f.label == label && f.components[0] && f.components[1] &&
                f.components[2])
              fully_fixed = true;
          if (!fully_fixed)
            result.insert(label);
        }
    return result;
  }

  FaceScratch::FaceScratch(const Mapping<3>       &mapping,
                           const FiniteElement<3> &fe,
                           const Quadrature<2>    &face_quadrature)
    : fe_face_values(mapping,
                     fe,
                     face_quadrature,
                     update_values | update_gradients |
                       update_quadrature_points | update_normal_vectors |
                       update_JxW_values)
    , face_d(face_quadrature.size())
    , face_w(face_quadrature.size())
    , face_grad_d(face_quadrature.size())
    , face_grad_w(face_quadrature.size())
    , face_matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
  {}

  FaceScratch::FaceScratch(const FaceScratch &other)
    : FaceScratch(other.fe_face_values.get_mapping(),
                  other.fe_face_values.get_fe(),
                  other.fe_face_values.get_quadrature())
  {}
} // namespace RestShape
