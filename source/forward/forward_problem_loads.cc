// ForwardProblem: the load terms (load_term.h) and the scene's load.
#include <restshape/forward/forward_problem.h>
#include <restshape/loads/body_force.h>
#include <restshape/loads/elastic_support.h>
#include <restshape/loads/load_registry.h>

namespace RestShape
{
  using namespace dealii;

  void
  ForwardProblem::setup_load_terms()
  {
    const LoadContext context{parameters,
                              labelled_mesh,
                              material_table,
                              *mapping_,
                              fe_,
                              face_quadrature_,
                              dof_handler_,
                              comm,
                              [this](const types::global_dof_index dof) {
                                return is_held(dof);
                              }};
    load_terms.clear();
    load_terms.push_back(std::make_unique<BodyForce>(context));
    auto pressure = std::make_unique<SurfacePressure>(context);
    pressure_term = pressure.get();
    load_terms.push_back(std::move(pressure));
    load_terms.push_back(std::make_unique<ElasticSupport>(context));
    for (auto &term : create_load_terms(parameters.load_terms, context))
      load_terms.push_back(std::move(term));
    body_terms.clear();
    for (const auto &term : load_terms)
      if (term->has_body_force())
        body_terms.push_back(term.get());
  }

  Point<3>
  ForwardProblem::highest_pressure_point(const Tensor<1, 3> &acceleration) const
  {
    return pressure_term->highest_point(acceleration);
  }

  unsigned int
  ForwardProblem::open_surface(const Region &region)
  {
    const bool         was_symmetric = tangent_is_symmetric();
    const unsigned int faces         = pressure_term->open(region);
    if (!region.defined() || was_symmetric != tangent_is_symmetric())
      linear_solver->set_symmetric(tangent_is_symmetric());
    return faces;
  }

  bool
  ForwardProblem::body_force_varies(const LoadState &load) const
  {
    for (const LoadTerm *term : body_terms)
      if (term->body_force_varies(load))
        return true;
    return false;
  }

  Tensor<1, 3>
  ForwardProblem::body_force(const CellAccessor<3, 3> &cell,
                             const Point<3>           &X,
                             const LoadState          &load) const
  {
    Tensor<1, 3> f;
    for (const LoadTerm *term : body_terms)
      f += term->body_force(cell, X, load);
    return f;
  }

  const SurfaceLoad &
  ForwardProblem::surface_load() const
  {
    return pressure_term->surface_load();
  }

  bool
  ForwardProblem::tangent_is_symmetric() const
  {
    for (const auto &term : load_terms)
      if (!term->symmetric())
        return false;
    return true;
  }

  LoadState
  ForwardProblem::scene_load() const
  {
    LoadState load;
    load.acceleration = parameters.loads.gravity;
    load.pressure     = parameters.loads.pressure;
    load.fluid =
      pressure_term->surface_load().scene_fluid(parameters.loads.gravity);
    load.terms = 1;
    return load;
  }
} // namespace RestShape
