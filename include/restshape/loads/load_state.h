// What loads the body at one point of a solve: by load term, its weighted
// columns.
#ifndef restshape_loads_load_state_h
#define restshape_loads_load_state_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <string>
#include <vector>

namespace RestShape
{
  /**
   * One column of a load term's load: the term's load at the parameters
   * @p parameters (an acceleration, a pressure, a fluid's acceleration and
   * level: what they are is the term's), times @p weight. A term's load is
   * the sum over its columns and linear in each weight.
   */
  struct LoadColumn
  {
    std::vector<double> parameters;
    double              weight = 1;
  };

  /**
   * The loads of a solve at one load step: the columns of every load term
   * that acts, by the term's name (load_registry.h; e.g. "Gravity",
   * "Surface pressure", "Surface traction"). All act on the mass of the
   * mesh (target) geometry.
   *
   * Every term is linear in the weights of its columns, so load stepping
   * blends two states (between()), a scenario's change is the difference
   * of two states (difference()), and any term can be scaled by name
   * (scale()) without knowing what it is.
   */
  class LoadState
  {
  public:
    using Columns = std::vector<LoadColumn>;

    /// The columns of the term @p name (none if it does not act).
    const Columns &
    columns(const std::string &name) const;
    /// Replace the columns of @p name (none: the term does not act).
    void
    set(const std::string &name, const Columns &columns);
    /// Add a column to @p name (merged with one of the same parameters).
    void
    add(const std::string         &name,
        const std::vector<double> &parameters,
        const double               weight = 1);
    /// Multiply the weights of @p name by @p factor.
    void
    scale(const std::string &name, const double factor);

    /// Whether @p name has a column of nonzero weight.
    bool
    acts(const std::string &name) const;
    /// Whether no term acts (every weight zero).
    bool
    empty() const;
    /// Sum of the weights of @p name's columns (a load without
    /// parameters: its weight).
    double
    weight(const std::string &name) const;
    /// Sum over the columns of @p name of weight * parameters[i].
    double
    weighted(const std::string &name, const unsigned int i = 0) const;
    /// The same for the vector of parameters[first], [first + 1],
    /// [first + 2] (e.g. an acceleration, m/s^2).
    dealii::Tensor<1, 3>
    weighted_vector(const std::string &name,
                    const unsigned int first = 0) const;

    /// Every term that has columns, by name.
    const std::map<std::string, Columns> &
    terms() const
    {
      return by_name;
    }

  private:
    std::map<std::string, Columns> by_name;
  };

  /// The parameters of a column that holds a vector (e.g. an acceleration).
  inline std::vector<double>
  vector_parameters(const dealii::Tensor<1, 3> &v)
  {
    return {v[0], v[1], v[2]};
  }
  /// The vector of parameters[first ... first + 2] of @p column.
  inline dealii::Tensor<1, 3>
  column_vector(const LoadColumn &column, const unsigned int first = 0)
  {
    return dealii::Tensor<1, 3>({column.parameters[first],
                                 column.parameters[first + 1],
                                 column.parameters[first + 2]});
  }

  /// @p a weighted by @p wa plus @p b weighted by @p wb: by term, columns
  /// of the same parameters merged, those of weight 0 dropped.
  LoadState
  combine(const LoadState &a,
          const double     wa,
          const LoadState &b,
          const double     wb);

  /// The load at fraction @p s of the way from @p start to @p end
  /// (load stepping: s = 0 gives start, s = 1 end).
  inline LoadState
  between(const LoadState &start, const LoadState &end, const double s)
  {
    return combine(start, 1 - s, end, s);
  }

  /// @p a - @p b: what changes from @p b to @p a.
  inline LoadState
  difference(const LoadState &a, const LoadState &b)
  {
    return combine(a, 1, b, -1);
  }
} // namespace RestShape

#endif
