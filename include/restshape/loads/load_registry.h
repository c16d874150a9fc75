// The registry of load terms: every load a scene can apply (the body force,
// the surface pressure, the elastic support, a surface traction, ...),
// each with its name, its description, its own parameters and the
// scenario entries it understands.
#ifndef restshape_loads_load_registry_h
#define restshape_loads_load_registry_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/parameter_parsing.h>
#include <restshape/loads/load_term.h>
#include <restshape/loads/scenario_change.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace RestShape
{
  /// What the registry knows of a load term; a term class gives it by a
  /// static info().
  struct LoadTermInfo
  {
    /// The term's name: its load in a LoadState (the name Scenario/Load
    /// scale takes) and its entry in the manual.
    std::string name;
    /// What it does, for the manual (doc/parameters.md).
    std::string description;
    /// The names of its loads in a LoadState (the names Scenario/Load
    /// scale takes); none for a support.
    std::vector<std::string> loads;
    /// Declare its parameters (each entry's help says its unit).
    std::function<void(dealii::ParameterHandler &)> declare;
    /// Read and check them (InputError naming the parameter); @p
    /// length_unit: metres per unit of the mesh. Returns the factory of the
    /// term, or an empty one where the scene does not enable it.
    std::function<LoadTermFactory(dealii::ParameterHandler &,
                                  const double length_unit)>
      parse;
    /// Its parameters that name labels.
    std::vector<LabelListEntry> labels = {};
    /// The entries it declares in every Scenario subsection.
    std::vector<ScenarioEntry> scenario_entries = {};
  };

  /// Every load term, in the order of assembly. A new load is one class and
  /// one line here.
  const std::vector<LoadTermInfo> &
  load_term_registry();

  /// Declare the parameters of every load term (and the environment they
  /// share, environment_parameters.h).
  void
  declare_load_term_parameters(dealii::ParameterHandler &prm);

  /// The parameters of the load terms that name labels.
  std::vector<LabelListEntry>
  load_term_label_entries();

  /// The terms the values of @p prm enable, ready to be made on a
  /// discretisation. Throws InputError naming the parameter for a bad
  /// value.
  std::vector<LoadTermFactory>
  parse_load_terms(dealii::ParameterHandler &prm, const double length_unit);

  /// The scenario entries of every load term.
  std::vector<ScenarioEntry>
  load_scenario_entries();

  /// The names of every term's loads (LoadTermInfo::loads).
  std::vector<std::string>
  load_names();

  /// The load terms as a section of the manual: each term's name,
  /// description, parameters and scenario entries (Markdown).
  std::string
  load_terms_reference();
} // namespace RestShape

#endif
