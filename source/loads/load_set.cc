#include <deal.II/base/mpi.h>

#include <restshape/loads/load_set.h>

namespace RestShape
{
  using namespace dealii;

  void
  LoadSet::create(const std::vector<LoadTermFactory> &factories,
                  const LoadContext                  &context)
  {
    terms.clear();
    body_terms.clear();
    for (const LoadTermFactory &make : factories)
      terms.push_back(make(context));
    for (const auto &term : terms)
      if (term->has_body_force())
        body_terms.push_back(term.get());
  }

  LoadState
  LoadSet::scene_load() const
  {
    LoadState load;
    for (const auto &term : terms)
      term->scene_load(load);
    return load;
  }

  LoadState
  LoadSet::changed_load(const ScenarioChange                &change,
                        const LoadState                     &scene,
                        const std::map<std::string, double> &scale) const
  {
    LoadState changed = scene;
    for (const auto &term : terms)
      term->change_load(change, changed);
    for (const auto &[name, factor] : scale)
      changed.scale(name, factor);
    for (const auto &term : terms)
      term->open_load(change, changed);
    return changed;
  }

  std::string
  LoadSet::change_text(const LoadState &scene, const LoadState &changed) const
  {
    std::string text;
    for (const auto &term : terms)
      if (const std::string part = term->change_text(scene, changed);
          !part.empty())
        text += (text.empty() ? "" : "; ") + part;
    return text;
  }

  unsigned int
  LoadSet::open(const Region &opening)
  {
    unsigned int faces = 0;
    for (const auto &term : terms)
      faces += term->open(opening);
    return faces;
  }

  bool
  LoadSet::body_force_varies(const LoadState &load) const
  {
    for (const LoadTerm *term : body_terms)
      if (term->body_force_varies(load))
        return true;
    return false;
  }

  Tensor<1, 3>
  LoadSet::body_force(const CellAccessor<3, 3> &cell,
                      const Point<3>           &X,
                      const LoadState          &load) const
  {
    Tensor<1, 3> f;
    for (const LoadTerm *term : body_terms)
      f += term->body_force(cell, X, load);
    return f;
  }

  void
  LoadSet::assemble_faces(const LoadCell &c) const
  {
    // Dead loads (gravity, a dead pressure): their potential is
    // -f_ext . (d - w), the work done from the rest shape. A follower
    // pressure or a support adds its own potential.
    for (const auto &term : terms)
      if (term->dead())
        term->assemble_faces(c);
    for (unsigned int i = 0; i < c.cell_external.size(); ++i)
      c.energy -= c.cell_external(i) * (c.d[i] - c.w[i]);
    for (const auto &term : terms)
      if (!term->dead())
        term->assemble_faces(c);
  }

  bool
  LoadSet::symmetric() const
  {
    for (const auto &term : terms)
      if (!term->symmetric())
        return false;
    return true;
  }

  Tensor<1, 3>
  LoadSet::resultant(const LoadState  &load,
                     const VectorType &d,
                     const VectorType &w,
                     const bool        supports,
                     const MPI_Comm    comm) const
  {
    Tensor<1, 3> force;
    for (const auto &term : terms)
      if (term->is_support() == supports)
        force += term->local_resultant(load, d, w);
    for (unsigned int c = 0; c < 3; ++c)
      force[c] = Utilities::MPI::sum(force[c], comm);
    return force;
  }

  bool
  LoadSet::has_support() const
  {
    for (const auto &term : terms)
      if (term->is_support())
        return true;
    return false;
  }
} // namespace RestShape
