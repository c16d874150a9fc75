// The VTU record of a cycle.
#include <restshape/contact/contact_report.h>
#include <restshape/postprocess/vtu_fields.h>

namespace RestShape
{
  using namespace dealii;

  void
  VtuFields::execute(const PostprocessInput &in)
  {
    TimerOutput::Scope      scope(in.timer, "Output");
    std::vector<NodalField> fields;
    VectorType              contact_fields;
    if (in.contact)
      {
        contact_fields =
          ContactReport(*in.contact)
            .nodal_fields(in.forward.raw_residual(), in.output.length_scale());
        fields.push_back({&contact_fields,
                          {"contact_active",
                           "contact_gap_" + in.parameters.mesh.length_unit_name,
                           "contact_pressure_Pa"},
                          1.,
                          ""});
      }
    const std::vector<CellField> cells = {
      {"estimated_error", in.estimate.indicators}};
    // The inverse iteration wrote its series; its final state is also the
    // pre-stressed state a later simulation can start from.
    if (in.parameters.inverse.enabled)
      in.output.write_fields(
        in.forward, 0, 0, fields, cells, "prestressed_state");
    else
      in.output.write_fields(in.forward, next_step++, in.cycle, fields, cells);
  }
} // namespace RestShape
