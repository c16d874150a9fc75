#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_3/initialize_triangulation_from_labeled_image.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/refine_mesh_3.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/base/machine_memory.h>
#include <restshape/mesh/mesh_description.h>
#include <restshape/mesher/components.h>
#include <restshape/mesher/image_mesher.h>
#include <restshape/mesher/image_morphology.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

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
    /// CGAL's image is padded by this many voxels of background on every
    /// side: the labelled region then ends half a voxel beyond the centres
    /// of the image's outermost voxels, as it does inside (CGAL's domain
    /// ends at the centres of the outermost voxels of its image).
    constexpr unsigned int border_pad_voxels = 1;

    struct ToWorld
    {
      /// @p shift: voxels of padding before the image's first voxel.
      ToWorld(const LabelledImage &image, const double shift)
        : image(image)
        , h(image.spacing())
        , shift(shift)
      {}
      dealii::Point<3>
      operator()(const double x, const double y, const double z) const
      {
        return image.position(x / h[0] - shift,
                              y / h[1] - shift,
                              z / h[2] - shift);
      }
      bool
      mirrors() const
      {
        return dealii::determinant(image.index_to_mm) < 0;
      }
      const LabelledImage  &image;
      std::array<double, 3> h;
      double                shift;
    };

    /// The labels as a CGAL image in the smallest unsigned word that holds
    /// them (an atlas with labels up to 255 takes a byte per voxel).
    _image *
    cgal_labels(const LabelledImage         &image,
                const std::array<double, 3> &h,
                const unsigned int           pad)
    {
      const unsigned int n[3]  = {image.size[0] + 2 * pad,
                                  image.size[1] + 2 * pad,
                                  image.size[2] + 2 * pad};
      const unsigned int bytes = image.label_bytes();
      _image            *raw   = ::_createImage(
        n[0], n[1], n[2], 1, h[0], h[1], h[2], bytes, WK_FIXED, SGN_UNSIGNED);
      if (pad == 0)
        {
          image.store_labels(raw->data);
          return raw;
        }
      std::vector<char> words(std::size_t(image.size[0]) * image.size[1] *
                              image.size[2] * bytes);
      image.store_labels(words.data());
      char *data = static_cast<char *>(raw->data);
      std::memset(data, 0, std::size_t(n[0]) * n[1] * n[2] * bytes);
      const std::size_t row = std::size_t(image.size[0]) * bytes;
      for (unsigned int k = 0; k < image.size[2]; ++k)
        for (unsigned int j = 0; j < image.size[1]; ++j)
          std::memcpy(data + ((std::size_t(k + pad) * n[1] + (j + pad)) * n[0] +
                              pad) *
                               bytes,
                      words.data() + image.index(0, j, k) * bytes,
                      row);
      return raw;
    }

    /// Whether a label touches the image's border (it then needs the
    /// padding).
    bool
    touches_border(const LabelledImage &image)
    {
      const auto &n = image.size;
      for (unsigned int k = 0; k < n[2]; ++k)
        for (unsigned int j = 0; j < n[1]; ++j)
          for (unsigned int i = 0; i < n[0];
               i += (j == 0 || k == 0 || j + 1 == n[1] || k + 1 == n[2]) ?
                      1 :
                      std::max(1u, n[0] - 1))
            if (image.labels[image.index(i, j, k)] != 0)
              return true;
      return false;
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
    /// Prints "  PHASE: N s" every few seconds while it lives (Mesh_3
    /// reports nothing during a phase).
    class Heartbeat
    {
    public:
      explicit Heartbeat(const std::string &phase)
        : phase(phase)
        , start(std::chrono::steady_clock::now())
        , thread([this]() { beat(); })
      {}
      ~Heartbeat()
      {
        {
          std::lock_guard<std::mutex> lock(mutex);
          done = true;
        }
        wake.notify_all();
        thread.join();
        std::ostringstream line;
        line << "  " << phase << ": done in " << std::fixed
             << std::setprecision(1) << seconds() << " s";
        std::cout << line.str() << std::endl;
      }

    private:
      static constexpr std::chrono::seconds interval{5};
      double
      seconds() const
      {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
          .count();
      }
      void
      beat()
      {
        std::unique_lock<std::mutex> lock(mutex);
        while (!wake.wait_for(lock, interval, [this]() { return done; }))
          std::cout << "  " << phase << ": " << std::lround(seconds()) << " s"
                    << std::endl;
      }
      const std::string                           phase;
      const std::chrono::steady_clock::time_point start;
      std::mutex                                  mutex;
      std::condition_variable                     wake;
      bool                                        done = false;
      std::thread                                 thread;
    };

    /// Initial points on the boundary of every connected component of
    /// every label (CGAL's own initial points come from random rays from
    /// the image's centre and miss enclosed regions and cavities; CGAL
    /// 5.6 added image initial points for that, 5.5 has this function).
    /// Its messages on std::cout are replaced by one line.
    template <typename Word>
    void
    seed_every_component(C3t3                &c3t3,
                         const Domain        &domain,
                         const CGAL::Image_3 &image,
                         const Criteria      &criteria)
    {
      std::ostringstream cgal_text;
      std::streambuf    *saved = std::cout.rdbuf(cgal_text.rdbuf());
      try
        {
          initialize_triangulation_from_labeled_image(
            c3t3, domain, image, criteria, Word(0));
        }
      catch (...)
        {
          std::cout.rdbuf(saved);
          throw;
        }
      std::cout.rdbuf(saved);
      std::cout << "  initial points on every connected component: "
                << c3t3.triangulation().number_of_vertices() << std::endl;
    }

    /// Mesh_3 with the options' optimiser and sliver removal: from
    /// CGAL's own initial points (make_mesh_3), or refining @p c3t3 that
    /// holds initial points already (refine_mesh_3).
    void
    run_mesh_3(C3t3                   &c3t3,
               const Domain           &domain,
               const Criteria         &criteria,
               const ImageMeshOptions &o,
               const bool              refine)
    {
      const auto perturb =
        params::perturb(params::sliver_bound = o.sliver_bound,
                        params::time_limit   = 0);
      const auto exude = params::exude(params::sliver_bound = o.sliver_bound,
                                       params::time_limit   = 0);
      const auto run   = [&](const auto &optimiser) {
        if (refine)
          CGAL::refine_mesh_3(
            c3t3, domain, criteria, optimiser, perturb, exude);
        else
          c3t3 = CGAL::make_mesh_3<C3t3>(
            domain, criteria, optimiser, perturb, exude);
      };
      const unsigned int n = o.optimiser_iterations;
      switch (o.optimiser)
        {
          case MeshOptimiser::odt:
            run(params::odt(params::time_limit           = 0,
                            params::max_iteration_number = n));
            break;
          case MeshOptimiser::lloyd:
            run(params::lloyd(params::time_limit           = 0,
                              params::max_iteration_number = n));
            break;
          default:
            run(params::no_odt());
        }
    }

    /// A segment from inside a cavity to the tissue around it, in CGAL's
    /// coordinates: its wall lies between the ends.
    using Segment = std::pair<Point, Point>;

    /// Per cavity, segments from its central voxel along the 26 voxel
    /// directions to the first voxel of tissue (CGAL 5.5's initial points
    /// come from the labelled regions alone, and miss cavity walls).
    std::vector<Segment>
    cavity_segments(const LabelledImage         &image,
                    const ImageComponents       &components,
                    const unsigned int           pad,
                    const std::array<double, 3> &h)
    {
      std::vector<Segment> segments;
      const auto           at = [&](const std::array<int, 3> &v) {
        return Point((v[0] + pad) * h[0],
                     (v[1] + pad) * h[1],
                     (v[2] + pad) * h[2]);
      };
      const auto inside = [&](const std::array<int, 3> &v) {
        for (unsigned int d = 0; d < 3; ++d)
          if (v[d] < 0 || v[d] >= int(image.size[d]))
            return false;
        return true;
      };
      for (const auto &c : components.cavity_voxels)
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
              {
                if (dx == 0 && dy == 0 && dz == 0)
                  continue;
                const std::array<int, 3> start = {
                  {int(c[0]), int(c[1]), int(c[2])}};
                for (std::array<int, 3> v = start; inside(v);
                     v                    = {{v[0] + dx, v[1] + dy, v[2] + dz}})
                  if (image.labels[image.index(v[0], v[1], v[2])] != 0)
                    {
                                         segments.emplace_back(at(start), at(v));
                                         break;
                    }
              }
      return segments;
    }

    /// Initial points on the cavity walls: where each segment crosses the
    /// domain's boundary.
    void
    seed_cavity_walls(C3t3                       &c3t3,
                      const Domain               &domain,
                      const std::vector<Segment> &segments)
    {
      auto       intersect = domain.construct_intersection_object();
      Tr        &tr        = c3t3.triangulation();
      const auto weighted =
        tr.geom_traits().construct_weighted_point_3_object();
      std::size_t added = 0;
      for (const auto &[inside, tissue] : segments)
        {
          const auto i = intersect(Kernel::Segment_3(inside, tissue));
          if (std::get<2>(i) == 0)
            continue;
          const Tr::Vertex_handle v = tr.insert(weighted(std::get<0>(i)));
          if (v == Tr::Vertex_handle())
            continue;
          c3t3.set_dimension(v, 2);
          c3t3.set_index(v, std::get<1>(i));
          ++added;
        }
      std::cout << "  initial points on cavity walls: " << added << std::endl;
    }

    /// Mesh_3 on the labels as CGAL has them; vertices mapped by @p to_world.
    MeshDescription
    mesh_cgal_image(const CGAL::Image_3        &cgal_image,
                    const ToWorld              &to_world,
                    const ImageMeshOptions     &options,
                    const bool                  every_component,
                    const std::vector<Segment> &cavities = {})
    {
      // The seed drives the domain's own random numbers and the initial
      // points' directions.
      CGAL::Random random(options.seed);
      seed_cgal(options.seed);
      const Domain domain =
        Domain::create_labeled_image_mesh_domain(cgal_image,
                                                 params::relative_error_bound =
                                                   1e-6,
                                                 params::p_rng = &random);
      const Criteria criteria(params::facet_angle    = options.facet_angle,
                              params::facet_size     = options.facet_size,
                              params::facet_distance = options.facet_distance,
                              params::cell_radius_edge_ratio =
                                options.radius_edge,
                              params::cell_size = options.cell_size);
      C3t3           c3t3;
      if (!every_component)
        {
          const Heartbeat beat("Mesh_3 (surfaces, volume, slivers)");
          run_mesh_3(c3t3, domain, criteria, options, false);
        }
      else
        {
          switch (cgal_image.image()->wdim)
            {
              case 1:
                seed_every_component<unsigned char>(c3t3,
                                                    domain,
                                                    cgal_image,
                                                    criteria);
                break;
              case 2:
                seed_every_component<unsigned short>(c3t3,
                                                     domain,
                                                     cgal_image,
                                                     criteria);
                break;
              default:
                seed_every_component<unsigned int>(c3t3,
                                                   domain,
                                                   cgal_image,
                                                   criteria);
            }
          seed_cavity_walls(c3t3, domain, cavities);
          const Heartbeat beat("Mesh_3 from them (surfaces, volume, slivers)");
          run_mesh_3(c3t3, domain, criteria, options, true);
        }

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

  namespace
  {
    /// Mesh_3 from CGAL's initial points, and again from points on every
    /// component if those missed one (CGAL's points are rays from the
    /// image's centre: they miss enclosed regions and cavities, which
    /// then vanish from the mesh). Meshes CGAL's own points reach alike
    /// stay as they were.
    MeshDescription
    mesh_every_component(const CGAL::Image_3        &cgal_image,
                         const ToWorld              &to_world,
                         const ImageMeshOptions     &options,
                         const ImageComponents      &components,
                         const double                voxel_volume,
                         const std::vector<Segment> &cavities)
    {
      MeshDescription mesh =
        mesh_cgal_image(cgal_image, to_world, options, false);
      std::ostringstream ignored;
      const std::string  lost = compare_components(
        components,
        mesh_components(mesh),
        voxel_volume,
        least_component_volume(options.cell_size),
        [](const unsigned int label) {
          return "label " + std::to_string(label);
        },
        ignored);
      if (lost.empty())
        return mesh;
      std::cout << "  CGAL's initial points missed regions (" << lost
                << "): meshing again from points on every connected component"
                << std::endl;
      return mesh_cgal_image(cgal_image, to_world, options, true, cavities);
    }
  } // namespace

  MeshDescription
  mesh_labelled_image(const LabelledImage    &image,
                      const ImageMeshOptions &options,
                      const ImageComponents  &components)
  {
    const unsigned int  pad = touches_border(image) ? border_pad_voxels : 0;
    const ToWorld       to_world(image, pad);
    const CGAL::Image_3 cgal_image(cgal_labels(image, to_world.h, pad));
    return mesh_every_component(
      cgal_image,
      to_world,
      options,
      components,
      std::abs(dealii::determinant(image.index_to_mm)),
      cavity_segments(image, components, pad, to_world.h));
  }

  MeshDescription
  mesh_labelled_image(LabelledImage         &&image,
                      const ImageMeshOptions &options,
                      const ImageComponents  &components)
  {
    const unsigned int  pad = touches_border(image) ? border_pad_voxels : 0;
    const ToWorld       to_world(image, pad);
    const CGAL::Image_3 cgal_image(cgal_labels(image, to_world.h, pad));
    const double        voxel_volume =
      std::abs(dealii::determinant(image.index_to_mm));
    const std::vector<Segment> cavities =
      cavity_segments(image, components, pad, to_world.h);
    std::vector<ImageLabel>().swap(image.labels);
    return mesh_every_component(
      cgal_image, to_world, options, components, voxel_volume, cavities);
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
        q.worst_cells.emplace_back(smallest, &cell - tets.cells.data());
      }
    if (!tets.cells.empty())
      q.mean_radius_edge = sum_ratio / tets.cells.size();
    constexpr std::size_t n_worst = 5;
    const std::size_t     n       = std::min(n_worst, q.worst_cells.size());
    std::partial_sort(q.worst_cells.begin(),
                      q.worst_cells.begin() + n,
                      q.worst_cells.end());
    q.worst_cells.resize(n);
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
    const ToWorld to_world(image, 0);
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
