// Subsections "Scenario" and "Scenario NAME": what surgery changes.
#ifndef restshape_app_scenario_parameters_h
#define restshape_app_scenario_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/base/region.h>
#include <restshape/loads/environment_parameters.h>
#include <restshape/loads/scenario_change.h>

#include <map>
#include <string>

namespace RestShape
{
  /**
   * Scenario: what surgery changes after the rest shape (the head turned,
   * the CSF drained, a force field), applied to the pre-stressed model and
   * to the model stress-free in the same geometry (source/app/scenario.cc).
   * Subsection "Scenario", and one "Scenario NAME" per further scenario.
   */
  struct ScenarioParameters
  {
    std::string name; // empty: subsection "Scenario"
    bool        enabled = false;
    /// What it changes, as the load terms see it: gravity rotated (about
    /// x, then y, then z), the fluid drained to a level (m, given in the
    /// mesh's length unit), the craniotomy (m), the values of the load
    /// terms' own entries (e.g. Surface pressure, Tissue body force).
    ScenarioChange change;
    /// Scenario/Load scale: load name -> factor.
    std::map<std::string, double> scale;

    /// The subsection "Scenario" (@p name empty) or "Scenario NAME".
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const std::string        &name = "");
    /// @p length_unit: metres per unit of the mesh, in which the fluid
    /// level and the craniotomy are given.
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const std::string        &name,
                     const double              length_unit);
    /// "Scenario" or "Scenario NAME": what error messages name.
    std::string
    section() const;
    /// "scenario" or "scenario_NAME": its files and summary keys.
    std::string
    output_name() const;
    /// Read the craniotomy's surface file (Craniotomy = 'surface: FILE',
    /// after Region::scale()): its inside test. Throws InputError naming
    /// the file and Scenario/Craniotomy.
    void
    read_surfaces();
    /// The value of the load term's entry @p e into change.values.
    void
    parse_entry(dealii::ParameterHandler &prm, const ScenarioEntry &e);
    /// Load scale's 'NAME: factor' list into scale.
    void
    parse_scale(const std::string &text);
    /// InputError for what an enabled scenario cannot do in this
    /// @p environment, or without the inverse problem (@p inverse_enabled).
    void
    check(const EnvironmentParameters &environment,
          const bool                   inverse_enabled) const;
  };
} // namespace RestShape

#endif
