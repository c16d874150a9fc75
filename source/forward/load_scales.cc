// LoadScales: the body's size, mass and the strains its loads impose.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <restshape/base/units.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/forward/load_scales.h>
#include <restshape/loads/surface_load.h>
#include <restshape/loads/ventricular_pressure.h>

#include <cstdio>
#include <limits>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Strains from this on are "of order one".
    constexpr double large_strain = 0.3;
    /// Soft-tissue bodies between 1 mm and 10 m across.
    constexpr double smallest_body = 1e-3, largest_body = 10;
  } // namespace

  LoadScales
  compute_load_scales(const ForwardProblem &forward)
  {
    const ForwardParameters &prm = forward.scene_parameters();
    const MPI_Comm           comm =
      forward.discretization().mesh().triangulation().get_communicator();
    const EnvironmentParameters &environment = prm.environment;
    const Tensor<1, 3>           gravity     = environment.gravity;
    const Tensor<1, 3>           down =
      gravity.norm() > 0 ? gravity / gravity.norm() : Tensor<1, 3>();
    const auto fully_fixed = [&](const Label label) {
      return prm.discretization.fully_fixed(label);
    };
    double   volume = 0, mass = 0, buoyed = 0, E_volume = 0;
    Point<3> low(std::numeric_limits<double>::max(),
                 std::numeric_limits<double>::max(),
                 std::numeric_limits<double>::max());
    Point<3> high = -low;
    double   top = -std::numeric_limits<double>::max(), bottom = -top;
    for (const auto &cell :
         forward.discretization().dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Label  label = cell->material_id();
          const double V     = cell->measure();
          const double rho   = forward.materials().density(label) *
                             forward.discretization().mesh().mass_ratio(*cell);
          mass += rho * V;
          if (fully_fixed(label))
            continue;
          volume += V;
          // The hydrostatic pressure carries the weight by compressing
          // the tissue: the strain is that of the full weight then.
          buoyed +=
            (environment.hydrostatic ? rho : rho - environment.fluid_density) *
            V;
          E_volume += forward.materials().youngs_modulus(label) * V;
          for (const unsigned int v : cell->vertex_indices())
            {
              const Point<3> &x = cell->vertex(v);
              for (unsigned int d = 0; d < 3; ++d)
                {
                  low[d]  = std::min(low[d], x[d]);
                  high[d] = std::max(high[d], x[d]);
                }
              top    = std::max(top, -(down * x));
              bottom = std::min(bottom, -(down * x));
            }
        }
    LoadScales s;
    volume   = Utilities::MPI::sum(volume, comm);
    s.mass   = Utilities::MPI::sum(mass, comm);
    buoyed   = Utilities::MPI::sum(buoyed, comm);
    E_volume = Utilities::MPI::sum(E_volume, comm);
    for (unsigned int d = 0; d < 3; ++d)
      s.extent[d] =
        Utilities::MPI::max(high[d], comm) + Utilities::MPI::max(-low[d], comm);
    s.height =
      Utilities::MPI::max(top, comm) + Utilities::MPI::max(-bottom, comm);
    if (!(volume > 0))
      return s;
    s.E = E_volume / volume;
    s.gravity_strain =
      std::abs(buoyed / volume) * gravity.norm() * s.height / s.E;
    // The larger of the pressures outside and in the ventricles.
    const LoadState &load = forward.loads().scene_load();
    s.pressure_strain =
      std::max(std::abs(load.weighted(SurfaceLoad::pressure_name)),
               std::abs(load.weighted(VentricularPressure::load_name))) /
      s.E;
    return s;
  }

  std::string
  LoadScales::text() const
  {
    char buffer[400];
    std::snprintf(
      buffer,
      sizeof(buffer),
      "Body: %.4g x %.4g x %.4g mm, %.4g mm high along gravity, "
      "mass %.4g kg; Young's modulus %.4g Pa (volume mean of the "
      "free cells); strain of the weight rho g H / E = "
      "%.3g, of the pressure p / E = %.3g (the larger of the surface "
      "and the ventricular pressure)",
      mm_per_m * extent[0],
      mm_per_m * extent[1],
      mm_per_m * extent[2],
      mm_per_m * height,
      mass,
      E,
      gravity_strain,
      pressure_strain);
    return buffer;
  }

  std::vector<std::string>
  LoadScales::warnings() const
  {
    std::vector<std::string> result;
    char                     buffer[400];
    const double             strain = std::max(gravity_strain, pressure_strain);
    if (strain >= large_strain)
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      "the loads strain the body by about %.3g (%s): the "
                      "co-rotational law inverts cells at strains of order "
                      "one (Materials/Material law = neo-Hookean or Ogden "
                      "resist them); check the units (Young's modulus in "
                      "Pa, density in kg/m^3, Mesh/Length unit) or buoy the "
                      "body (Loads/Fluid density)",
                      strain,
                      gravity_strain >= pressure_strain ? "rho g H / E" :
                                                          "p / E");
        result.push_back(buffer);
      }
    const double size = extent.norm();
    if (size > 0 && (size < smallest_body || size > largest_body))
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      "the body is %.4g m across, implausible for soft "
                      "tissue: is Mesh/Length unit right?",
                      size);
        result.push_back(buffer);
      }
    return result;
  }
} // namespace RestShape
