// Subsection "Loads": gravity, the pressure and the immersing fluid.
#ifndef restshape_loads_load_parameters_h
#define restshape_loads_load_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <restshape/base/label_values.h>

#include <set>

namespace RestShape
{
  struct LoadParameters
  {
    dealii::Tensor<1, 3> gravity;  // m/s^2
    double               pressure; // Pa, positive pushes inward
    bool   follower      = true;   // the pressure acts on the current surface
    double fluid_density = 0;      // kg/m^3 of an immersing fluid
    /// The fluid acts as hydrostatic pressure on the pressure faces (else:
    /// as buoyancy, a reduced density).
    bool             hydrostatic     = false;
    bool             has_fluid_level = false;
    dealii::Point<3> fluid_level;     // m, on the free surface
    std::set<Label>  pressure_labels; // empty: all unfixed labels

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
