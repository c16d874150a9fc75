// A posteriori error estimate of a displacement field, per cell and in
// total: Kelly's indicator (the jump of the gradient across faces) or the
// jump of the traction, which knows material interfaces and rigid labels.
#ifndef restshape_error_estimator_h
#define restshape_error_estimator_h

#include <deal.II/lac/vector.h>

#include <restshape/forward/forward_problem.h>
#include <restshape/postprocess/refinement_parameters.h>

namespace RestShape
{
  struct ErrorEstimate
  {
    /// eta_K per active cell (sqrt of h_K/24 times the squared jumps over
    /// the faces of K: of the normal derivative, Kelly et al. 1983, or of
    /// the traction divided by Young's modulus).
    dealii::Vector<float> indicators;
    /// sqrt(sum_K eta_K^2) / |grad u|_L2: an estimate of the relative H1
    /// error |grad(u - u_h)| / |grad u| (compare with h1_error_relative of
    /// an exact solution: doc/model.md).
    double relative = 0;
  };

  /**
   * The error indicator @p estimator of the field @p u (owned or ghosted,
   * in the DoF layout of @p problem), e.g. the displacement from the rest
   * shape. Boundary faces contribute nothing (traction-free and loaded faces
   * alike).
   *
   * kelly: deal.II's KellyErrorEstimator, the jump of grad u n across
   * every interior face. Where the exact gradient jumps (a material
   * interface, a rigid label) it counts the jump as error.
   *
   * traction_jump: the jump of the traction P(I + grad u) n of the
   * material law of each side, divided by the smaller Young's modulus of
   * the two, over the faces whose cells both deform; faces of cells whose
   * every DoF is fixed count as Dirichlet boundary (nothing). The exact
   * traction is continuous across material interfaces, so only the
   * discretisation error remains; a rigid motion gives none.
   */
  ErrorEstimate
  estimate_error(const ForwardProblem           &problem,
                 const VectorType               &u,
                 RefinementParameters::Estimator estimator);
} // namespace RestShape

#endif
