// The loads of a scenario: gravity turned about the mesh's axes (right-
// handed, x then y then z), the drainage as the buoyancy lost above a
// level, and the change between two load states that the stress-free model
// receives (linear in every term, so load stepping reaches it exactly).
#include <restshape/app/scenario.h>

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

  LoadState
  turned(const Tensor<1, 3> &degrees, const Tensor<1, 3> &gravity)
  {
    ScenarioParameters p;
    p.rotation_degrees = degrees;
    LoadState scene;
    scene.acceleration = gravity;
    return changed_load(p, scene);
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
  scene.acceleration      = vec(0, 0, -g);
  scene.pressure          = 100;
  const LoadState changed = changed_load(p, scene);
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
  return failures == 0 ? 0 : 1;
}
