#include <restshape/loads/load_registry.h>
#include <restshape/loads/surface_traction.h>

#include <functional>

namespace RestShape
{
  namespace
  {
    /// What the registry knows of a load term.
    struct Registration
    {
      std::function<void(dealii::ParameterHandler &)>            declare;
      std::function<LoadTermFactory(dealii::ParameterHandler &)> parse;
      std::vector<LabelListEntry>                                labels;
    };

    /// A term class with static declare_parameters(prm),
    /// parse_parameters(prm) (an empty factory where the scene does not
    /// enable it) and label_entries().
    template <typename Term>
    Registration
    registration()
    {
      return {&Term::declare_parameters,
              &Term::parse_parameters,
              Term::label_entries()};
    }

    /// Every registered term. A new load is one class and one line here.
    const std::vector<Registration> &
    registry()
    {
      static const std::vector<Registration> terms = {
        registration<SurfaceTraction>()};
      return terms;
    }
  } // namespace

  void
  declare_load_term_parameters(dealii::ParameterHandler &prm)
  {
    for (const Registration &r : registry())
      r.declare(prm);
  }

  std::vector<LabelListEntry>
  load_term_label_entries()
  {
    std::vector<LabelListEntry> entries;
    for (const Registration &r : registry())
      entries.insert(entries.end(), r.labels.begin(), r.labels.end());
    return entries;
  }

  std::vector<LoadTermFactory>
  parse_load_terms(dealii::ParameterHandler &prm)
  {
    std::vector<LoadTermFactory> factories;
    for (const Registration &r : registry())
      if (LoadTermFactory make = r.parse(prm))
        factories.push_back(std::move(make));
    return factories;
  }

  std::vector<std::unique_ptr<LoadTerm>>
  create_load_terms(const std::vector<LoadTermFactory> &factories,
                    const LoadContext                  &context)
  {
    std::vector<std::unique_ptr<LoadTerm>> terms;
    for (const LoadTermFactory &make : factories)
      terms.push_back(make(context));
    return terms;
  }
} // namespace RestShape
