// Helpers for the unit tests: a scene built from a .prm text, and checks
// that print what they compare and fail the test with a non-zero exit.
#ifndef restshape_test_utilities_h
#define restshape_test_utilities_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <restshape/app/parameters.h>
#include <restshape/contact/contact.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/material/material_table.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/labelled_mesh.h>
#include <restshape/mesh/mesh_transforms.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace RestShape::Test
{
  inline int failures = 0;

  /// Report "name: value (limit)" and count a failure if value > limit.
  inline void
  check_below(const std::string &name, const double value, const double limit)
  {
    const bool ok = std::isfinite(value) && value <= limit;
    std::cout << (ok ? "ok   " : "FAIL ") << name << ": " << value << " (limit "
              << limit << ")" << std::endl;
    failures += !ok;
  }

  /// The tangent of @p law at @p F against central differences of its
  /// stress: max |difference - tangent| / max |difference| over entries.
  inline double
  tangent_error(const MaterialLaw &law,
                const Tensor2     &F,
                const TangentType  type = TangentType::consistent)
  {
    Tensor2 P;
    Tensor4 A;
    law.evaluate(F, P, &A, type);
    double error = 0, scale = 0;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int L = 0; L < 3; ++L)
        {
          constexpr double h  = 1e-6;
          Tensor2          Fp = F, Fm = F, Pp, Pm;
          Fp[k][L] += h;
          Fm[k][L] -= h;
          law.evaluate(Fp, Pp, nullptr, type);
          law.evaluate(Fm, Pm, nullptr, type);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int J = 0; J < 3; ++J)
              {
                const double fd = (Pp[i][J] - Pm[i][J]) / (2 * h);
                error           = std::max(error, std::abs(fd - A[i][J][k][L]));
                scale           = std::max(scale, std::abs(fd));
              }
        }
    return error / scale;
  }

  inline void
  check_between(const std::string &name,
                const double       value,
                const double       low,
                const double       high)
  {
    const bool ok = std::isfinite(value) && value >= low && value <= high;
    std::cout << (ok ? "ok   " : "FAIL ") << name << ": " << value
              << " (expected in [" << low << ", " << high << "])" << std::endl;
    failures += !ok;
  }

  /// The rotation by |axis_angle| radians about axis_angle (Rodrigues).
  inline Tensor2
  rotation(const dealii::Tensor<1, 3> &axis_angle)
  {
    const double  angle = axis_angle.norm();
    const Tensor2 K     = skew_matrix(axis_angle / angle);
    return Tensor2(dealii::unit_symmetric_tensor<3>()) + std::sin(angle) * K +
           (1 - std::cos(angle)) * K * K;
  }

  /// The owned vector with the value @p field(X) at every node X of @p f.
  template <typename Field>
  inline VectorType
  nodal_field(const ForwardProblem &f, const Field &field)
  {
    VectorType v = f.discretization().zero_vector();
    for (const Node &node : f.discretization().owned_nodes())
      {
        const dealii::Tensor<1, 3> value = field(node.position);
        for (unsigned int c = 0; c < 3; ++c)
          v[node.dofs[c]] = value[c];
      }
    v.compress(dealii::VectorOperation::insert);
    return v;
  }

  inline int
  exit_code()
  {
    std::cout << (failures == 0 ? "all checks passed" :
                                  "checks FAILED: " + std::to_string(failures))
              << std::endl;
    return failures == 0 ? 0 : 1;
  }

  /// The parameters of .prm text (defaults for what it does not set).
  inline Parameters
  parsed_parameters(const std::string &prm_text)
  {
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    prm.parse_input_from_string(prm_text);
    Parameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }

  /// A forward problem set up from .prm text (file paths relative to the
  /// source directory, which tests run in).
  struct Scene
  {
    Scene(const std::string &prm_text)
      : parameters(parsed_parameters(prm_text))
      , pcout(std::cout, false)
      , timer(MPI_COMM_WORLD,
              pcout,
              dealii::TimerOutput::never,
              dealii::TimerOutput::wall_times)
    {
      mesh = std::make_unique<LabelledMesh>(parameters.mesh, MPI_COMM_WORLD);
      materials = std::make_unique<MaterialTable>(parameters.forward.materials,
                                                  mesh->labels());
      forward   = std::make_unique<ForwardProblem>(
        parameters.forward, *mesh, *materials, timer, pcout);
      forward->setup();
    }

    /// Contact with the scene's obstacle (subsection Contact), attached to
    /// the forward problem and set up.
    ContactProblem &
    add_contact()
    {
      contact = std::make_unique<ContactProblem>(
        parameters.contact,
        forward->discretization(),
        *forward,
        parameters.forward.solver.newton_tolerance,
        materials->max_youngs_modulus(),
        timer);
      forward->set_contact(contact.get());
      forward->setup();
      contact->setup();
      return *contact;
    }

    Parameters                      parameters;
    dealii::ConditionalOStream      pcout;
    dealii::TimerOutput             timer;
    std::unique_ptr<LabelledMesh>   mesh;
    std::unique_ptr<MaterialTable>  materials;
    std::unique_ptr<ForwardProblem> forward;
    std::unique_ptr<ContactProblem> contact;
  };
} // namespace RestShape::Test

#endif
