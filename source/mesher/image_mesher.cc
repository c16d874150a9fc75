#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/make_mesh_3.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/base/machine_memory.h>
#include <restshape/mesh/mesh_description.h>
#include <restshape/mesher/image_mesher.h>
#include <restshape/mesher/image_morphology.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace RestShape
{
  namespace
  {
    using Kernel     = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Domain     = CGAL::Labeled_mesh_domain_3<Kernel>;
    using Tr         = CGAL::Mesh_triangulation_3<Domain>::type;
    using C3t3       = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
    using Criteria   = CGAL::Mesh_criteria_3<Tr>;
    using Point      = Kernel::Point_3;
    namespace params = CGAL::parameters;

    /// CGAL meshes in "scaled index space" (i h0, j h1, k h2); this maps such
    /// a point to the image's world coordinates (mm).
    struct ToWorld
    {
      explicit ToWorld(const LabelledImage &image)
        : image(image)
        , h(image.spacing())
      {}
      dealii::Point<3>
      operator()(const double x, const double y, const double z) const
      {
        return image.position(x / h[0], y / h[1], z / h[2]);
      }
      bool
      mirrors() const
      {
        return dealii::determinant(image.index_to_mm) < 0;
      }
      const LabelledImage  &image;
      std::array<double, 3> h;
    };

    /// The labels as a CGAL image in the smallest unsigned word that holds
    /// them (an atlas with labels up to 255 takes a byte per voxel).
    _image *
    cgal_labels(const LabelledImage &image, const std::array<double, 3> &h)
    {
      _image *raw = ::_createImage(image.size[0],
                                   image.size[1],
                                   image.size[2],
                                   1,
                                   h[0],
                                   h[1],
                                   h[2],
                                   image.label_bytes(),
                                   WK_FIXED,
                                   SGN_UNSIGNED);
      image.store_labels(raw->data);
      return raw;
    }

    /// Mesh_3 draws random numbers: a fixed seed makes the mesh reproducible.
    void
    seed_cgal(const unsigned int seed)
    {
      CGAL::get_default_random() = CGAL::Random(seed);
    }
  } // namespace

  namespace
  {
    /// Mesh_3 on the labels as CGAL has them; vertices mapped by @p to_world.
    MeshDescription
    mesh_cgal_image(const CGAL::Image_3    &cgal_image,
                    const ToWorld          &to_world,
                    const ImageMeshOptions &options)
    {
      const Domain domain = Domain::create_labeled_image_mesh_domain(
        cgal_image, params::relative_error_bound = 1e-6);
      const Criteria criteria(params::facet_angle    = options.facet_angle,
                              params::facet_size     = options.facet_size,
                              params::facet_distance = options.facet_distance,
                              params::cell_radius_edge_ratio =
                                options.radius_edge,
                              params::cell_size = options.cell_size);
      seed_cgal(options.seed);
      const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(
        domain,
        criteria,
        params::perturb(params::sliver_bound = options.sliver_bound,
                        params::time_limit   = 0),
        params::exude(params::sliver_bound = options.sliver_bound,
                      params::time_limit   = 0));

      MeshDescription                           mesh;
      std::map<Tr::Vertex_handle, unsigned int> index;
      const bool                                mirrors = to_world.mirrors();
      for (auto c = c3t3.cells_in_complex_begin();
           c != c3t3.cells_in_complex_end();
           ++c)
        {
          dealii::CellData<3> cell(4);
          for (unsigned int v = 0; v < 4; ++v)
            {
              const auto vh       = c->vertex(v);
              const auto inserted = index.emplace(vh, mesh.vertices.size());
              if (inserted.second)
                {
                  const auto p = vh->point();
                  mesh.vertices.push_back(to_world(CGAL::to_double(p.x()),
                                                   CGAL::to_double(p.y()),
                                                   CGAL::to_double(p.z())));
                }
              cell.vertices[v] = inserted.first->second;
            }
          if (mirrors)
            std::swap(cell.vertices[0], cell.vertices[1]);
          cell.material_id = c3t3.subdomain_index(c);
          mesh.cells.push_back(cell);
        }
      return mesh;
    }
  } // namespace

  MeshDescription
  mesh_labelled_image(const LabelledImage    &image,
                      const ImageMeshOptions &options)
  {
    const ToWorld       to_world(image);
    const CGAL::Image_3 cgal_image(cgal_labels(image, to_world.h));
    return mesh_cgal_image(cgal_image, to_world, options);
  }

  MeshDescription
  mesh_labelled_image(LabelledImage &&image, const ImageMeshOptions &options)
  {
    const ToWorld       to_world(image);
    const CGAL::Image_3 cgal_image(cgal_labels(image, to_world.h));
    std::vector<ImageLabel>().swap(image.labels);
    return mesh_cgal_image(cgal_image, to_world, options);
  }

  MeshQuality
  mesh_quality(const MeshDescription &tets)
  {
    using dealii::Tensor;
    MeshQuality q;
    double      sum_ratio = 0;
    for (const auto &cell : tets.cells)
      {
        std::array<dealii::Point<3>, 4> p;
        for (unsigned int v = 0; v < 4; ++v)
          p[v] = tets.vertices[cell.vertices[v]];
        const Tensor<1, 3> a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
        const double       six_volume = a * dealii::cross_product_3d(b, c);
        q.min_volume =
          (q.total_volume == 0 ? six_volume / 6 :
                                 std::min(q.min_volume, six_volume / 6));
        q.total_volume += six_volume / 6;
        q.volume_per_label[cell.material_id] += six_volume / 6;

        // Circumradius over shortest edge.
        const Tensor<1, 3> centre =
          (a.norm_square() * dealii::cross_product_3d(b, c) +
           b.norm_square() * dealii::cross_product_3d(c, a) +
           c.norm_square() * dealii::cross_product_3d(a, b)) /
          (2 * six_volume);
        double shortest = std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = i + 1; j < 4; ++j)
            shortest = std::min(shortest, p[i].distance(p[j]));
        const double ratio = centre.norm() / shortest;
        q.max_radius_edge  = std::max(q.max_radius_edge, ratio);
        sum_ratio += ratio;

        // Outward unit normals of the faces opposite each vertex; the
        // dihedral angle at the edge shared by faces k and l is
        // pi - angle(n_k, n_l).
        std::array<Tensor<1, 3>, 4> n;
        for (unsigned int m = 0; m < 4; ++m)
          {
            const unsigned int i = (m + 1) % 4, j = (m + 2) % 4,
                               k = (m + 3) % 4;
            Tensor<1, 3> normal =
              dealii::cross_product_3d(p[j] - p[i], p[k] - p[i]);
            if (normal * (p[i] - p[m]) < 0)
              normal = -normal;
            n[m] = normal / normal.norm();
          }
        double smallest = 180;
        for (unsigned int k = 0; k < 4; ++k)
          for (unsigned int l = k + 1; l < 4; ++l)
            {
              const double angle =
                180 - std::acos(std::clamp(n[k] * n[l], -1., 1.)) * 180 / M_PI;
              smallest           = std::min(smallest, angle);
              q.max_dihedral_deg = std::max(q.max_dihedral_deg, angle);
            }
        q.min_dihedral_deg = std::min(q.min_dihedral_deg, smallest);
        if (smallest < 10)
          ++q.n_below_10_deg;
      }
    if (!tets.cells.empty())
      q.mean_radius_edge = sum_ratio / tets.cells.size();
    return q;
  }

  namespace
  {
    /// Bytes per voxel of the skull's distance grid: the region, its
    /// complement and two distance fields.
    constexpr double skull_grid_bytes_per_voxel = 2 + 2 * sizeof(double);
    /// The share of the machine's memory the grid may take.
    constexpr double skull_grid_memory_share = 0.5;

    /// A grid padded by the gap that cannot fit the machine is refused.
    void
    check_skull_grid(const std::array<double, 3> &n, const double gap)
    {
      const double voxels = n[0] * n[1] * n[2];
      const double bytes  = voxels * skull_grid_bytes_per_voxel;
      if (exceeds_machine_memory(bytes, skull_grid_memory_share))
        throw InputError("",
                         "--skull-gap",
                         "a gap of " + number_text(gap) +
                           " mm needs a distance grid of " +
                           number_text(voxels) + " voxels (" +
                           gibibytes_text(bytes) +
                           "), more than this machine can hold; "
                           "expected a gap of a few mm");
    }

    /// A skull cutting deeper than the labelled region is thick encloses
    /// nothing: @p dist is the signed distance (negative inside).
    void
    check_gap_leaves_a_region(const std::vector<double> &dist,
                              const double               gap,
                              const double               h_min)
    {
      const double deepest = *std::min_element(dist.begin(), dist.end());
      // At least a voxel of the region must lie inside the skull.
      if (gap - h_min > deepest)
        return;
      throw InputError("",
                       "--skull-gap",
                       "a skull " + number_text(-gap) +
                         " mm inside the labelled region's surface encloses "
                         "nothing of it (its deepest voxel lies " +
                         number_text(-deepest) +
                         " mm inside); expected a gap above " +
                         number_text(deepest + h_min) + " mm");
    }
  } // namespace

  unsigned int
  write_enclosing_surface(const LabelledImage &image,
                          const double         gap,
                          const double         closing,
                          const double         facet_size,
                          const double         facet_distance,
                          const std::string   &file)
  {
    const ToWorld to_world(image);
    const auto   &h     = to_world.h;
    const double  h_min = *std::min_element(h.begin(), h.end());

    // The distance grid: the image padded so that the level set fits.
    const double pad_voxels =
      std::max(0., std::ceil((closing + gap + facet_size) / h_min)) + 2;
    std::array<double, 3> padded;
    for (unsigned int d = 0; d < 3; ++d)
      padded[d] = image.size[d] + 2 * pad_voxels;
    check_skull_grid(padded, gap);
    const int                   pad = int(pad_voxels);
    std::array<unsigned int, 3> n;
    for (unsigned int d = 0; d < 3; ++d)
      n[d] = image.size[d] + 2 * pad;
    const VoxelGrid   grid{n, h};
    std::vector<bool> region(grid.size(), false);
    for (unsigned int k = 0; k < image.size[2]; ++k)
      for (unsigned int j = 0; j < image.size[1]; ++j)
        for (unsigned int i = 0; i < image.size[0]; ++i)
          if (image.labels[image.index(i, j, k)] != 0)
            region[grid.at(i + pad, j + pad, k + pad)] = true;

    // Morphological closing with a ball of radius `closing`: it bridges
    // sulci and fissures narrower than the ball, as the inner table of the
    // skull does.
    close_with_ball(region, grid, closing);
    // Signed distance to the boundary of the closed region (half a voxel
    // beyond the centres of its outer voxels), negative inside, so that a
    // gap <= 0 puts the surface on or into the region (a segmented skull
    // that touches or cuts the brain).
    std::vector<double> dist = distance_to(region, grid);
    {
      std::vector<bool> outside(region.size());
      for (std::size_t v = 0; v < region.size(); ++v)
        outside[v] = !region[v];
      const std::vector<double> inward = distance_to(outside, grid);
      for (std::size_t v = 0; v < region.size(); ++v)
        dist[v] =
          region[v] ? -(inward[v] - 0.5 * h_min) : dist[v] - 0.5 * h_min;
    }

    check_gap_leaves_a_region(dist, gap, h_min);

    // The signed distance minus the gap, trilinear, in scaled index space
    // of the unpadded image.
    const double shift    = gap;
    const auto   function = [&](const Point &p) -> double {
      std::array<double, 3>       x{{CGAL::to_double(p.x()) / h[0] + pad,
                                     CGAL::to_double(p.y()) / h[1] + pad,
                                     CGAL::to_double(p.z()) / h[2] + pad}};
      std::array<unsigned int, 3> i0;
      std::array<double, 3>       t;
      for (unsigned int dd = 0; dd < 3; ++dd)
        {
          if (!(x[dd] >= 0 && x[dd] <= n[dd] - 1))
            return gap + pad * h_min;
          i0[dd] = std::min<unsigned int>(std::floor(x[dd]), n[dd] - 2);
          t[dd]  = x[dd] - i0[dd];
        }
      double value = 0;
      for (unsigned int corner = 0; corner < 8; ++corner)
        {
          double       weight = 1;
          unsigned int c[3];
          for (unsigned int dd = 0; dd < 3; ++dd)
            {
              const bool upper = (corner >> dd) & 1;
              c[dd]            = i0[dd] + upper;
              weight *= upper ? t[dd] : 1 - t[dd];
            }
          value += weight * dist[grid.at(c[0], c[1], c[2])];
        }
      return value - shift;
    };

    Kernel::Point_3       lower(-pad * h[0], -pad * h[1], -pad * h[2]);
    Kernel::Point_3       upper((n[0] - pad - 1) * h[0],
                          (n[1] - pad - 1) * h[1],
                          (n[2] - pad - 1) * h[2]);
    const Kernel::Point_3 centre = CGAL::midpoint(lower, upper);
    const Domain          domain = Domain::create_implicit_mesh_domain(
      function,
      Kernel::Sphere_3(centre, CGAL::squared_distance(lower, centre)),
      params::relative_error_bound = 1e-6);
    const Criteria criteria(params::facet_angle            = 25,
                            params::facet_size             = facet_size,
                            params::facet_distance         = facet_distance,
                            params::cell_radius_edge_ratio = 3,
                            params::cell_size              = 4 * facet_size);
    seed_cgal(0);
    const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain,
                                              criteria,
                                              params::no_perturb(),
                                              params::no_exude(),
                                              params::manifold());

    CGAL::Surface_mesh<Point> surface;
    CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, surface);
    if (surface.number_of_faces() == 0)
      throw InputError(file,
                       "--skull-gap",
                       "the skull surface at a gap of " + number_text(gap) +
                         " mm is empty; expected a gap that leaves the "
                         "labelled region a surface");
    for (const auto vertex : surface.vertices())
      {
        const Point &p        = surface.point(vertex);
        const auto   x        = to_world(p.x(), p.y(), p.z());
        surface.point(vertex) = Point(x[0], x[1], x[2]);
      }
    if (!CGAL::Polygon_mesh_processing::is_outward_oriented(surface))
      CGAL::Polygon_mesh_processing::reverse_face_orientations(surface);

    write_named_file_atomically(
      file,
      [&](const std::string &tmp) {
        return CGAL::IO::write_polygon_mesh(tmp,
                                            surface,
                                            params::stream_precision(12));
      },
      "--skull-out",
      "cannot write the surface; expected a writable .stl, .off or .obj file name");
    return surface.number_of_faces();
  }
} // namespace RestShape
