// The loads of a scenario: gravity turned about the mesh's axes (right-
// handed, x then y then z), the drainage as the buoyancy lost above a
// level or as a hydrostatic pressure cut at the level, and the change
// between two load states that the stress-free model receives (linear in
// every term, so load stepping reaches it exactly).
#include <restshape/app/scenario.h>
#include <restshape/base/input_error.h>
#include <restshape/loads/surface_load.h>

#include <cmath>

#include "checks.h"

using namespace RestShape;
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

  /// Buoyancy: the free surface is never asked for.
  const FreeSurface no_surface = [](const Tensor<1, 3> &) -> Point<3> {
    throw InputError("", "test", "the free surface asked for");
  };

  LoadState
  turned(const Tensor<1, 3> &degrees, const Tensor<1, 3> &gravity)
  {
    ScenarioParameters p;
    p.rotation_degrees = degrees;
    LoadState scene;
    scene.acceleration = gravity;
    return changed_load(p, LoadParameters(), scene, no_surface);
  }

  /// The hydrostatic pressure: the scene under (0, 0, -g) with its free
  /// surface at z = 0.1 m, turned, drained and opened.
  void
  check_hydrostatic(const double g)
  {
    LoadParameters loads;
    loads.hydrostatic   = true;
    loads.fluid_density = 1000;
    const SurfaceLoad surface(loads, Point<3>(0, 0, 0.1));
    LoadState         scene;
    scene.acceleration = vec(0, 0, -g);
    scene.fluid        = surface.scene_fluid(scene.acceleration);
    const Point<3> x(0, 0.02, 0.05); // 0.05 m below the surface
    expect(std::abs(surface.pressure(scene, x) - 1000 * g * 0.05) < 1e-9,
           "the scene's hydrostatic pressure: rho g depth");

    ScenarioParameters prone;
    prone.rotation_degrees = vec(180, 0, 0);
    const Point<3> bottom(0, 0, -0.1); // the surface after the turn
    const auto     turned_surface = [&](const Tensor<1, 3> &a) {
      expect(a == vec(0, 0, g), "the free surface under the turned gravity");
      return bottom;
    };
    const LoadState flipped = changed_load(prone, loads, scene, turned_surface);
    expect(flipped.fluid.size() == 1 &&
             std::abs(surface.pressure(flipped, x) - 1000 * g * 0.15) < 1e-9,
           "turned prone, the pressure grows towards +z from the new surface");
    const LoadState change = difference(flipped, scene);
    expect(change.fluid.size() == 2 &&
             std::abs(surface.pressure(change, x) - 1000 * g * 0.10) < 1e-9,
           "the change: the turned column less the scene's");
    expect(std::abs(surface.pressure(between(scene, flipped, 0.25), x) -
                    1000 * g * (0.75 * 0.05 + 0.25 * 0.15)) < 1e-9,
           "load stepping blends the two columns");
    expect(between(scene, scene, 0.3).fluid.size() == 1, "equal columns merge");

    ScenarioParameters drained;
    drained.has_fluid_level = true;
    drained.fluid_level     = Point<3>(0, 0, 0.03);
    const LoadState low     = changed_load(drained, loads, scene, no_surface);
    expect(surface.pressure(low, x) == 0 &&
             std::abs(surface.pressure(low, Point<3>(0, 0, 0.01)) -
                      1000 * g * 0.02) < 1e-9 &&
             low.drained_acceleration == Tensor<1, 3>(),
           "drained: no pressure above the level, rho g depth below it, no "
           "buoyancy term");

    ScenarioParameters opened;
    opened.craniotomy          = parse_region("sphere: 0, 0, 0, 1", "test");
    const LoadState open       = changed_load(opened, loads, scene, no_surface);
    const auto      in_opening = SurfaceLoad::Face::opened;
    expect(surface.pressure(open, x, in_opening) == 0 &&
             surface.pressure_gradient(open, x, in_opening) == Tensor<1, 3>() &&
             surface.potential_flux(open, x, in_opening).norm() < 1e-15 &&
             std::abs(surface.pressure(open, x) - 1000 * g * 0.05) < 1e-9,
           "an opening is at atmospheric pressure, the rest stays wetted");
    expect(std::abs(surface.pressure(difference(open, scene), x, in_opening) +
                    1000 * g * 0.05) < 1e-9 &&
             surface.pressure(difference(open, scene), x) == 0,
           "the change at an opening: the scene's pressure taken off");
  }
} // namespace

int
main()
{
  const double g = 9.81;
  expect(turned(vec(90, 0, 0), vec(0, 0, -g)).acceleration == vec(0, g, 0),
         "90 degrees about x turn (0, 0, -g) to (0, g, 0), exactly");
  expect(turned(vec(0, 90, 0), vec(1, 0, 0)).acceleration == vec(0, 0, -1),
         "90 degrees about y turn x to -z (right-handed)");
  expect(turned(vec(0, 0, 90), vec(1, 0, 0)).acceleration == vec(0, 1, 0),
         "90 degrees about z turn x to y");
  expect(turned(vec(180, 0, 0), vec(0, -g, 0)).acceleration == vec(0, g, 0),
         "supine to prone (180 about x) reverses (0, -g, 0)");
  expect(turned(vec(90, 90, 0), vec(0, 1, 0)).acceleration == vec(1, 0, 0),
         "x first, then y: y -> z -> x");
  const Tensor<1, 3> a =
    turned(vec(30, -45, 120), vec(0.3, -2, 9)).acceleration;
  expect(std::abs(a.norm() - vec(0.3, -2, 9).norm()) < 1e-14,
         "a rotation keeps the magnitude");
  expect(near(turned(vec(-30, 0, 0),
                     turned(vec(30, 0, 0), vec(1, 2, 3)).acceleration)
                .acceleration,
              vec(1, 2, 3)),
         "the opposite angle turns back");

  ScenarioParameters p;
  p.has_fluid_level     = true;
  p.fluid_level         = Point<3>(0, 0, 0.01);
  p.has_pressure        = true;
  p.pressure            = 0;
  p.tissue_acceleration = vec(1, 0, 0);
  LoadState scene;
  scene.acceleration = vec(0, 0, -g);
  scene.pressure     = 100;
  const LoadState changed =
    changed_load(p, LoadParameters(), scene, no_surface);
  expect(changed.drained_acceleration == vec(0, 0, -g) &&
           changed.fluid_level == p.fluid_level && changed.pressure == 0 &&
           changed.tissue_acceleration == vec(1, 0, 0),
         "drained to a level: the buoyancy lost under the (turned) gravity, "
         "the pressure set, the tissue force added");
  const LoadState change = difference(changed, scene);
  expect(change.acceleration == Tensor<1, 3>() && change.pressure == -100 &&
           change.drained_acceleration == vec(0, 0, -g) &&
           change.fluid_level == p.fluid_level &&
           change.tissue_acceleration == vec(1, 0, 0),
         "the change: gravity unchanged, the pressure's drop, the drainage "
         "and the tissue force");
  const LoadState half = between(scene, changed, 0.5);
  expect(half.pressure == 50 &&
           half.drained_acceleration == vec(0, 0, -g / 2) &&
           half.fluid_level == p.fluid_level,
         "half way, half the drainage at the new level");
  const LoadState end = between(scene, changed, 1);
  expect(end.acceleration == changed.acceleration &&
           end.drained_acceleration == changed.drained_acceleration &&
           end.pressure == changed.pressure,
         "load stepping ends at the changed load");

  // A craniotomy: its faces lose the uniform pressure after the change.
  ScenarioParameters opened;
  opened.craniotomy   = parse_region("sphere: 0, 0, 10, 5", "test");
  opened.has_pressure = true;
  opened.pressure     = 40;
  const LoadState open =
    changed_load(opened, LoadParameters(), scene, no_surface);
  expect(open.pressure == 40 && open.opening_pressure == 40,
         "an opening is at atmospheric pressure: it loses the pressure "
         "after the change");
  expect(difference(open, scene).opening_pressure == 40 &&
           difference(open, scene).pressure == -60 &&
           between(scene, open, 0.25).opening_pressure == 10,
         "the opening's pressure is a linear load term");
  expect(opened.craniotomy.contains(Point<3>(0, 3, 14)) &&
           !opened.craniotomy.contains(Point<3>(0, 3, 14.01)),
         "a sphere contains its inside and boundary, not beyond");
  const Region cylinder = parse_region("cylinder: 1, 1, 0, 0, 0, 2, 3", "test");
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
  check_hydrostatic(g);
  return failures == 0 ? 0 : 1;
}
