// restshape-mesh: a labelled NIfTI image to a labelled tetrahedral mesh
// (CGAL Mesh_3), and optionally the skull surface around it. Its options
// and what they do: the usage text below (restshape-mesh --help).
#include <deal.II/base/timer.h>

#include <restshape/base/atomic_file.h>
#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/interruption.h>
#include <restshape/base/machine_memory.h>
#include <restshape/base/units.h>
#include <restshape/base/version.h>
#include <restshape/contact/obstacle.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/labelled_mesh.h>
#include <restshape/mesh/mesh_checks.h>
#include <restshape/mesh/mesh_pieces.h>
#include <restshape/mesher/components.h>
#include <restshape/mesher/image_mesher.h>
#include <restshape/mesher/image_morphology.h>
#include <restshape/mesher/label_map.h>
#include <restshape/mesher/labelled_image.h>
#include <restshape/mesher/skull_cavity.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>

namespace
{
  const char *const usage =
    "restshape-mesh: a labelled NIfTI image to a labelled tetrahedral mesh\n"
    "(CGAL Mesh_3), and optionally the skull surface around it.\n"
    "\n"
    "  restshape-mesh --image LABELS.nii[.gz] --out MESH.msh\n"
    "      [--cell-size MM] [--facet-size MM] [--facet-distance MM]\n"
    "      [--sliver-bound DEG] [--seed N] [--min-piece-fraction F]\n"
    "      [--optimise none|odt|lloyd [--optimise-iterations N]]\n"
    "      [--close-sulci MM]\n"
    "      [--label-names NAMES.txt] [--label-map MAP.txt\n"
    "       [--unlisted-labels error|background]]\n"
    "      [--skull-out SKULL.stl --skull-gap MM [--skull-closing MM]\n"
    "       [--skull-facet-size MM]]\n"
    "      [--skull-out SKULL.stl --skull-image MASK.nii[.gz]\n"
    "       [--skull-facet-size MM]]\n"
    "\n"
    "The mesh is written as gmsh 2.2 in mm, every tetrahedron with its image\n"
    "label as physical volume tag; the mesh and the skull appear together,\n"
    "once both are made (a failure leaves earlier files as they were). Sizes\n"
    "below a quarter of the voxel size, and a cell size whose mesh would not\n"
    "fit the machine's memory, are refused before the work.\n"
    "The skull is a closed, outward-oriented surface at --skull-gap mm from\n"
    "the labelled region (0: touching it; negative: cutting into it, as a\n"
    "segmented skull can), for\n"
    "Contact/Obstacle file with Side = inside. Before the offset, the labelled\n"
    "region is closed morphologically with a ball of --skull-closing mm\n"
    "(default 10; 0 = none), so that the skull bridges sulci and fissures.\n"
    "--skull-image instead takes a segmented skull (a mask: non-zero voxels\n"
    "are bone, on any grid): the skull surface is the boundary of the\n"
    "largest region the mask encloses (its cavity); a mask open to the\n"
    "outside, e.g. at the foramen magnum, is an error (close it in the\n"
    "mask). Brain nodes beyond it are reported, as for a negative gap.\n"
    "Pieces of the mesh joined to the rest only at vertices or edges (Mesh_3\n"
    "leaves them where labelled voxels touch diagonally) and smaller than\n"
    "--min-piece-fraction times the largest piece (default 0.01; 0 keeps all)\n"
    "are removed: they would hinge freely and stop Newton's method.\n"
    "--close-sulci MM (default 0 = off) closes the labelled region with a ball\n"
    "of MM mm before meshing: sulci and gaps narrower than about 2 MM are\n"
    "filled with the neighbouring label, so that the mesh's surface has no\n"
    "pinched edges there (two folds touching along an edge, where CSF\n"
    "pressure crushes the cells). The report counts the pinched edges left.\n"
    "\n"
    "Labels: any whole-number voxel value from 0 (background) to 2147483647.\n"
    "--label-names reads a table of 'label name' lines (e.g. the .nii.txt\n"
    "next to an atlas); the mesh then carries the names of its labels as gmsh\n"
    "$PhysicalNames, and a scene may use them wherever it lists labels\n"
    "('Young's modulus = cerebrum:1500, *:1000'). --label-map merges atlas\n"
    "labels into tissues before meshing, one line per tissue:\n"
    "  # atlas labels   tissue label   name\n"
    "  1-90             1              cerebrum\n"
    "  91-116,120       3              cerebellum\n"
    "  117              0              (0: background, left out)\n"
    "Atlas labels are labels, ranges or (with --label-names) atlas names;\n"
    "the mesh carries the tissue names. Image labels the map does not list\n"
    "are an error that lists them, or background with --unlisted-labels\n"
    "background.\n"
    "\n"
    "Every connected component of every label is meshed, inclusions enclosed\n"
    "by another label and cavities (label 0 inside the body, e.g. ventricles)\n"
    "too: Mesh_3 starts from points on each component's boundary. The report\n"
    "gives each label's components and volume in the image and in the mesh\n"
    "and the boundary surfaces (the outer one and each cavity's wall); a\n"
    "component of more than 8 cells' volume missing from the mesh is an error\n"
    "(a smaller one a warning). Labels on the image's border keep their outer\n"
    "half voxel. --seed N (default 0) seeds Mesh_3's random numbers: the same\n"
    "seed gives the same mesh. --optimise odt|lloyd runs CGAL's ODT or Lloyd\n"
    "smoothing (--optimise-iterations, default 10) before the sliver\n"
    "perturbation and exudation; the quality report names the worst cells.\n"
    "Long phases print a line every 5 s. The boundary is written as gmsh\n"
    "physical surfaces by role: 1 outer_surface (skull contact, CSF), 2\n"
    "cavity_walls (ventricles); restshape reads the volumes alone.\n";
} // namespace

using namespace RestShape;

namespace
{
  /// What the command line asks for.
  struct MesherSettings
  {
    std::string      image_file, out, skull_out, skull_image;
    std::string      label_names_file, label_map_file;
    UnlistedLabels   unlisted = UnlistedLabels::error;
    ImageMeshOptions options;
    double           skull_gap = 0, skull_facet_size = 0, skull_closing = 10;
    double           min_piece_fraction = 0.01, close_sulci = 0;
  };

  /// --out is a gmsh file name, --skull-out a surface file name, neither
  /// an existing directory, and not the same file.
  void
  check_output_names(const MesherSettings &s)
  {
    namespace fs     = std::filesystem;
    const auto check = [](const std::string              &file,
                          const std::string              &option,
                          const std::vector<std::string> &extensions,
                          const std::string              &expected) {
      if (fs::is_directory(file))
        throw InputError(file, option, "is a directory; expected " + expected);
      const std::string extension = fs::path(file).extension().string();
      if (std::find(extensions.begin(), extensions.end(), extension) ==
          extensions.end())
        throw InputError(file,
                         option,
                         "unsupported extension '" + extension +
                           "'; expected " + expected);
    };
    check(s.out, "--out", {".msh"}, "a gmsh file name (.msh)");
    if (s.skull_out.empty())
      return;
    check(s.skull_out,
          "--skull-out",
          {".off", ".stl", ".obj"},
          "a surface file name (.off, .stl or .obj)");
    if (fs::absolute(s.skull_out).lexically_normal() ==
        fs::absolute(s.out).lexically_normal())
      throw InputError(s.skull_out,
                       "--skull-out",
                       "names the same file as --out; expected another file");
  }

  MesherSettings
  read_settings(const ToolOptions &cl)
  {
    MesherSettings s;
    s.image_file =
      cl.required("--image", "a labelled NIfTI image (.nii or .nii.gz)");
    s.out       = cl.required("--out", "the output mesh's file name (.msh)");
    s.skull_out = cl.text("--skull-out");
    s.label_names_file = cl.text("--label-names");
    s.label_map_file   = cl.text("--label-map");
    if (cl.given("--unlisted-labels") && s.label_map_file.empty())
      throw InputError("",
                       "--unlisted-labels",
                       "given without --label-map; expected it with a map");
    s.unlisted =
      cl.choice("--unlisted-labels", "error", {"error", "background"}) ==
          "error" ?
        UnlistedLabels::error :
        UnlistedLabels::background;
    auto &o          = s.options;
    o.cell_size      = cl.positive("--cell-size", o.cell_size);
    o.facet_size     = cl.positive("--facet-size", o.cell_size);
    o.facet_distance = cl.positive("--facet-distance", o.facet_distance);
    o.sliver_bound   = cl.positive("--sliver-bound", o.sliver_bound);
    o.seed           = cl.integer("--seed", o.seed, 0, 2147483647);
    const std::string optimiser =
      cl.choice("--optimise", "none", {"none", "odt", "lloyd"});
    o.optimiser = optimiser == "odt"   ? MeshOptimiser::odt :
                  optimiser == "lloyd" ? MeshOptimiser::lloyd :
                                         MeshOptimiser::none;
    o.optimiser_iterations =
      cl.integer("--optimise-iterations", o.optimiser_iterations, 1, 1000);
    s.min_piece_fraction =
      cl.non_negative("--min-piece-fraction", s.min_piece_fraction);
    if (s.min_piece_fraction > 1)
      throw InputError("",
                       "--min-piece-fraction",
                       "got " + cl.text("--min-piece-fraction") +
                         " (expected a fraction from 0 to 1)");
    s.close_sulci      = cl.non_negative("--close-sulci", 0);
    s.skull_gap        = cl.number("--skull-gap", 0);
    s.skull_closing    = cl.non_negative("--skull-closing", s.skull_closing);
    s.skull_facet_size = cl.positive("--skull-facet-size", o.facet_size);
    s.skull_image      = cl.text("--skull-image");
    if (!s.skull_image.empty() && s.skull_out.empty())
      throw InputError("",
                       "--skull-out",
                       "--skull-image given without an output surface");
    if (!s.skull_image.empty() && cl.given("--skull-gap"))
      throw InputError("",
                       "--skull-gap",
                       "given with --skull-image, whose cavity is the skull's "
                       "inner surface; expected one of them");
    if (!s.skull_out.empty() && s.skull_image.empty() &&
        !cl.given("--skull-gap"))
      throw InputError("",
                       "--skull-gap",
                       "--skull-out needs the CSF gap in mm (or a segmented "
                       "skull: --skull-image)");
    if (s.skull_out.empty() && cl.given("--skull-gap"))
      throw InputError("",
                       "--skull-out",
                       "--skull-gap given without an output surface");
    check_output_names(s);
    // Fail on an unwritable destination before the meshing work.
    for (const std::string &file : {s.out, s.skull_out})
      if (!file.empty())
        ensure_writable_directory(
          std::filesystem::path(file).parent_path().empty() ?
            "." :
            std::filesystem::path(file).parent_path().string(),
          file == s.out ? "--out" : "--skull-out");
    return s;
  }

  /// "label 3" or "label 3 (cerebellum)".
  std::string
  label_text(const unsigned int label, const LabelNames &names)
  {
    const std::string name = names.name(label);
    return "label " + std::to_string(label) +
           (name.empty() ? "" : " (" + name + ")");
  }

  /// Apply --label-map and read --label-names; the names of the labels
  /// the mesh will carry.
  LabelNames
  prepare_labels(LabelledImage &image, const MesherSettings &s)
  {
    const LabelNames atlas_names =
      s.label_names_file.empty() ?
        LabelNames() :
        read_label_names(s.label_names_file, "--label-names");
    if (s.label_map_file.empty())
      return atlas_names;
    const LabelMap map =
      LabelMap::read(s.label_map_file, "--label-map", atlas_names);
    const std::size_t n_dropped =
      apply_label_map(image, map, s.unlisted, s.label_map_file, "--label-map");
    const auto counts = image.label_counts();
    if (counts.empty())
      throw InputError(s.label_map_file,
                       "--label-map",
                       "every labelled voxel became background; expected "
                       "at least one tissue label other than 0");
    const auto h = image.spacing();
    std::cout << "label map " << s.label_map_file << ": " << counts.size()
              << " tissue labels, " << n_dropped * h[0] * h[1] * h[2] / 1000
              << " cm^3 of the atlas now background" << std::endl;
    return map.tissue_names();
  }

  /// Size, spacing and labels of @p image, with @p counts its voxels per
  /// label.
  void
  report_image(const LabelledImage                       &image,
               const std::map<unsigned int, std::size_t> &counts,
               const std::string                         &file,
               const LabelNames                          &names)
  {
    const auto h = image.spacing();
    std::cout << std::setprecision(4) << "image " << file << ": "
              << image.size[0] << "x" << image.size[1] << "x" << image.size[2]
              << " voxels of " << h[0] << "x" << h[1] << "x" << h[2]
              << " mm; labels";
    // An atlas has hundreds of labels: then only their list.
    constexpr std::size_t max_listed = 12;
    if (counts.size() > max_listed)
      {
        std::set<Label> labels;
        for (const auto &[label, count] : counts)
          labels.insert(label);
        std::cout << ' ' << to_string(labels) << std::endl;
        return;
      }
    for (const auto &[label, count] : counts)
      std::cout << " " << label
                << (names.name(label).empty() ? "" : " " + names.name(label))
                << " (" << count * h[0] * h[1] * h[2] / 1000 << " cm^3)";
    std::cout << std::endl;
  }

  /// Sizes of the mesh against the image: Mesh_3 resolves a surface far
  /// below the voxel size only by refining without end, and a cell size
  /// far below it makes more tetrahedra than memory holds.
  void
  check_mesh_sizes(const LabelledImage                       &image,
                   const std::map<unsigned int, std::size_t> &counts,
                   const MesherSettings                      &s)
  {
    // Smallest sizes, as fractions of the smallest voxel size.
    constexpr double smallest_size_in_voxels = 0.25;
    // Measured with Mesh_3 on tests/data/sphere_labels.nii (cell size
    // 0.5 mm: 864,279 tetrahedra): a tetrahedron per 0.25 cell size^3.
    constexpr double volume_per_tetrahedron = 0.25;
    constexpr double bytes_per_tetrahedron  = 1024;
    constexpr double usable_share           = 0.75;

    const auto   h     = image.spacing();
    const double h_min = *std::min_element(h.begin(), h.end());
    const double bound = smallest_size_in_voxels * h_min;
    const std::vector<std::pair<std::string, double>> sizes = {
      {"--cell-size", s.options.cell_size},
      {"--facet-size", s.options.facet_size},
      {"--facet-distance", s.options.facet_distance},
      {"--skull-facet-size", s.skull_out.empty() ? bound : s.skull_facet_size}};
    for (const auto &[option, size] : sizes)
      if (size < bound)
        throw InputError(s.image_file,
                         option,
                         number_text(size) +
                           " mm is far below the voxel size (" +
                           number_text(h_min) + " mm); expected at least " +
                           number_text(bound) + " mm");

    double volume = 0; // mm^3
    for (const auto &[label, count] : counts)
      volume += count * h[0] * h[1] * h[2];
    const double tetrahedra =
      volume / (volume_per_tetrahedron * std::pow(s.options.cell_size, 3));
    const double bytes = tetrahedra * bytes_per_tetrahedron;
    if (exceeds_machine_memory(bytes, usable_share))
      throw InputError(s.image_file,
                       "--cell-size",
                       number_text(s.options.cell_size) + " mm makes about " +
                         number_text(tetrahedra) + " tetrahedra (" +
                         gibibytes_text(bytes) + "), more than " +
                         available_memory().text() +
                         "; expected a larger cell size");
  }

  /// --close-sulci: the closed image (moved from @p image unless the
  /// skull still needs it: an atlas is large); @p counts: the voxels per
  /// label of @p image.
  LabelledImage
  close_sulci(LabelledImage                             &image,
              const std::map<unsigned int, std::size_t> &counts,
              const MesherSettings                      &s)
  {
    dealii::Timer timer;
    std::size_t   n_labelled = 0;
    for (const auto &[label, count] : counts)
      n_labelled += count;
    LabelledImage      closed = s.skull_out.empty() ? std::move(image) : image;
    const ClosedVoxels added  = close_labelled_image(closed, s.close_sulci);
    std::cout << "closed sulci narrower than about " << 2 * s.close_sulci
              << " mm (--close-sulci " << s.close_sulci
              << "): " << added.n_added << " voxels, "
              << added.volume_mm3 / 1000 << " cm^3 ("
              << 100. * added.n_added / n_labelled
              << " % of the labelled volume) added, in " << timer.wall_time()
              << " s" << std::endl;
    return closed;
  }

  /// Mesh_3 and the removal of pieces that hang at vertices or edges.
  /// The labels of @p image are freed unless @p keep_image.
  MeshDescription
  make_mesh(LabelledImage         &image,
            const MesherSettings  &s,
            const bool             keep_image,
            const ImageComponents &components)
  {
    dealii::Timer   timer;
    const auto     &o = s.options;
    MeshDescription mesh =
      keep_image ? mesh_labelled_image(image, o, components) :
                   mesh_labelled_image(std::move(image), o, components);
    if (mesh.cells.empty())
      throw InputError(
        s.image_file,
        "--cell-size",
        "the mesh is empty: the sizes are too large for the labelled "
        "region; expected sizes well below its extent");
    std::cout << "Mesh_3 (cell size " << o.cell_size << " mm, facet size "
              << o.facet_size << " mm, facet distance " << o.facet_distance
              << " mm): " << mesh.vertices.size() << " nodes, "
              << mesh.cells.size() << " tetrahedra in " << timer.wall_time()
              << " s" << std::endl;
    const RemovedPieces removed =
      remove_small_pieces(mesh, s.min_piece_fraction);
    if (removed.n_pieces > 0)
      std::cout << "removed " << removed.n_cells << " tetrahedra in "
                << removed.n_pieces
                << " pieces joined to the body only at vertices or edges "
                   "(smaller than --min-piece-fraction "
                << s.min_piece_fraction << " of the largest)" << std::endl;
    const unsigned int n_pieces = face_connected_pieces(mesh).n_cells.size();
    if (n_pieces > 1)
      std::cout << "warning: the mesh has " << n_pieces
                << " pieces not joined by faces" << std::endl;
    return mesh;
  }

  /// The voxels of each label of the meshed image and their size (mm).
  struct ImageVolumes
  {
    std::map<unsigned int, std::size_t> voxels;
    std::array<double, 3>               spacing;
  };

  /// Pinched edges, narrow gaps, cells and volume per label, quality.
  void
  report_mesh(const MeshDescription &mesh,
              const ImageVolumes    &image,
              const MesherSettings  &s)
  {
    const unsigned int n_pinched = n_pinched_boundary_edges(mesh);
    std::cout << "pinched boundary edges (two folds of the surface touching "
                 "along an edge): "
              << n_pinched
              << (n_pinched > 0 && s.close_sulci == 0 ?
                    "; CSF pressure on them can crush the cells there, "
                    "--close-sulci removes them" :
                    "")
              << std::endl;
    const SurfaceGap gap =
      narrowest_surface_gap(mesh, s.options.facet_distance);
    if (std::isfinite(gap.width))
      std::cout << describe_surface_gap(gap.width, gap.location) << "; "
                << gap.n_narrow
                << " surface faces face another fold closer than the facet "
                   "distance (thin flaps of tissue border such gaps; "
                   "--close-sulci fills them)"
                << std::endl;

    const MeshQuality                    q = mesh_quality(mesh);
    const auto                           h = image.spacing;
    std::map<unsigned int, unsigned int> n_per_label;
    for (const auto &cell : mesh.cells)
      ++n_per_label[cell.material_id];
    for (const auto &[label, count] : image.voxels)
      {
        const auto volume = q.volume_per_label.find(label);
        std::cout << "  " << label_text(label, mesh.names) << ": "
                  << n_per_label[label] << " tetrahedra, "
                  << (volume == q.volume_per_label.end() ?
                        0. :
                        volume->second / 1000)
                  << " cm^3 (image " << count * h[0] * h[1] * h[2] / 1000
                  << " cm^3)" << std::endl;
        if (n_per_label[label] == 0)
          std::cout << "  warning: " << label_text(label, mesh.names)
                    << " has no tetrahedron; reduce --cell-size to resolve it"
                    << std::endl;
      }
    std::cout << "quality: dihedral angles " << q.min_dihedral_deg << " to "
              << q.max_dihedral_deg << " deg (" << q.n_below_10_deg
              << " cells below 10 deg), radius-edge ratio mean "
              << q.mean_radius_edge << ", max " << q.max_radius_edge
              << std::endl;
    if (!q.worst_cells.empty())
      {
        std::cout << "worst cells (smallest dihedral angle; --optimise odt "
                     "or lloyd, or a larger --sliver-bound, improves them):";
        for (const auto &[angle, c] : q.worst_cells)
          {
            dealii::Point<3> centre;
            for (const unsigned int v : mesh.cells[c].vertices)
              centre += mesh.vertices[v] / 4.;
            std::cout << "\n  " << angle << " deg at (" << centre[0] << ", "
                      << centre[1] << ", " << centre[2] << ") mm, "
                      << label_text(mesh.cells[c].material_id, mesh.names);
          }
        std::cout << std::endl;
      }
  }

  /// The components of the image against the mesh's (report_mesh's
  /// lines); InputError naming --cell-size if the mesh lost a component
  /// or cavity of more than a few cells' volume.
  MeshComponents
  check_components(const MeshDescription &mesh,
                   const ImageComponents &image,
                   const ImageVolumes    &volumes,
                   const MesherSettings  &s)
  {
    const auto  &h     = volumes.spacing;
    const double least = least_component_volume(s.options.cell_size);
    std::cout << "components (6-connected voxels; face-connected cells):"
              << std::endl;
    MeshComponents    pieces = mesh_components(mesh);
    const std::string lost   = compare_components(
      image,
      pieces,
      h[0] * h[1] * h[2],
      least,
      [&](const unsigned int label) { return label_text(label, mesh.names); },
      std::cout);
    if (!lost.empty())
      throw InputError(s.image_file,
                       "--cell-size",
                       lost +
                         "; expected a smaller --cell-size (and --facet-size) "
                         "that resolves them");
    return pieces;
  }

  /// Physical surface tags of the boundary by role.
  constexpr int outer_surface_tag = 1, cavity_wall_tag = 2;

  /// The boundary triangles, tagged by role: the outer surface (skull
  /// contact, CSF) and the walls of cavities (ventricles).
  std::vector<SurfaceTriangle>
  surfaces_by_role(const MeshComponents &pieces)
  {
    std::vector<SurfaceTriangle> triangles;
    for (unsigned int f = 0; f < pieces.boundary_faces.size(); ++f)
      triangles.push_back(
        {pieces.boundary_faces[f],
         pieces.on_cavity_wall(f) ? cavity_wall_tag : outer_surface_tag});
    return triangles;
  }

  /// The skull's facet distance (mm): within half the gap of the exact
  /// surface, so that the mesh stays inside; for a gap <= 0 (a skull that
  /// touches or cuts the mesh) a tenth of its facet size, so that where it
  /// cuts is decided by the gap, not by its chords. (Small gaps cost
  /// triangles: on the coarse brain with --skull-facet-size 5, 680,704
  /// triangles in 147 s at 0.1 mm, 95,964 in 15 s at 0.4 mm.)
  double
  skull_facet_distance(const double facet_distance,
                       const double gap,
                       const double facet_size)
  {
    constexpr double chord_fraction = 0.1;
    return gap > 0 ? std::min(facet_distance, gap / 2) :
                     std::min(facet_distance, chord_fraction * facet_size);
  }

  /// Write the skull (the offset of @p image, or the boundary of the
  /// @p cavity of a segmented skull) and report its distances to the
  /// mesh's surface nodes (@p mesh in metres).
  void
  write_skull(const LabelledImage   &image,
              const LabelledImage   &cavity,
              const MeshDescription &mesh,
              const MesherSettings  &s,
              const std::string     &file)
  {
    dealii::Timer timer;
    const bool    segmented = !s.skull_image.empty();
    // A segmented skull: the boundary of the cavity its mask encloses.
    const unsigned int n_triangles =
      segmented ?
        write_enclosing_surface(cavity,
                                0,
                                0,
                                s.skull_facet_size,
                                skull_facet_distance(s.options.facet_distance,
                                                     0,
                                                     s.skull_facet_size),
                                file) :
        write_enclosing_surface(image,
                                s.skull_gap,
                                s.skull_closing,
                                s.skull_facet_size,
                                skull_facet_distance(s.options.facet_distance,
                                                     s.skull_gap,
                                                     s.skull_facet_size),
                                file);
    const Obstacle skull(file, 1e-3, true);
    double         min_gap = 1e9, max_gap = 0, sum = 0;
    unsigned int   outside = 0;
    const auto     nodes   = boundary_vertices(mesh);
    for (const unsigned int v : nodes)
      {
        const double gap = skull.gap(mesh.vertices[v]).gap * mm_per_m;
        min_gap          = std::min(min_gap, gap);
        max_gap          = std::max(max_gap, gap);
        sum += gap;
        outside += gap < 0;
      }
    std::cout << "skull " << s.skull_out << ": " << n_triangles
              << (segmented ?
                    " triangles, the inner surface of " + s.skull_image :
                    " triangles, gap " + number_text(s.skull_gap) + " mm")
              << ", in " << timer.wall_time()
              << " s; distance from the mesh's surface nodes to it: min "
              << min_gap << ", mean " << sum / nodes.size() << ", max "
              << max_gap << " mm" << std::endl;
    // The mesh's surface follows the image only to within
    // --facet-distance: a skull closer to the image than that may leave
    // surface nodes beyond it, whatever the sign of the gap.
    if (min_gap < 0)
      std::cout << "skull: " << outside << " of " << nodes.size()
                << " surface nodes of the mesh lie outside it (by up to "
                << -min_gap << " mm"
                << (segmented || s.skull_gap <= 0 ?
                      std::string() :
                      "; the mesh's surface follows the image to within "
                      "--facet-distance = " +
                        number_text(s.options.facet_distance) +
                        " mm, more than the gap")
                << "): the target crosses the skull; restshape iterates "
                   "towards their projection onto it (the admissible target)"
                << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  RestShape::install_interrupt_handlers();
  try
    {
      const ToolOptions cl(argc,
                           argv,
                           {"--image",
                            "--out",
                            "--cell-size",
                            "--facet-size",
                            "--facet-distance",
                            "--sliver-bound",
                            "--seed",
                            "--optimise",
                            "--optimise-iterations",
                            "--min-piece-fraction",
                            "--close-sulci",
                            "--skull-out",
                            "--skull-gap",
                            "--skull-closing",
                            "--skull-facet-size",
                            "--skull-image",
                            "--label-names",
                            "--label-map",
                            "--unlisted-labels"});
      if (cl.version())
        {
          std::cout << version_text("restshape-mesh") << std::endl;
          return 0;
        }
      if (cl.help())
        {
          std::cout << usage;
          return 0;
        }
      const MesherSettings s = read_settings(cl);
      // A segmented skull is checked before any work is written.
      const LabelledImage cavity =
        s.skull_image.empty() ?
          LabelledImage() :
          skull_cavity(read_labelled_image(s.skull_image, "--skull-image"),
                       s.skull_image,
                       "--skull-image");
      LabelledImage    image  = read_labelled_image(s.image_file, "--image");
      const LabelNames names  = prepare_labels(image, s);
      const auto       counts = image.label_counts();
      report_image(image, counts, s.image_file, names);
      check_mesh_sizes(image, counts, s);

      // The closed image is meshed; the skull comes from the image as read.
      LabelledImage closed;
      if (s.close_sulci > 0)
        closed = close_sulci(image, counts, s);
      // The image as read makes the skull; the closed one is not needed
      // after meshing.
      LabelledImage     &meshed_image = s.close_sulci > 0 ? closed : image;
      const ImageVolumes volumes{s.close_sulci > 0 ? closed.label_counts() :
                                                     counts,
                                 meshed_image.spacing()};
      const ImageComponents components = image_components(meshed_image);
      MeshDescription       mesh =
        make_mesh(meshed_image,
                  s,
                  s.close_sulci == 0 && !s.skull_out.empty(),
                  components);
      for (const auto &[label, name] : names.by_label())
        mesh.names.add(label, name, s.out, "--out");
      report_mesh(mesh, volumes, s);
      const MeshComponents pieces =
        check_components(mesh, components, volumes, s);

      MeshDescription in_metres = mesh;
      for (auto &p : in_metres.vertices)
        p *= 1e-3;
      check_mesh(in_metres, s.out);
      // The mesh and its skull appear together, once both are made.
      StagedFiles staged;
      write_gmsh(in_metres,
                 1e-3,
                 staged.stage(s.out),
                 surfaces_by_role(pieces),
                 {{outer_surface_tag, "outer_surface"},
                  {cavity_wall_tag, "cavity_walls"}});
      if (!s.skull_out.empty())
        write_skull(image, cavity, in_metres, s, staged.stage(s.skull_out));
      staged.commit("--out");
      std::cout << "wrote " << s.out << " (mm"
                << (names.empty() ? "" : ", with the names of its labels")
                << ")" << (s.skull_out.empty() ? "" : " and " + s.skull_out)
                << std::endl;
    }
  catch (const std::exception &exc)
    {
      std::cerr << "restshape-mesh: error: " << one_line_message(exc)
                << std::endl;
      return 1;
    }
  return 0;
}
