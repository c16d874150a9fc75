#include <restshape/base/input_error.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/fem/element_limits.h>
#include <restshape/loads/elastic_support.h>
#include <restshape/loads/surface_load.h>

#include <array>

namespace RestShape
{
  using namespace dealii;

  LoadTermInfo
  ElasticSupport::info()
  {
    LoadTermInfo i;
    i.name        = "Elastic support";
    i.description = "Tethers on the outer faces of Boundary conditions/"
                    "Elastic support labels (the arachnoid trabeculae "
                    "between brain and skull): a traction -k (d - w) per "
                    "unit area of the rest shape's faces, stress-free in "
                    "the rest shape. A support, not a load: its resultant "
                    "is a reaction.";
    i.declare     = [](ParameterHandler &prm) {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Elastic support stiffness",
                        "0",
                        Patterns::Double(),
                        "Stiffness k in N/m^3 (Pa of traction per m of "
                            "displacement) of an elastic foundation on the outer "
                            "faces: traction -k u per unit area of the rest "
                            "shape's faces, u the displacement from the rest "
                            "shape, in every direction. It stands for tethers "
                            "such as the arachnoid trabeculae between brain and "
                            "skull, which are stress-free in the rest shape. 1e4 "
                            "N/m^3 (10 Pa per mm) holds a 1.5 kPa brain against "
                            "rotating freely in a frictionless skull. 0: none.");
      prm.declare_entry("Elastic support labels",
                        "",
                        Patterns::Anything(),
                        "The elastic support acts on the outer faces of "
                            "cells with these labels; empty: all labels that "
                            "are not fully fixed.");
      prm.leave_subsection();
    };
    i.parse = [](ParameterHandler &prm, double) {
      Settings s;
      prm.enter_subsection("Boundary conditions");
      s.stiffness = prm.get_double("Elastic support stiffness");
      if (!(s.stiffness >= 0))
        throw InputError("",
                         "Boundary conditions/Elastic support stiffness",
                         "'" + prm.get("Elastic support stiffness") +
                           "': expected a stiffness >= 0 in N/m^3");
      s.labels = parse_label_set(prm.get("Elastic support labels"),
                                 "Boundary conditions/Elastic support labels");
      prm.leave_subsection();
      return LoadTermFactory([s](const LoadContext &context) {
        return std::make_unique<ElasticSupport>(s, context);
      });
    };
    i.labels = {{"Boundary conditions", "Elastic support labels", false}};
    return i;
  }

  ElasticSupport::ElasticSupport(const Settings    &settings,
                                 const LoadContext &context)
    : k(settings.stiffness)
    , labels(context.labels_or_unfixed(settings.labels))
    , context(context)
  {}

  void
  ElasticSupport::assemble_faces(const LoadCell &c) const
  {
    if (!(k > 0 && labels.count(c.cell->material_id())))
      return;
    const unsigned int               n_dofs    = context.fe.n_dofs_per_cell();
    const std::vector<unsigned int> &component = c.d.components();
    const FaceScratch               &s         = c.scratch;
    // By component, the shape functions that do not vanish at a point (the
    // face's); the components have the same scalar functions in the same
    // order, so their values once.
    std::array<std::array<unsigned int, max_scalar_functions>, 3> rows;
    std::array<double, max_scalar_functions>                      values;
    AssertThrow(n_dofs <= max_dofs_per_cell, ExcInternalError());
    double *const matrix = c.matrix ? &c.cell_matrix(0, 0) : nullptr;
    for (const unsigned int f : c.cell->face_indices())
      if (c.cell->face(f)->at_boundary())
        {
          const FaceScratch &fv = c.face(f);
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              const Tensor<1, 3> u_rest = s.face_d[q] - s.face_w[q];
              const double       JxW =
                rest_area(s.face_grad_w[q], fv.normal_vector(q)) * fv.JxW(q);
              c.energy += 0.5 * k * u_rest.norm_square() * JxW;
              std::array<unsigned int, 3> n_rows = {{0, 0, 0}};
              for (unsigned int i = 0; i < n_dofs; ++i)
                if (const double phi = fv.shape_value(i, q); phi != 0)
                  {
                    const unsigned int ci = component[i];
                    if (ci == 0)
                      values[n_rows[ci]] = phi;
                    rows[ci][n_rows[ci]++] = i;
                    c.cell_rhs(i) -= k * u_rest[ci] * phi * JxW;
                  }
              if (matrix == nullptr)
                continue;
              // k phi_i phi_j dA between functions of one component: each
              // product once, for the three.
              AssertThrow(n_rows[1] == n_rows[0] && n_rows[2] == n_rows[0],
                          ExcInternalError());
              for (unsigned int r = 0; r < n_rows[0]; ++r)
                {
                  const double phi = values[r];
                  for (unsigned int t = 0; t < n_rows[0]; ++t)
                    {
                      const double product = k * phi * values[t] * JxW;
                      for (unsigned int ci = 0; ci < 3; ++ci)
                        matrix[rows[ci][r] * n_dofs + rows[ci][t]] += product;
                    }
                }
            }
        }
  }

  Tensor<1, 3>
  ElasticSupport::local_resultant(const LoadState &,
                                  const VectorType &d,
                                  const VectorType &w) const
  {
    Tensor<1, 3> force;
    if (!(k > 0))
      return force;
    const Quadrature<2>             &quadrature = context.face_quadrature;
    FEFaceValues<3>                  ffv(context.mapping,
                        context.fe,
                        quadrature,
                        update_values | update_gradients |
                          update_normal_vectors | update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<1, 3>>        face_d(quadrature.size()),
      face_w(quadrature.size());
    std::vector<Tensor2> grad_w(quadrature.size());
    for_each_boundary_face(
      context.dof_handler, context.mesh, labels, [&](const auto &cell, auto f) {
        ffv.reinit(cell, f);
        ffv[u].get_function_values(d, face_d);
        ffv[u].get_function_values(w, face_w);
        ffv[u].get_function_gradients(w, grad_w);
        for (const unsigned int q : ffv.quadrature_point_indices())
          force -= k * (face_d[q] - face_w[q]) *
                   rest_area(grad_w[q], ffv.normal_vector(q)) * ffv.JxW(q);
      });
    return force;
  }
} // namespace RestShape
