// Study mode: the runs' nodal fields against the reference run's.
#include <restshape/app/study_compare.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// Mesh positions are matched to this fraction of the length unit.
    constexpr double position_resolution = 1e-6;

    using Key = std::array<long long, 3>;
    /// Displacement and rest shift (mm) of a node.
    using Values = std::array<double, 6>;

    /// nodes.csv: position (mesh unit) -> displacement and rest shift.
    std::map<Key, Values>
    read_nodes(const std::string &file)
    {
      std::map<Key, Values> nodes;
      std::ifstream         in(file);
      std::string           line;
      std::getline(in, line); // header
      while (std::getline(in, line))
        {
          std::replace(line.begin(), line.end(), ',', ' ');
          std::istringstream    row(line);
          std::array<double, 9> v;
          for (double &x : v)
            row >> x;
          if (!row)
            continue;
          Key    key;
          Values values;
          for (unsigned int c = 0; c < 3; ++c)
            key[c] = std::llround(v[c] / position_resolution);
          std::copy(v.begin() + 3, v.end(), values.begin());
          nodes[key] = values;
        }
      return nodes;
    }

    /// Largest |(x, y, z)| of the three values from @p first on.
    double
    norm(const Values &v, const unsigned int first)
    {
      return std::hypot(v[first], v[first + 1], v[first + 2]);
    }
  } // namespace

  std::vector<FieldDifference>
  differences_to_reference(const std::vector<std::string> &files,
                           const std::size_t               reference)
  {
    std::vector<FieldDifference> result(files.size());
    if (reference >= files.size() || files[reference].empty())
      return result;
    const std::map<Key, Values> ref      = read_nodes(files[reference]);
    double                      scale[2] = {0, 0};
    for (const auto &[key, v] : ref)
      for (unsigned int f = 0; f < 2; ++f)
        scale[f] = std::max(scale[f], norm(v, 3 * f));
    for (std::size_t r = 0; r < files.size(); ++r)
      {
        if (r == reference || files[r].empty())
          continue;
        double largest[2] = {0, 0};
        for (const auto &[key, v] : read_nodes(files[r]))
          {
            const auto match = ref.find(key);
            if (match == ref.end())
              continue;
            ++result[r].shared_nodes;
            Values d;
            for (unsigned int i = 0; i < 6; ++i)
              d[i] = v[i] - match->second[i];
            for (unsigned int f = 0; f < 2; ++f)
              largest[f] = std::max(largest[f], norm(d, 3 * f));
          }
        if (result[r].shared_nodes == 0)
          continue;
        if (scale[0] > 0)
          result[r].displacement = largest[0] / scale[0];
        if (scale[1] > 0)
          result[r].rest_shape = largest[1] / scale[1];
      }
    return result;
  }
} // namespace RestShape
