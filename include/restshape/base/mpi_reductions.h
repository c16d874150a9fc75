// Reductions over the MPI ranks that the parts share.
#ifndef restshape_base_mpi_reductions_h
#define restshape_base_mpi_reductions_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <utility>
#include <vector>

namespace RestShape
{
  /// The largest of every rank's @p value, with the place @p where the rank
  /// found it (the first rank's on ties).
  inline std::pair<double, dealii::Point<3>>
  largest_with_place(const double            value,
                     const dealii::Point<3> &where,
                     const MPI_Comm          comm)
  {
    std::pair<double, dealii::Point<3>> result(value, where);
    const std::vector<double> mine = {value, where[0], where[1], where[2]};
    for (const auto &r : dealii::Utilities::MPI::all_gather(comm, mine))
      if (r[0] > result.first)
        result = {r[0], dealii::Point<3>(r[1], r[2], r[3])};
    return result;
  }
} // namespace RestShape

#endif
