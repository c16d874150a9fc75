// Subsection "Output": where and what a run writes.
#ifndef restshape_io_output_parameters_h
#define restshape_io_output_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace RestShape
{
  struct OutputParameters
  {
    std::string directory;
    bool        write_vtu;
    bool        write_nodal_csv;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace RestShape

#endif
