#include <deal.II/base/mpi.h>

#include <restshape/fem/nodal_norms.h>

#include <algorithm>

namespace RestShape
{
  using namespace dealii;

  std::pair<double, double>
  nodal_norms(const Discretization &discretization, const VectorType &v)
  {
    const NodalNorms all = nodal_norms_above(discretization, v, -1.);
    return {all.mean, all.max};
  }

  NodalNorms
  nodal_norms_above(const Discretization &discretization,
                    const VectorType     &v,
                    const double          threshold)
  {
    double       sum = 0, max = 0;
    unsigned int n = 0;
    for (const Node &node : discretization.owned_nodes())
      {
        Tensor<1, 3> value;
        for (unsigned int c = 0; c < 3; ++c)
          value[c] = v[node.dofs[c]];
        if (value.norm() > threshold)
          {
            ++n;
            sum += value.norm();
          }
        max = std::max(max, value.norm());
      }
    NodalNorms result;
    result.n    = Utilities::MPI::sum(n, discretization.communicator());
    result.mean = Utilities::MPI::sum(sum, discretization.communicator()) /
                  std::max(1u, result.n);
    result.max = Utilities::MPI::max(max, discretization.communicator());
    return result;
  }
} // namespace RestShape
