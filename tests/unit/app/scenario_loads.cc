// The loads of a scenario, through the load terms of a scene (the P2
// column of tests/scenes/column_p2_tet.prm, 20 x 20 x 50 mm, its base at
// z = 0): gravity turned about the mesh's axes (right-handed, x then y
// then z), the drainage as the buoyancy lost above a level or as a
// hydrostatic pressure cut at the level, a load scaled by name, and the
// change between two load states that the stress-free model receives
// (linear in every term, so load stepping reaches it exactly).
#include <deal.II/base/mpi.h>

#include <restshape/base/input_error.h>
#include <restshape/base/mpi_start.h>
#include <restshape/loads/surface_load.h>

#include <cmath>

#include "checks.h"
#include "test_utilities.h"

using namespace RestShape;
using namespace RestShape::Test;
using namespace checks;
using dealii::Point;
using dealii::Tensor;

namespace
{
  Tensor<1, 3>
  vec(const double x, const double y, const double z)
  {
    return Tensor<1, 3>({x, y, z});
  }

  bool
  near(const Tensor<1, 3> &a, const Tensor<1, 3> &b)
  {
    return (a - b).norm() <= 1e-14 * (1 + b.norm());
  }

  const std::string gravity = "Gravity", drained = "Drained buoyancy",
                    tissue = "Tissue body force";

  /// The column scene with @p more .prm text (a scenario, loads).
  std::string
  column(const std::string &more)
  {
    return "subsection Mesh\n set File = meshes/column_tet.msh\n"
           " set Length unit = mm\nend\n"
           "subsection Boundary conditions\n set Fixed labels = 2\nend\n"
           "subsection Inverse problem\n set Enabled = true\nend\n" +
           more;
  }

  /// The change of the first enabled scenario of @p prm_text.
  ScenarioParameters
  scenario(const std::string &prm_text)
  {
    const Parameters p = parsed_parameters(column(prm_text));
    AssertThrow(!p.scenarios.empty(), dealii::ExcInternalError());
    return p.scenarios[0];
  }

  /// Gravity @p g turned by @p degrees ('x, y, z').
  Tensor<1, 3>
  turned(const std::string &degrees, const Tensor<1, 3> &g)
  {
    return scenario("subsection Scenario\n set Enabled = true\n"
                    " set Gravity rotation = " +
                    degrees + "\nend\n")
             .change.rotation *
           g;
  }

  /// A scene's load changed by its first scenario.
  struct Changed
  {
    Changed(const std::string &prm_text)
      : scene(column(prm_text))
      , before(scene.forward->loads().scene_load())
      , after(scene.forward->loads().changed_load(
          scene.parameters.scenarios[0].change,
          before,
          scene.parameters.scenarios[0].scale))
    {}
    Scene     scene;
    LoadState before, after;
  };

  void
  check_rotations(const double g)
  {
    expect(turned("90, 0, 0", vec(0, 0, -g)) == vec(0, g, 0),
           "90 degrees about x turn (0, 0, -g) to (0, g, 0), exactly");
    expect(turned("0, 90, 0", vec(1, 0, 0)) == vec(0, 0, -1),
           "90 degrees about y turn x to -z (right-handed)");
    expect(turned("0, 0, 90", vec(1, 0, 0)) == vec(0, 1, 0),
           "90 degrees about z turn x to y");
    expect(turned("180, 0, 0", vec(0, -g, 0)) == vec(0, g, 0),
           "supine to prone (180 about x) reverses (0, -g, 0)");
    expect(turned("90, 90, 0", vec(0, 1, 0)) == vec(1, 0, 0),
           "x first, then y: y -> z -> x");
    const Tensor<1, 3> a = turned("30, -45, 120", vec(0.3, -2, 9));
    expect(std::abs(a.norm() - vec(0.3, -2, 9).norm()) < 1e-14,
           "a rotation keeps the magnitude");
    expect(near(turned("-30, 0, 0", turned("30, 0, 0", vec(1, 2, 3))),
                vec(1, 2, 3)),
           "the opposite angle turns back");
    const Changed prone("subsection Scenario\n set Enabled = true\n"
                        " set Gravity rotation = 180, 0, 0\nend\n");
    expect(prone.after.weighted_vector(gravity) == vec(0, 0, g),
           "the body force's gravity turns with the head");
  }

  void
  check_drainage(const double g)
  {
    const Changed             c("subsection Loads\n set Fluid density = 1000\n"
                                " set Surface pressure = 100\nend\n"
                                "subsection Scenario\n set Enabled = true\n"
                                " set Fluid level = 0, 0, 10\n set Surface pressure = 0\n"
                                " set Tissue body force = 1, 0, 0\nend\n");
    const std::vector<double> level_column = {0, 0, -g, 0, 0, 0.01};
    const LoadState          &changed      = c.after;
    expect(changed.columns(drained).size() == 1 &&
             changed.columns(drained)[0].parameters == level_column &&
             changed.weighted(SurfaceLoad::pressure_name) == 0 &&
             changed.weighted_vector(tissue) == vec(1, 0, 0),
           "drained to a level: the buoyancy lost under the (turned) gravity "
           "at the level (m), the pressure set, the tissue force added");
    const LoadState change = difference(changed, c.before);
    expect(!change.acts(gravity) &&
             change.weighted(SurfaceLoad::pressure_name) == -100 &&
             change.weighted_vector(drained) == vec(0, 0, -g) &&
             change.weighted_vector(tissue) == vec(1, 0, 0),
           "the change: gravity unchanged, the pressure's drop, the drainage "
           "and the tissue force");
    const LoadState half = between(c.before, changed, 0.5);
    expect(half.weighted(SurfaceLoad::pressure_name) == 50 &&
             half.weighted_vector(drained) == vec(0, 0, -g / 2) &&
             half.columns(drained)[0].parameters == level_column,
           "half way, half the drainage at the new level");
    const LoadState end = between(c.before, changed, 1);
    expect(end.weighted_vector(gravity) == changed.weighted_vector(gravity) &&
             end.weighted_vector(drained) == changed.weighted_vector(drained) &&
             end.weighted(SurfaceLoad::pressure_name) ==
               changed.weighted(SurfaceLoad::pressure_name),
           "load stepping ends at the changed load");
    expect(difference(c.before, c.before).empty() &&
             between(c.before, c.before, 0.3).columns(gravity).size() == 1,
           "no change is an empty load; equal columns merge");
  }

  void
  check_opening_and_scale()
  {
    // A craniotomy: its faces lose the uniform pressure after the change.
    const Changed     c("subsection Loads\n set Surface pressure = 100\nend\n"
                        "subsection Scenario\n set Enabled = true\n"
                        " set Craniotomy = sphere: 0, 0, 10, 5\n"
                        " set Surface pressure = 40\n"
                        " set Load scale = Gravity: 0.5\nend\n");
    const std::string opening = SurfaceLoad::opening_pressure_name;
    const LoadState  &open    = c.after;
    expect(open.weighted(SurfaceLoad::pressure_name) == 40 &&
             open.weighted(opening) == 40,
           "an opening is at atmospheric pressure: it loses the pressure "
           "after the change");
    const LoadState change = difference(open, c.before);
    expect(change.weighted(opening) == 40 &&
             change.weighted(SurfaceLoad::pressure_name) == -60 &&
             between(c.before, open, 0.25).weighted(opening) == 10,
           "the opening's pressure is a linear load term");
    expect(open.weighted_vector(gravity) ==
             0.5 * c.before.weighted_vector(gravity),
           "Load scale scales a load by its name");
    const Region &sphere = c.scene.parameters.scenarios[0].change.opening;
    expect(sphere.contains(Point<3>(0, 0.003, 0.014)) &&
             !sphere.contains(Point<3>(0, 0.003, 0.01401)),
           "a sphere (mesh units, mm) contains its inside and boundary, not "
           "beyond");
    unsigned int refused = 0;
    for (const char *bad : {"Nothing: 1", "Gravity 1", "Gravity: x"})
      try
        {
          scenario(std::string("subsection Scenario\n set Enabled = true\n"
                               " set Load scale = ") +
                   bad + "\nend\n");
        }
      catch (const InputError &e)
        {
          refused += e.parameter == "Scenario/Load scale";
        }
    expect(refused == 3, "an unknown load or a bad factor is refused");
  }

  void
  check_regions()
  {
    const Region cylinder =
      parse_region("cylinder: 1, 1, 0, 0, 0, 2, 3", "test");
    expect(cylinder.contains(Point<3>(1, 4, -1e6)) &&
             !cylinder.contains(Point<3>(4.01, 1, 0)),
           "a cylinder is unbounded along its (normalised) axis");
    unsigned int refused = 0;
    for (const char *bad : {"sphere: 0, 0, 0",
                            "cube: 0, 0, 0, 1",
                            "sphere 0, 0, 0, 1",
                            "sphere: 0, 0, 0, -1",
                            "cylinder: 0, 0, 0, 0, 0, 0, 1",
                            "sphere: a, 0, 0, 1"})
      try
        {
          parse_region(bad, "test");
        }
      catch (const InputError &)
        {
          refused += 1;
        }
    expect(refused == 6 && parse_region(" ", "test").defined() == false,
           "bad regions are refused; an empty one is none");
  }

  /// The hydrostatic pressure: the column under (0, 0, -g), its fluid's
  /// free surface at z = 100 mm, turned, drained and opened.
  void
  check_hydrostatic(const double g)
  {
    const std::string loads =
      "subsection Loads\n set Fluid density = 1000\n"
      " set Fluid load = hydrostatic pressure\n set Fluid level = 0, 0, 100\n"
      "end\n";
    const SurfaceLoad surface(true, 1000, Point<3>(0, 0, 0.1));
    const auto        p = [&](const LoadState  &load,
                       const Point<3>   &x,
                       SurfaceLoad::Face face = SurfaceLoad::Face::covered) {
      return surface.pressure(SurfaceLoad::field(load), x, face);
    };
    const Point<3>   x(0, 0.02, 0.05); // 0.05 m below the surface
    const Changed    prone(loads + "subsection Scenario\n set Enabled = true\n"
                                   " set Gravity rotation = 180, 0, 0\nend\n");
    const LoadState &scene = prone.before;
    expect(std::abs(p(scene, x) - 1000 * g * 0.05) < 1e-9,
           "the scene's hydrostatic pressure: rho g depth");
    // Turned prone about the given level, the pressure grows towards +z.
    const LoadState &flipped = prone.after;
    expect(flipped.columns(SurfaceLoad::fluid_name).size() == 1 &&
             std::abs(p(flipped, Point<3>(0, 0, 0.12)) - 1000 * g * 0.02) <
               1e-9 &&
             p(flipped, x) == 0,
           "turned prone, the fluid pushes from its level towards +z");
    const LoadState change = difference(flipped, scene);
    expect(change.columns(SurfaceLoad::fluid_name).size() == 2 &&
             std::abs(p(change, x) + 1000 * g * 0.05) < 1e-9,
           "the change: the turned column less the scene's");
    expect(std::abs(p(between(scene, flipped, 0.25), x) -
                    1000 * g * 0.75 * 0.05) < 1e-9,
           "load stepping blends the two columns");

    const Changed    drained_low(loads +
                              "subsection Scenario\n set Enabled = true\n"
                                 " set Fluid level = 0, 0, 30\nend\n");
    const LoadState &low = drained_low.after;
    expect(p(low, x) == 0 &&
             std::abs(p(low, Point<3>(0, 0, 0.01)) - 1000 * g * 0.02) < 1e-9 &&
             !low.acts(drained),
           "drained: no pressure above the level, rho g depth below it, no "
           "buoyancy term");

    const Changed    opened(loads + "subsection Scenario\n set Enabled = true\n"
                                    " set Craniotomy = sphere: 0, 0, 0, 1000\n"
                                    "end\n");
    const LoadState &open       = opened.after;
    const auto       in_opening = SurfaceLoad::Face::opened;
    const PressureField field   = SurfaceLoad::field(open);
    expect(p(open, x, in_opening) == 0 &&
             surface.pressure_gradient(field, x, in_opening) ==
               Tensor<1, 3>() &&
             surface.potential_flux(field, x, in_opening).norm() < 1e-15 &&
             std::abs(p(open, x) - 1000 * g * 0.05) < 1e-9,
           "an opening is at atmospheric pressure, the rest stays wetted");
    expect(std::abs(p(difference(open, scene), x, in_opening) +
                    1000 * g * 0.05) < 1e-9 &&
             p(difference(open, scene), x) == 0,
           "the change at an opening: the scene's pressure taken off");
  }
} // namespace

int
main(int argc, char **argv)
{
  prefer_fast_singleton_mpi();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             g = 9.81;
  check_rotations(g);
  check_drainage(g);
  check_opening_and_scale();
  check_regions();
  check_hydrostatic(g);
  return checks::failures == 0 ? 0 : 1;
}
