// Subsections "Scenario" and "Scenario NAME": what surgery changes.
#ifndef restshape_app_scenario_parameters_h
#define restshape_app_scenario_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/base/region.h>
#include <restshape/loads/load_parameters.h>

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
    std::string          name; // empty: subsection "Scenario"
    bool                 enabled = false;
    dealii::Tensor<1, 3> rotation_degrees; // about x, then y, then z
    bool                 has_fluid_level = false;
    dealii::Point<3>     fluid_level; // m (given in the mesh's length unit)
    bool                 has_pressure = false;
    double               pressure     = 0;    // Pa
    dealii::Tensor<1, 3> tissue_acceleration; // m/s^2
    Region               craniotomy;          // m (given in the mesh unit)

    /// The subsection "Scenario" (@p name empty) or "Scenario NAME".
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const std::string        &name = "");
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &name);
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
    /// InputError for what an enabled scenario cannot do with these
    /// @p loads, or without the inverse problem (@p inverse_enabled).
    void
    check(const LoadParameters &loads, const bool inverse_enabled) const;
  };
} // namespace RestShape

#endif
