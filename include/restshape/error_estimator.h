// A posteriori error estimate of a displacement field: Kelly's indicator
// (the jump of the gradient across faces), per cell and in total.
#ifndef restshape_error_estimator_h
#define restshape_error_estimator_h

#include <deal.II/lac/vector.h>

#include <restshape/forward_problem.h>

namespace RestShape
{
  struct ErrorEstimate
  {
    /// eta_K per active cell (sqrt of h_K/24 times the squared jumps of the
    /// normal derivative over the faces of K; Kelly et al. 1983).
    dealii::Vector<float> indicators;
    /// sqrt(sum_K eta_K^2) / |grad u|_L2: an estimate of the relative H1
    /// error |grad(u - u_h)| / |grad u| (compare with h1_error_relative of
    /// an exact solution: doc/model.md).
    double relative = 0;
  };

  /**
   * Kelly's estimator on the field @p u (owned or ghosted, in the DoF layout
   * of @p problem), e.g. the displacement from the rest shape. Boundary
   * faces contribute nothing (traction-free and loaded faces alike).
   */
  ErrorEstimate
  estimate_error(const ForwardProblem &problem, const VectorType &u);
} // namespace RestShape

#endif
