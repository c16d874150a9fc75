#include <restshape/loads/load_state.h>

namespace RestShape
{
  namespace
  {
    const LoadState::Columns no_columns;
  } // namespace

  const LoadState::Columns &
  LoadState::columns(const std::string &name) const
  {
    const auto it = by_name.find(name);
    return it == by_name.end() ? no_columns : it->second;
  }

  void
  LoadState::set(const std::string &name, const Columns &columns)
  {
    if (columns.empty())
      by_name.erase(name);
    else
      by_name[name] = columns;
  }

  void
  LoadState::add(const std::string         &name,
                 const std::vector<double> &parameters,
                 const double               weight)
  {
    Columns &columns = by_name[name];
    for (LoadColumn &c : columns)
      if (c.parameters == parameters)
        {
          c.weight += weight;
          return;
        }
    columns.push_back({parameters, weight});
  }

  void
  LoadState::scale(const std::string &name, const double factor)
  {
    const auto it = by_name.find(name);
    if (it == by_name.end())
      return;
    for (LoadColumn &c : it->second)
      c.weight *= factor;
  }

  bool
  LoadState::acts(const std::string &name) const
  {
    for (const LoadColumn &c : columns(name))
      if (c.weight != 0)
        return true;
    return false;
  }

  bool
  LoadState::empty() const
  {
    for (const auto &[name, columns] : by_name)
      if (acts(name))
        return false;
    return true;
  }

  double
  LoadState::weight(const std::string &name) const
  {
    double sum = 0;
    for (const LoadColumn &c : columns(name))
      sum += c.weight;
    return sum;
  }

  double
  LoadState::weighted(const std::string &name, const unsigned int i) const
  {
    double sum = 0;
    for (const LoadColumn &c : columns(name))
      sum += c.weight * c.parameters[i];
    return sum;
  }

  dealii::Tensor<1, 3>
  LoadState::weighted_vector(const std::string &name,
                             const unsigned int first) const
  {
    dealii::Tensor<1, 3> sum;
    for (const LoadColumn &c : columns(name))
      sum += c.weight * column_vector(c, first);
    return sum;
  }

  LoadState
  combine(const LoadState &a,
          const double     wa,
          const LoadState &b,
          const double     wb)
  {
    LoadState sum;
    for (const auto &[name, columns] : a.terms())
      for (const LoadColumn &c : columns)
        sum.add(name, c.parameters, wa * c.weight);
    for (const auto &[name, columns] : b.terms())
      for (const LoadColumn &c : columns)
        sum.add(name, c.parameters, wb * c.weight);
    LoadState kept;
    for (const auto &[name, columns] : sum.terms())
      for (const LoadColumn &c : columns)
        if (c.weight != 0)
          kept.add(name, c.parameters, c.weight);
    return kept;
  }
} // namespace RestShape
