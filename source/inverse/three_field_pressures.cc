// ThreeFieldPressures: the direct inverse's cell pressures (see
// three_field_pressures.h).
#include <restshape/inverse/three_field_pressures.h>

namespace RestShape
{
  ThreeFieldPressures::ThreeFieldPressures(ForwardProblem &forward)
    : forward(forward)
  {}

  bool
  ThreeFieldPressures::enabled() const
  {
    return forward.scene_parameters().discretization.mixed;
  }

  void
  ThreeFieldPressures::forget()
  {
    known = false;
  }

  void
  ThreeFieldPressures::begin_step()
  {
    if (!enabled())
      return;
    at_step = forward.pressure_points();
    if (!known)
      {
        pressure.resize(at_step.size());
        for (unsigned int c = 0; c < at_step.size(); ++c)
          pressure[c] = at_step[c].dU;
      }
    std::vector<double> offsets(at_step.size());
    for (unsigned int c = 0; c < at_step.size(); ++c)
      offsets[c] = pressure[c] - at_step[c].dU;
    forward.set_pressure_offsets(std::move(offsets));
  }

  void
  ThreeFieldPressures::record_direction(const double e)
  {
    if (!enabled())
      return;
    const std::vector<PressurePoint> &moved = forward.pressure_points();
    change.resize(at_step.size());
    for (unsigned int c = 0; c < at_step.size(); ++c)
      change[c] = (moved[c].J - at_step[c].J) / e;
  }

  void
  ThreeFieldPressures::end_products()
  {
    if (enabled())
      forward.set_pressure_offsets({});
  }

  void
  ThreeFieldPressures::accept(const double alpha)
  {
    if (!enabled() || change.size() != at_step.size())
      return;
    pressure.resize(at_step.size());
    for (unsigned int c = 0; c < at_step.size(); ++c)
      pressure[c] = at_step[c].dU + at_step[c].d2U * alpha * change[c];
    known = true;
  }
} // namespace RestShape
