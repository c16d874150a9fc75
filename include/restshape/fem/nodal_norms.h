// Norms of a displacement-like field over the nodes of a discretisation.
#ifndef restshape_fem_nodal_norms_h
#define restshape_fem_nodal_norms_h

#include <restshape/base/linear_algebra_types.h>
#include <restshape/fem/discretization.h>

#include <utility>

namespace RestShape
{
  /// Over all ranks: the nodes where |v| > a threshold (m), the mean of
  /// |v| over them and the largest |v|.
  struct NodalNorms
  {
    unsigned int n    = 0;
    double       mean = 0, max = 0;
  };

  /// Mean and max over all nodes of |v| at the node (v owned or ghosted,
  /// a displacement-like field; m).
  std::pair<double, double>
  nodal_norms(const Discretization &discretization, const VectorType &v);

  /// NodalNorms of @p v (owned or ghosted) above @p threshold.
  NodalNorms
  nodal_norms_above(const Discretization &discretization,
                    const VectorType     &v,
                    const double          threshold);
} // namespace RestShape

#endif
