// What a scene file describes: every part's parameters together. The
// driver (Simulator) parses them and hands each part its slice; the
// postprocessors see them all, as ASPECT's see the simulator's.
#ifndef restshape_app_parameters_h
#define restshape_app_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <restshape/app/scenario_parameters.h>
#include <restshape/base/label_names.h>
#include <restshape/base/label_values.h>
#include <restshape/base/parameter_parsing.h>
#include <restshape/contact/contact_parameters.h>
#include <restshape/forward/forward_parameters.h>
#include <restshape/inverse/inverse_parameters.h>
#include <restshape/io/output_parameters.h>
#include <restshape/mesh/mesh_parameters.h>
#include <restshape/postprocess/postprocessor.h>
#include <restshape/postprocess/refinement_parameters.h>
#include <restshape/postprocess/verification_parameters.h>

#include <string>
#include <vector>

namespace RestShape
{
  struct Parameters
  {
    MeshParameters         mesh;
    ForwardParameters      forward;
    OutputParameters       output;
    VerificationParameters verification;
    RefinementParameters   refinement;
    ContactParameters      contact;
    InverseParameters      inverse;
    /// The enabled scenarios: "Scenario", then the named ones as written.
    std::vector<ScenarioParameters> scenarios;
    /// Every parameter that names labels, as written (checked against the
    /// mesh's labels by the Simulator).
    std::vector<LabelList> label_lists;

    /// Every part's parameters, and those the registered material laws and
    /// load terms declare themselves (registered_parameters.h).
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Throws InputError (without file name; the caller adds it).
    /// @p scenario_names: the named scenarios declared (read_scene()).
    void
    parse_parameters(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &scenario_names = {});

    /**
     * Replace the label names in every label list of @p prm by their
     * labels (replace_label_names()), before parse_parameters(). Throws
     * InputError naming the parameter for an unknown name.
     */
    /// The slices the postprocessors read.
    PostprocessParameters
    postprocess_parameters() const
    {
      return {mesh, forward, inverse, refinement, verification, output};
    }

    static void
    replace_label_names(dealii::ParameterHandler &prm, const LabelNames &names);
  };
} // namespace RestShape

#endif
