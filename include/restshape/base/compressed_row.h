// Where given columns sit in one row of a compressed (CRS) matrix: the
// search that lets TangentScatter and the averaged nodal pressure add
// into a Trilinos matrix's value array directly, instead of through
// Epetra's map lookup and search per entry.
#ifndef restshape_base_compressed_row_h
#define restshape_base_compressed_row_h

#include <algorithm>
#include <utility>

namespace RestShape
{
  /// For the @p n (local column, j) pairs of @p columns, sorted by column,
  /// place[j] = the column's offset in the row's sorted column indices
  /// [@p begin, @p end). One walk along the row: the next column is often
  /// the next entry (a node's components), else a binary search on. False
  /// where a column is not in the row (not in the sparsity, or the row's
  /// columns not sorted); @p place is then incomplete.
  template <typename Place>
  bool
  find_in_row(const std::pair<int, unsigned int> *columns,
              const unsigned int                  n,
              const int                          *begin,
              const int                          *end,
              Place                              *place)
  {
    const int *k = begin;
    for (unsigned int c = 0; c < n; ++c)
      {
        const auto &[col, j] = columns[c];
        if (k == end || *k != col)
          k = std::lower_bound(k, end, col);
        if (k == end || *k != col)
          return false;
        place[j] = static_cast<Place>(k - begin);
        ++k;
      }
    return true;
  }
} // namespace RestShape

#endif
