#include <restshape/base/input_error.h>
#include <restshape/mesher/components.h>

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <numeric>
#include <ostream>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// Union-find over 0..n-1.
    class Partition
    {
    public:
      explicit Partition(const std::size_t n)
        : parent(n)
      {
        std::iota(parent.begin(), parent.end(), std::size_t(0));
      }
      std::size_t
      find(std::size_t i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }
      void
      join(const std::size_t a, const std::size_t b)
      {
        parent[find(a)] = find(b);
      }

    private:
      std::vector<std::size_t> parent;
    };

    /// The component of voxel @p start (6-connected, one label) by a
    /// breadth-first search; marks it in @p seen; whether it reaches the
    /// border.
    std::size_t
    flood(const LabelledImage         &image,
          const std::size_t            start,
          std::vector<bool>           &seen,
          bool                        &at_border,
          std::array<unsigned int, 3> *central = nullptr)
    {
      const auto              &n     = image.size;
      const ImageLabel         label = image.labels[start];
      std::vector<std::size_t> queue = {start};
      seen[start]                    = true;
      at_border                      = false;
      for (std::size_t head = 0; head < queue.size(); ++head)
        {
          const std::size_t  v = queue[head];
          const unsigned int i = v % n[0], j = (v / n[0]) % n[1],
                             k = v / (std::size_t(n[0]) * n[1]);
          const std::array<unsigned int, 3> ijk = {{i, j, k}};
          for (unsigned int d = 0; d < 3; ++d)
            for (const int step : {-1, 1})
              {
                if ((step < 0 && ijk[d] == 0) ||
                    (step > 0 && ijk[d] + 1 == n[d]))
                  {
                    at_border = true;
                    continue;
                  }
                std::array<unsigned int, 3> m = ijk;
                m[d] += step;
                const std::size_t w = image.index(m[0], m[1], m[2]);
                if (!seen[w] && image.labels[w] == label)
                  {
                    seen[w] = true;
                    queue.push_back(w);
                  }
              }
        }
      if (central != nullptr)
        {
          const auto ijk = [&](const std::size_t v) {
            return std::array<double, 3>{
              {double(v % n[0]),
               double((v / n[0]) % n[1]),
               double(v / (std::size_t(n[0]) * n[1]))}};
          };
          std::array<double, 3> mean = {{0, 0, 0}};
          for (const std::size_t v : queue)
            for (unsigned int d = 0; d < 3; ++d)
              mean[d] += ijk(v)[d] / queue.size();
          double best = std::numeric_limits<double>::max();
          for (const std::size_t v : queue)
            {
              const auto   c  = ijk(v);
              const double d2 = (c[0] - mean[0]) * (c[0] - mean[0]) +
                                (c[1] - mean[1]) * (c[1] - mean[1]) +
                                (c[2] - mean[2]) * (c[2] - mean[2]);
              if (d2 < best)
                {
                  best     = d2;
                  *central = {{unsigned(c[0]), unsigned(c[1]), unsigned(c[2])}};
                }
            }
        }
      return queue.size();
    }

    using Face = std::array<unsigned int, 3>;

    Face
    sorted_face(const dealii::CellData<3> &cell, const unsigned int opposite)
    {
      Face f;
      for (unsigned int v = 0, m = 0; v < 4; ++v)
        if (v != opposite)
          f[m++] = cell.vertices[v];
      std::sort(f.begin(), f.end());
      return f;
    }
  } // namespace

  ImageComponents
  image_components(const LabelledImage &image)
  {
    ImageComponents   c;
    std::vector<bool> seen(image.labels.size(), false);
    for (std::size_t v = 0; v < image.labels.size(); ++v)
      if (!seen[v])
        {
          bool                        at_border = false;
          std::array<unsigned int, 3> central;
          const std::size_t           n =
            flood(image,
                  v,
                  seen,
                  at_border,
                  image.labels[v] == 0 ? &central : nullptr);
          if (image.labels[v] != 0)
            c.voxels[image.labels[v]].push_back(n);
          else if (!at_border)
            {
              c.cavities.push_back(n);
              c.cavity_voxels.push_back(central);
            }
        }
    for (auto &[label, sizes] : c.voxels)
      std::sort(sizes.rbegin(), sizes.rend());
    // Cavities largest first, their voxels with them.
    std::vector<std::size_t> order(c.cavities.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](const auto a, const auto b) {
      return c.cavities[a] > c.cavities[b];
    });
    ImageComponents sorted = c;
    for (std::size_t i = 0; i < order.size(); ++i)
      {
        sorted.cavities[i]      = c.cavities[order[i]];
        sorted.cavity_voxels[i] = c.cavity_voxels[order[i]];
      }
    return sorted;
  }

  unsigned int
  MeshComponents::n_cavities() const
  {
    return std::count_if(surfaces.begin(), surfaces.end(), [](const double v) {
      return v < 0;
    });
  }

  MeshComponents
  mesh_components(const MeshDescription &mesh)
  {
    const auto &cells = mesh.cells;
    // Each face and the cells (with the vertex opposite it) that have it.
    std::map<Face, std::vector<std::pair<unsigned int, unsigned int>>> faces;
    for (unsigned int c = 0; c < cells.size(); ++c)
      for (unsigned int v = 0; v < 4; ++v)
        faces[sorted_face(cells[c], v)].emplace_back(c, v);

    Partition           pieces(cells.size());
    std::vector<Face>   boundary, result_faces;
    std::vector<double> boundary_moment; // 1/3 x.n dA of each boundary face
    for (const auto &[face, at] : faces)
      {
        if (at.size() == 2 &&
            cells[at[0].first].material_id == cells[at[1].first].material_id)
          pieces.join(at[0].first, at[1].first);
        if (at.size() != 1)
          continue;
        const auto             &cell = cells[at[0].first];
        const auto             &p    = mesh.vertices;
        const dealii::Point<3> &a = p[face[0]], &b = p[face[1]],
                               &c        = p[face[2]];
        const dealii::Point<3> &opposite = p[cell.vertices[at[0].second]];
        dealii::Tensor<1, 3>    n = dealii::cross_product_3d(b - a, c - a) / 2;
        Face                    oriented = face;
        if (n * (a - opposite) < 0)
          {
            n = -n; // outward
            std::swap(oriented[1], oriented[2]);
          }
        boundary.push_back(face);
        result_faces.push_back(oriented);
        boundary_moment.push_back((a + b + c) / 3. * n / 3.);
      }

    MeshComponents                                         result;
    std::map<std::size_t, std::pair<unsigned int, double>> piece_volume;
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const auto  &p = mesh.vertices;
        const auto  &v = cells[c].vertices;
        const double volume =
          std::abs(
            (p[v[1]] - p[v[0]]) *
            dealii::cross_product_3d(p[v[2]] - p[v[0]], p[v[3]] - p[v[0]])) /
          6;
        auto &entry = piece_volume[pieces.find(c)];
        entry.first = cells[c].material_id;
        entry.second += volume;
      }
    for (const auto &[root, entry] : piece_volume)
      result.volumes[entry.first].push_back(entry.second);
    for (auto &[label, volumes] : result.volumes)
      std::sort(volumes.rbegin(), volumes.rend());

    // Boundary faces joined across their edges.
    Partition surfaces(boundary.size());
    std::map<std::array<unsigned int, 2>, unsigned int> edge_owner;
    for (unsigned int f = 0; f < boundary.size(); ++f)
      for (unsigned int e = 0; e < 3; ++e)
        {
          const std::array<unsigned int, 2> edge = {
            {boundary[f][e], boundary[f][(e + 1) % 3]}};
          const std::array<unsigned int, 2> key = {
            {std::min(edge[0], edge[1]), std::max(edge[0], edge[1])}};
          const auto [it, inserted] = edge_owner.emplace(key, f);
          if (!inserted)
            surfaces.join(f, it->second);
        }
    std::map<std::size_t, double> enclosed;
    for (unsigned int f = 0; f < boundary.size(); ++f)
      enclosed[surfaces.find(f)] += boundary_moment[f];
    // Surfaces by decreasing enclosed volume: the outer ones first.
    std::vector<std::pair<double, std::size_t>> order;
    for (const auto &[root, volume] : enclosed)
      order.emplace_back(volume, root);
    std::sort(order.rbegin(), order.rend());
    std::map<std::size_t, unsigned int> index;
    for (const auto &[volume, root] : order)
      {
        index[root] = result.surfaces.size();
        result.surfaces.push_back(volume);
      }
    result.boundary_faces = result_faces;
    for (unsigned int f = 0; f < boundary.size(); ++f)
      result.face_surface.push_back(index.at(surfaces.find(f)));
    return result;
  }

  namespace
  {
    std::string
    volumes_text(const std::vector<double> &volumes, const double unit)
    {
      std::ostringstream text;
      text.precision(3);
      text << volumes.size()
           << (volumes.size() == 1 ? " component" : " components");
      if (!volumes.empty())
        {
          text << " (";
          constexpr std::size_t listed = 4;
          for (std::size_t i = 0; i < std::min(listed, volumes.size()); ++i)
            text << (i > 0 ? ", " : "") << volumes[i] * unit;
          text << (volumes.size() > listed ? ", ..." : "") << " cm^3)";
        }
      return text.str();
    }

    std::vector<double>
    in_mm3(const std::vector<std::size_t> &voxels, const double voxel_volume)
    {
      std::vector<double> v;
      for (const std::size_t n : voxels)
        v.push_back(n * voxel_volume);
      return v;
    }

    /// How many of the image's components larger than @p least (both
    /// lists largest first) the mesh lacks: the k-th largest in the mesh
    /// must hold at least @p fraction of the k-th largest in the image.
    std::size_t
    n_missing(const std::vector<double> &image,
              const std::vector<double> &mesh,
              const double               least,
              const double               fraction)
    {
      std::size_t missing = 0;
      for (std::size_t k = 0; k < image.size() && image[k] > least; ++k)
        missing += !(k < mesh.size() && mesh[k] >= fraction * image[k]);
      return missing;
    }

    std::size_t
    count_above(const std::vector<double> &volumes, const double least)
    {
      return std::count_if(volumes.begin(), volumes.end(), [&](const double v) {
        return v > least;
      });
    }
  } // namespace

  std::string
  compare_components(const ImageComponents &image,
                     const MeshComponents  &mesh,
                     const double           voxel_volume,
                     const double           least_volume,
                     const std::function<std::string(unsigned int)> &name,
                     std::ostream                                   &report)
  {
    constexpr double cm3_per_mm3 = 1e-3;
    // A mesh piece counts for an image component if it holds a fair part
    // of its volume (the k-th largest of each, in order).
    constexpr double kept_fraction = 0.25;
    std::string      lost;
    const auto       add = [&](const std::string &what) {
      lost += (lost.empty() ? "" : "; ") + what;
    };
    for (const auto &[label, voxels] : image.voxels)
      {
        const std::vector<double> in_image = in_mm3(voxels, voxel_volume);
        const auto                found    = mesh.volumes.find(label);
        const std::vector<double> in_mesh =
          found == mesh.volumes.end() ? std::vector<double>() : found->second;
        report << "  " << name(label) << ": image "
               << volumes_text(in_image, cm3_per_mm3) << ", mesh "
               << volumes_text(in_mesh, cm3_per_mm3) << '\n';
        const std::size_t wanted = count_above(in_image, least_volume);
        const std::size_t missing =
          n_missing(in_image, in_mesh, least_volume, kept_fraction);
        if (missing > 0)
          add(name(label) + ": " + std::to_string(missing) + " of " +
              std::to_string(wanted) + " components larger than " +
              number_text(least_volume * cm3_per_mm3) +
              " cm^3 missing from the mesh (or joined to another)");
      }
    const std::vector<double> cavities = in_mm3(image.cavities, voxel_volume);
    std::vector<double>       walls;
    for (const double v : mesh.surfaces)
      if (v < 0)
        walls.push_back(-v);
    std::sort(walls.rbegin(), walls.rend());
    report << "  boundary surfaces: " << mesh.surfaces.size() << " ("
           << mesh.surfaces.size() - walls.size() << " outer, " << walls.size()
           << " cavity walls); cavities: image "
           << volumes_text(cavities, cm3_per_mm3) << ", mesh "
           << volumes_text(walls, cm3_per_mm3) << '\n';
    const std::size_t wanted = count_above(cavities, least_volume);
    const std::size_t missing =
      n_missing(cavities, walls, least_volume, kept_fraction);
    if (missing > 0)
      add(
        std::to_string(missing) + " of " + std::to_string(wanted) +
        " cavities (label 0 enclosed by the body) larger than " +
        number_text(least_volume * cm3_per_mm3) +
        " cm^3 missing from the mesh (filled with tissue, or joined to another)");
    return lost;
  }
} // namespace RestShape
