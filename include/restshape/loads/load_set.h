// The load terms of a scene, made from the registry on a discretisation:
// what the forward problem's assembly, its reports and the scenarios ask
// of the loads, without knowing any of them.
#ifndef restshape_loads_load_set_h
#define restshape_loads_load_set_h

#include <restshape/loads/load_registry.h>
#include <restshape/loads/load_term.h>

#include <memory>
#include <string>
#include <typeinfo>
#include <vector>

namespace RestShape
{
  class LoadSet
  {
  public:
    /// Make the terms of @p factories on @p context (in the registry's
    /// order). Throws InputError where a term cannot act (e.g. a fluid
    /// that wets no pressure face).
    void
    create(const std::vector<LoadTermFactory> &factories,
           const LoadContext                  &context);

    /// The scene's load: every term's at weight 1.
    LoadState
    scene_load() const;
    /// The scene's load @p scene changed as the scenario @p change says:
    /// each term's change, then the loads scaled by name (@p scale: load
    /// name -> factor), then what an opening takes off.
    LoadState
    changed_load(const ScenarioChange                &change,
                 const LoadState                     &scene,
                 const std::map<std::string, double> &scale) const;
    /// What changed from @p scene to @p changed, term by term ("; "
    /// between them; empty if nothing the terms describe).
    std::string
    change_text(const LoadState &scene, const LoadState &changed) const;
    /// An opening of the skull for every term (empty region: closed
    /// again); the number of faces it changes.
    unsigned int
    open(const Region &opening);

    /// Whether the body force of @p load varies within a cell.
    bool
    body_force_varies(const LoadState &load) const;
    /// The body force per unit mesh volume (N/m^3) of @p load at the point
    /// @p X of @p cell (mesh geometry): the sum of the terms'.
    dealii::Tensor<1, 3>
    body_force(const dealii::CellAccessor<3, 3> &cell,
               const dealii::Point<3>           &X,
               const LoadState                  &load) const;
    /// The face terms of @p c's cell: first the dead terms', then the dead
    /// loads' potential -f_ext . (d - w), then the others' (which add their
    /// own potential).
    void
    assemble_faces(const LoadCell &c) const;
    /// Whether the assembled tangent of every term is symmetric.
    bool
    symmetric() const;
    /// Over all ranks: the resultant (N) of the terms' face forces under
    /// @p load at the state @p d, @p w (ghosted): of the loads, or with
    /// @p supports of the supports only.
    dealii::Tensor<1, 3>
    resultant(const LoadState  &load,
              const VectorType &d,
              const VectorType &w,
              const bool        supports,
              const MPI_Comm    comm) const;
    /// Whether a term holds the body as a support.
    bool
    has_support() const;

    /// The term of class @p Term itself (not of a class derived from it:
    /// find<SurfacePressure>() is never the VentricularPressure), or null
    /// if the scene has none.
    template <typename Term>
    const Term *
    find() const
    {
      for (const auto &term : terms)
        if (typeid(*term) == typeid(Term))
          return static_cast<const Term *>(term.get());
      return nullptr;
    }

  private:
    std::vector<std::unique_ptr<LoadTerm>> terms;
    /// The terms with a body force.
    std::vector<const LoadTerm *> body_terms;
  };
} // namespace RestShape

#endif
