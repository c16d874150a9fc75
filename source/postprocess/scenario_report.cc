// summary.json: the brain-shift scenarios.
#include <restshape/base/units.h>
#include <restshape/postprocess/scenario_report.h>

namespace RestShape
{
  namespace
  {
    std::string
    key(const std::string &name, const std::string &what)
    {
      return name + "_" + what;
    }
  } // namespace

  void
  record_scenario_opening(Summary           &summary,
                          const std::string &name,
                          const unsigned int freed_contact_nodes,
                          const unsigned int pressure_faces)
  {
    summary.set(key(name, "craniotomy_freed_contact_nodes"),
                long(freed_contact_nodes));
    summary.set(key(name, "craniotomy_pressure_faces"), long(pressure_faces));
  }

  void
  record_scenario_forces(Summary               &summary,
                         const std::string     &name,
                         const SolveReductions &r)
  {
    summary.set(key(name, "external_force_N"), r.external);
    summary.set(key(name, "support_reaction_N"), r.reaction);
    summary.set(key(name, "contact_force_N"), r.contact);
    summary.set(key(name, "elastic_support_force_N"), r.support);
  }

  void
  record_scenario_success(Summary &summary, const std::string &name)
  {
    summary.set(key(name, "converged"), true);
  }

  void
  record_scenario_failure(Summary           &summary,
                          const std::string &name,
                          const std::string &reason)
  {
    summary.set(key(name, "converged"), false);
    summary.set(key(name, "failure"), reason);
  }

  void
  record_scenario_newton(Summary               &summary,
                         const std::string     &name,
                         const SolveStatistics &prestressed,
                         const SolveStatistics &stress_free)
  {
    summary.set(key(name, "newton_iterations_prestressed"),
                long(prestressed.newton_iterations));
    summary.set(key(name, "newton_iterations_stress_free"),
                long(stress_free.newton_iterations));
  }

  void
  record_scenario_shifts(Summary                         &summary,
                         const std::string               &name,
                         const std::pair<double, double> &prestressed,
                         const std::pair<double, double> &stress_free)
  {
    summary.set(key(name, "prestressed_mean_shift_mm"),
                prestressed.first * mm_per_m);
    summary.set(key(name, "prestressed_max_shift_mm"),
                prestressed.second * mm_per_m);
    summary.set(key(name, "stress_free_mean_shift_mm"),
                stress_free.first * mm_per_m);
    summary.set(key(name, "stress_free_max_shift_mm"),
                stress_free.second * mm_per_m);
  }
} // namespace RestShape
