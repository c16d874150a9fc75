// The screen lines after a solve.
#include <restshape/base/units.h>
#include <restshape/contact/contact_report.h>
#include <restshape/loads/surface_pressure.h>
#include <restshape/loads/surface_traction.h>
#include <restshape/postprocess/screen_report.h>

namespace RestShape
{
  namespace
  {
    /// Active nodes, force, penetration and the strict conditions; nodes
    /// beyond the obstacle, on fixed planes, or pulling.
    void
    report_contact(const PostprocessInput &in)
    {
      const ContactProblem    &contact    = *in.contact;
      const ContactConditions &conditions = in.forward.contact_conditions();
      in.pcout << "  Contact: " << ContactReport(contact).n_active()
               << " active nodes, force " << in.reductions.contact
               << " N, largest penetration "
               << conditions.max_penetration * mm_per_m << " mm; "
               << conditions.text() << std::endl;
      if (in.parameters.inverse.enabled &&
          ContactReport(contact).n_active() > 0)
        {
          in.pcout << "  Contact at the target, by tissue:";
          const LabelNames &names = in.mesh.label_names();
          for (const auto &[label, f] : in.reductions.contact_by_label)
            if (f.norm() > 0)
              in.pcout << ' '
                       << (names.name(label).empty() ?
                             "label " + std::to_string(label) :
                             names.name(label))
                       << " " << f.norm() << " N";
          in.pcout << std::endl;
        }
      if (conditions.outside > 0)
        in.pcout << "  Contact: " << conditions.outside
                 << " candidate nodes lie beyond the obstacle (they started "
                    "there and are free until they come back in)"
                 << std::endl;
      const auto [n_fixed, fixed_distance] = in.reductions.fixed_planes;
      if (n_fixed > 0)
        in.pcout << "  Contact: " << n_fixed
                 << " nodes on fixed planes (their planes kept changing), up "
                    "to "
                 << fixed_distance * mm_per_m << " mm off the obstacle surface"
                 << std::endl;
      const ContactReport::Adhesion &adhesion = in.reductions.adhesion;
      if (adhesion.nodes > 0)
        in.pcout << "  Contact: " << adhesion.nodes
                 << " active nodes pull on the obstacle (accepted), with "
                 << adhesion.force << " N, " << 100 * adhesion.fraction
                 << " % of the contact force" << std::endl;
    }
  } // namespace

  void
  ScreenReport::execute(const PostprocessInput &in)
  {
    const SolveReductions &r = in.reductions;
    in.pcout << "  Displacement: max " << r.max_displacement_mm << " mm, mean "
             << r.mean_displacement_mm << " mm; force balance " << r.imbalance()
             << " N of " << r.external.norm() << " N; potential energy "
             << in.forward.potential_energy() << " J" << std::endl;
    const auto *pressure_term = in.forward.loads().find<SurfacePressure>();
    const bool  pressure =
      pressure_term != nullptr && pressure_term->acts(in.forward.load());
    const std::string kind =
      pressure_term != nullptr && pressure_term->surface_load().follower() ?
        "follower" :
        "dead";
    // surface_force() sums the pressure and the other surface loads.
    if (in.forward.loads().find<SurfaceTraction>() != nullptr)
      in.pcout << "  Surface loads: resultant " << r.surface << " N ("
               << (pressure ? "the " + kind + " pressure and " : "")
               << "the load terms of the scene, e.g. Surface traction)"
               << std::endl;
    else if (pressure)
      in.pcout << "  Surface pressure: resultant " << r.surface << " N ("
               << kind << " load)" << std::endl;
    if (in.forward.loads().has_support())
      in.pcout << "  Elastic support: force " << r.support << " N" << std::endl;
    if (in.contact)
      report_contact(in);
  }
} // namespace RestShape
