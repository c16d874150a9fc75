#include <restshape/mesher/image_morphology.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>

namespace RestShape
{
  namespace
  {
    /// Squared Euclidean distance transform along one line (Felzenszwalb and
    /// Huttenlocher 2012), samples @p h apart.
    void
    distance_transform_1d(std::vector<double>       &f,
                          const double               h,
                          std::vector<unsigned int> &v,
                          std::vector<double>       &z,
                          std::vector<double>       &d)
    {
      const unsigned int n  = f.size();
      const double       h2 = h * h;
      auto intersection     = [&](const unsigned int q, const unsigned int p) {
        return ((f[q] + h2 * q * q) - (f[p] + h2 * p * p)) /
               (2 * h2 * (double(q) - double(p)));
      };
      unsigned int k = 0;
      v[0]           = 0;
      z[0]           = -std::numeric_limits<double>::infinity();
      z[1]           = std::numeric_limits<double>::infinity();
      for (unsigned int q = 1; q < n; ++q)
        {
          double s = intersection(q, v[k]);
          while (s <= z[k])
            {
              --k;
              s = intersection(q, v[k]);
            }
          ++k;
          v[k]     = q;
          z[k]     = s;
          z[k + 1] = std::numeric_limits<double>::infinity();
        }
      k = 0;
      for (unsigned int q = 0; q < n; ++q)
        {
          while (z[k + 1] < q)
            ++k;
          const double dq = double(q) - double(v[k]);
          d[q]            = h2 * dq * dq + f[v[k]];
        }
      f = d;
    }
  } // namespace

  std::vector<double>
  distance_to(const std::vector<bool> &mask, const VoxelGrid &grid)
  {
    const auto         &n = grid.n;
    std::vector<double> dist(mask.size());
    for (std::size_t v = 0; v < mask.size(); ++v)
      dist[v] = mask[v] ? 0. : 1e20;
    const unsigned int        n_max = *std::max_element(n.begin(), n.end());
    std::vector<double>       line, z(n_max + 1), d(n_max);
    std::vector<unsigned int> v(n_max);
    // Separable: the 1d transform axis after axis.
    for (unsigned int axis = 0; axis < 3; ++axis)
      {
        const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (unsigned int ib = 0; ib < n[b]; ++ib)
          for (unsigned int ia = 0; ia < n[a]; ++ia)
            {
              std::array<unsigned int, 3> ijk;
              ijk[a] = ia;
              ijk[b] = ib;
              line.resize(n[axis]);
              d.resize(n[axis]);
              for (ijk[axis] = 0; ijk[axis] < n[axis]; ++ijk[axis])
                line[ijk[axis]] = dist[grid.at(ijk[0], ijk[1], ijk[2])];
              distance_transform_1d(line, grid.h[axis], v, z, d);
              for (ijk[axis] = 0; ijk[axis] < n[axis]; ++ijk[axis])
                dist[grid.at(ijk[0], ijk[1], ijk[2])] = line[ijk[axis]];
            }
      }
    for (double &value : dist)
      value = std::sqrt(value);
    return dist;
  }

  void
  close_with_ball(std::vector<bool> &mask,
                  const VoxelGrid   &grid,
                  const double       radius)
  {
    if (radius <= 0)
      return;
    const std::vector<double> to_mask = distance_to(mask, grid);
    std::vector<bool>         outside(mask.size());
    for (std::size_t v = 0; v < mask.size(); ++v)
      outside[v] = to_mask[v] > radius;
    const std::vector<double> to_outside = distance_to(outside, grid);
    for (std::size_t v = 0; v < mask.size(); ++v)
      mask[v] = mask[v] || to_outside[v] > radius;
  }

  ClosedVoxels
  close_labelled_image(LabelledImage &image, const double radius)
  {
    ClosedVoxels closed;
    if (radius <= 0)
      return closed;
    const auto   h     = image.spacing();
    const double h_min = *std::min_element(h.begin(), h.end());
    // Pad so that the erosion sees background beyond the image's border.
    const unsigned int pad = std::ceil(radius / h_min) + 1;
    VoxelGrid          grid;
    grid.h = h;
    for (unsigned int d = 0; d < 3; ++d)
      grid.n[d] = image.size[d] + 2 * pad;
    std::vector<bool> region(grid.size(), false);
    for (unsigned int k = 0; k < image.size[2]; ++k)
      for (unsigned int j = 0; j < image.size[1]; ++j)
        for (unsigned int i = 0; i < image.size[0]; ++i)
          region[grid.at(i + pad, j + pad, k + pad)] =
            image.labels[image.index(i, j, k)] != 0;
    close_with_ball(region, grid, radius);

    // The added voxels inside the image, labelled layer by layer: in every
    // pass each one with labelled neighbours takes their most common label
    // (the labels of the previous pass only, so the order does not matter).
    std::vector<std::size_t> unlabelled;
    for (unsigned int k = 0; k < image.size[2]; ++k)
      for (unsigned int j = 0; j < image.size[1]; ++j)
        for (unsigned int i = 0; i < image.size[0]; ++i)
          if (region[grid.at(i + pad, j + pad, k + pad)] &&
              image.labels[image.index(i, j, k)] == 0)
            unlabelled.push_back(image.index(i, j, k));
    const auto &s = image.size;
    while (!unlabelled.empty())
      {
        std::vector<std::pair<std::size_t, ImageLabel>> assigned;
        std::vector<std::size_t>                        remaining;
        for (const std::size_t index : unlabelled)
          {
            const unsigned int i = index % s[0], j = (index / s[0]) % s[1],
                               k = index / (std::size_t(s[0]) * s[1]);
            std::map<ImageLabel, unsigned int> count;
            for (int dk = -1; dk <= 1; ++dk)
              for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di)
                  {
                    const int ii = int(i) + di, jj = int(j) + dj,
                              kk = int(k) + dk;
                    if (ii < 0 || jj < 0 || kk < 0 || ii >= int(s[0]) ||
                        jj >= int(s[1]) || kk >= int(s[2]))
                      continue;
                    const ImageLabel label =
                      image.labels[image.index(ii, jj, kk)];
                    if (label != 0)
                      ++count[label];
                  }
            if (count.empty())
              remaining.push_back(index);
            else
              assigned.emplace_back(index,
                                    std::max_element(count.begin(),
                                                     count.end(),
                                                     [](const auto &a,
                                                        const auto &b) {
                                                       return a.second <
                                                              b.second;
                                                     })
                                      ->first);
          }
        // Voxels joined to the region only through the padding stay
        // background.
        if (assigned.empty())
          break;
        for (const auto &[index, label] : assigned)
          image.labels[index] = label;
        closed.n_added += assigned.size();
        unlabelled = std::move(remaining);
      }
    closed.volume_mm3 = closed.n_added * h[0] * h[1] * h[2];
    return closed;
  }
  std::pair<std::vector<int>, std::vector<std::size_t>>
  face_connected_components(const LabelledImage     &image,
                            const std::vector<bool> &in)
  {
    std::vector<int>         component(in.size(), -1);
    std::vector<std::size_t> sizes;
    std::deque<std::size_t>  queue;
    for (std::size_t seed = 0; seed < in.size(); ++seed)
      if (in[seed] && component[seed] < 0)
        {
          const int c     = sizes.size();
          component[seed] = c;
          sizes.push_back(0);
          queue.push_back(seed);
          while (!queue.empty())
            {
              const std::size_t v = queue.front();
              queue.pop_front();
              ++sizes[c];
              for_neighbours(image, v, [&](const std::size_t w) {
                if (in[w] && component[w] < 0)
                  {
                    component[w] = c;
                    queue.push_back(w);
                  }
              });
            }
        }
    return {component, sizes};
  }

} // namespace RestShape
