// Subsection "Contact": the obstacle and the active-set method.
#ifndef restshape_contact_contact_parameters_h
#define restshape_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/base/label_values.h>

#include <set>
#include <string>

namespace RestShape
{
  struct ContactParameters
  {
    std::string     obstacle_file; // empty: no contact
    std::string     length_unit_name;
    double          length_unit;
    bool            inside; // allowed region: inside the closed surface
    std::set<Label> labels; // empty: all
    double          active_set_constant;
    unsigned int    free_updates  = 10;
    unsigned int    plane_changes = 6; // then a crease node's planes are fixed
    double max_outside_fraction   = 0.05; // of the candidates, before solving
    double gap_tolerance          = 0;    // m; 0: round-off
    double pull_tolerance         = 0;    // Pa; 0: round-off

    bool
    enabled() const
    {
      return !obstacle_file.empty();
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
