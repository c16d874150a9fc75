// restshape-mesh: a labelled NIfTI image to a labelled tetrahedral mesh
// (CGAL Mesh_3), and optionally the skull surface around it.
//
//   restshape-mesh --image LABELS.nii[.gz] --out MESH.msh
//       [--cell-size MM] [--facet-size MM] [--facet-distance MM]
//       [--sliver-bound DEG] [--seed N] [--min-piece-fraction F]
//       [--close-sulci MM]
//       [--skull-out SKULL.stl --skull-gap MM [--skull-closing MM]
//        [--skull-facet-size MM]]
//
// The mesh is written as gmsh 2.2 in mm, every tetrahedron with its image
// label as physical volume tag. The skull is a closed, outward-oriented
// surface at --skull-gap mm from the labelled region (0: touching it;
// negative: cutting into it, as a segmented skull can), for
// Contact/Obstacle file with Side = inside. Before the offset, the labelled
// region is closed morphologically with a ball of --skull-closing mm
// (default 10; 0 = none), so that the skull bridges sulci and fissures.
// Pieces of the mesh joined to the rest only at vertices or edges (Mesh_3
// leaves them where labelled voxels touch diagonally) and smaller than
// --min-piece-fraction times the largest piece (default 0.01; 0 keeps all)
// are removed: they would hinge freely and stop Newton's method.
// --close-sulci MM (default 0 = off) closes the labelled region with a ball
// of MM mm before meshing: sulci and gaps narrower than about 2 MM are
// filled with the neighbouring label, so that the mesh's surface has no
// pinched edges there (two folds touching along an edge, where CSF
// pressure crushes the cells). The report counts the pinched edges left.
#include <deal.II/base/timer.h>

#include <restshape/base/atomic_file.h>
#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/contact/obstacle.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/labelled_mesh.h>
#include <restshape/mesh/mesh_checks.h>
#include <restshape/mesh/mesh_pieces.h>
#include <restshape/mesher/image_mesher.h>
#include <restshape/mesher/image_morphology.h>
#include <restshape/mesher/labelled_image.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>

namespace
{
  /// --help: the usage comment at the top of this file.
  const char *const usage =
    "restshape-mesh: a labelled NIfTI image to a labelled tetrahedral mesh\n"
    "(CGAL Mesh_3), and optionally the skull surface around it.\n"
    "\n"
    "  restshape-mesh --image LABELS.nii[.gz] --out MESH.msh\n"
    "      [--cell-size MM] [--facet-size MM] [--facet-distance MM]\n"
    "      [--sliver-bound DEG] [--seed N] [--min-piece-fraction F]\n"
    "      [--close-sulci MM]\n"
    "      [--skull-out SKULL.stl --skull-gap MM [--skull-closing MM]\n"
    "       [--skull-facet-size MM]]\n"
    "\n"
    "The mesh is written as gmsh 2.2 in mm, every tetrahedron with its image\n"
    "label as physical volume tag. The skull is a closed, outward-oriented\n"
    "surface at --skull-gap mm from the labelled region (0: touching it;\n"
    "negative: cutting into it, as a segmented skull can), for\n"
    "Contact/Obstacle file with Side = inside. Before the offset, the labelled\n"
    "region is closed morphologically with a ball of --skull-closing mm\n"
    "(default 10; 0 = none), so that the skull bridges sulci and fissures.\n"
    "Pieces of the mesh joined to the rest only at vertices or edges (Mesh_3\n"
    "leaves them where labelled voxels touch diagonally) and smaller than\n"
    "--min-piece-fraction times the largest piece (default 0.01; 0 keeps all)\n"
    "are removed: they would hinge freely and stop Newton's method.\n"
    "--close-sulci MM (default 0 = off) closes the labelled region with a ball\n"
    "of MM mm before meshing: sulci and gaps narrower than about 2 MM are\n"
    "filled with the neighbouring label, so that the mesh's surface has no\n"
    "pinched edges there (two folds touching along an edge, where CSF\n"
    "pressure crushes the cells). The report counts the pinched edges left.\n";
} // namespace

using namespace RestShape;

namespace
{
  /// The nodes on the boundary of a tetrahedral mesh (faces of one cell).
  std::set<unsigned int>
  boundary_nodes(const MeshDescription &mesh)
  {
    std::map<std::array<unsigned int, 3>, unsigned int> faces;
    for (const auto &cell : mesh.cells)
      for (unsigned int m = 0; m < 4; ++m)
        {
          std::array<unsigned int, 3> face;
          for (unsigned int i = 0, f = 0; i < 4; ++i)
            if (i != m)
              face[f++] = cell.vertices[i];
          std::sort(face.begin(), face.end());
          ++faces[face];
        }
    std::set<unsigned int> nodes;
    for (const auto &[face, count] : faces)
      if (count == 1)
        nodes.insert(face.begin(), face.end());
    return nodes;
  }

  /// The skull's facet distance (mm): within half the gap of the exact
  /// surface, so that the mesh stays inside; for a gap <= 0 (a skull that
  /// touches or cuts the mesh) a tenth of its facet size, so that where it
  /// cuts is decided by the gap, not by its chords.
  double
  skull_facet_distance(const double facet_distance,
                       const double gap,
                       const double facet_size)
  {
    constexpr double chord_fraction = 0.1;
    return gap > 0 ? std::min(facet_distance, gap / 2) :
                     std::min(facet_distance, chord_fraction * facet_size);
  }
} // namespace

int
main(int argc, char **argv)
{
  if (wants_help(argc, argv))
    {
      std::cout << usage;
      return 0;
    }
  try
    {
      std::string      image_file, out, skull_out;
      ImageMeshOptions options;
      double           skull_gap = 0, skull_facet_size = 0, skull_closing = 10;
      bool             skull_gap_given    = false;
      double           min_piece_fraction = 0.01, close_sulci = 0;
      bool             facet_size_given = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (i + 1 >= argc)
            throw InputError(
              "",
              arg,
              "missing value (restshape-mesh --help lists the options)");
          const std::string value = argv[++i];
          if (arg == "--image")
            image_file = value;
          else if (arg == "--out")
            out = value;
          else if (arg == "--skull-out")
            skull_out = value;
          else if (arg == "--cell-size")
            options.cell_size = parse_positive(arg, value);
          else if (arg == "--facet-size")
            {
              options.facet_size = parse_positive(arg, value);
              facet_size_given   = true;
            }
          else if (arg == "--facet-distance")
            options.facet_distance = parse_positive(arg, value);
          else if (arg == "--sliver-bound")
            options.sliver_bound = parse_positive(arg, value);
          else if (arg == "--seed")
            options.seed =
              static_cast<unsigned int>(parse_positive(arg, value));
          else if (arg == "--min-piece-fraction")
            {
              min_piece_fraction =
                value == "0" ? 0. : parse_positive(arg, value);
              if (min_piece_fraction > 1)
                throw InputError("",
                                 arg,
                                 "got " + value +
                                   " (expected a fraction from 0 to 1)");
            }
          else if (arg == "--close-sulci")
            close_sulci = value == "0" ? 0. : parse_positive(arg, value);
          else if (arg == "--skull-gap")
            {
              skull_gap       = parse_number(arg, value);
              skull_gap_given = true;
            }
          else if (arg == "--skull-closing")
            skull_closing = value == "0" ? 0. : parse_positive(arg, value);
          else if (arg == "--skull-facet-size")
            skull_facet_size = parse_positive(arg, value);
          else
            throw InputError(
              "",
              arg,
              "unknown option; expected --image, --out, --cell-size, "
              "--facet-size, --facet-distance, --sliver-bound, --seed, "
              "--min-piece-fraction, --close-sulci, --skull-out, --skull-gap, "
              "--skull-closing or --skull-facet-size");
        }
      if (image_file.empty())
        throw InputError("",
                         "--image",
                         "no image given; expected a labelled NIfTI image");
      if (out.empty())
        throw InputError("",
                         "--out",
                         "no output mesh given; expected a .msh file name");
      if (!skull_out.empty() && !skull_gap_given)
        throw InputError("",
                         "--skull-gap",
                         "--skull-out needs the CSF gap in mm");
      if (skull_out.empty() && skull_gap_given)
        throw InputError("",
                         "--skull-out",
                         "--skull-gap given without an output surface");
      if (!facet_size_given)
        options.facet_size = options.cell_size;
      if (skull_facet_size == 0)
        skull_facet_size = options.facet_size;
      // Fail on an unwritable destination before the meshing work.
      for (const std::string &file : {out, skull_out})
        if (!file.empty())
          ensure_writable_directory(
            std::filesystem::path(file).parent_path().empty() ?
              "." :
              std::filesystem::path(file).parent_path().string(),
            file == out ? "--out" : "--skull-out");

      LabelledImage image = read_labelled_image(image_file, "--image");
      const auto    h     = image.spacing();
      std::cout << std::setprecision(4) << "image " << image_file << ": "
                << image.size[0] << "x" << image.size[1] << "x" << image.size[2]
                << " voxels of " << h[0] << "x" << h[1] << "x" << h[2]
                << " mm; labels";
      for (const auto &[label, count] : image.label_counts())
        std::cout << " " << label << " (" << count * h[0] * h[1] * h[2] / 1000
                  << " cm^3)";
      std::cout << std::endl;

      dealii::Timer timer;
      // The closed image is meshed; the skull comes from the image as read
      // (a copy only when both are asked for: an atlas is large).
      LabelledImage closed_image;
      if (close_sulci > 0)
        {
          std::size_t n_labelled = 0;
          for (const auto &[label, count] : image.label_counts())
            n_labelled += count;
          closed_image = skull_out.empty() ? std::move(image) : image;
          const ClosedVoxels closed =
            close_labelled_image(closed_image, close_sulci);
          std::cout << "closed sulci narrower than about " << 2 * close_sulci
                    << " mm (--close-sulci " << close_sulci
                    << "): " << closed.n_added << " voxels, "
                    << closed.volume_mm3 / 1000 << " cm^3 ("
                    << 100. * closed.n_added / n_labelled
                    << " % of the labelled volume) added, in "
                    << timer.wall_time() << " s" << std::endl;
          timer.restart();
        }
      const LabelledImage &meshed_image =
        close_sulci > 0 ? closed_image : image;
      MeshDescription mesh = mesh_labelled_image(meshed_image, options);
      if (mesh.cells.empty())
        throw InputError(
          image_file,
          "--cell-size",
          "the mesh is empty: the sizes are too large for the labelled "
          "region; expected sizes well below its extent");
      std::cout << "Mesh_3 (cell size " << options.cell_size
                << " mm, facet size " << options.facet_size
                << " mm, facet distance " << options.facet_distance
                << " mm): " << mesh.vertices.size() << " nodes, "
                << mesh.cells.size() << " tetrahedra in " << timer.wall_time()
                << " s" << std::endl;
      const RemovedPieces removed =
        remove_small_pieces(mesh, min_piece_fraction);
      if (removed.n_pieces > 0)
        std::cout << "removed " << removed.n_cells << " tetrahedra in "
                  << removed.n_pieces
                  << " pieces joined to the body only at vertices or edges "
                     "(smaller than --min-piece-fraction "
                  << min_piece_fraction << " of the largest)" << std::endl;
      const unsigned int n_pieces = face_connected_pieces(mesh).n_cells.size();
      if (n_pieces > 1)
        std::cout << "warning: the mesh has " << n_pieces
                  << " pieces not joined by faces" << std::endl;

      const unsigned int n_pinched = n_pinched_boundary_edges(mesh);
      std::cout << "pinched boundary edges (two folds of the surface touching "
                   "along an edge): "
                << n_pinched
                << (n_pinched > 0 && close_sulci == 0 ?
                      "; CSF pressure on them can crush the cells there, "
                      "--close-sulci removes them" :
                      "")
                << std::endl;

      // The mesh is in mm here.
      const SurfaceGap gap =
        narrowest_surface_gap(mesh, options.facet_distance);
      if (std::isfinite(gap.width))
        std::cout << describe_surface_gap(gap.width, gap.location) << "; "
                  << gap.n_narrow
                  << " surface faces face another fold closer than the facet "
                     "distance (thin flaps of tissue border such gaps; "
                     "--close-sulci fills them)"
                  << std::endl;

      const MeshQuality                    q = mesh_quality(mesh);
      std::map<unsigned int, unsigned int> n_per_label;
      for (const auto &cell : mesh.cells)
        ++n_per_label[cell.material_id];
      for (const auto &[label, count] : meshed_image.label_counts())
        {
          const auto volume = q.volume_per_label.find(label);
          std::cout << "  label " << label << ": " << n_per_label[label]
                    << " tetrahedra, "
                    << (volume == q.volume_per_label.end() ?
                          0. :
                          volume->second / 1000)
                    << " cm^3 (image " << count * h[0] * h[1] * h[2] / 1000
                    << " cm^3)" << std::endl;
          if (n_per_label[label] == 0)
            std::cout << "  warning: label " << label
                      << " has no tetrahedron; reduce --cell-size to resolve it"
                      << std::endl;
        }
      std::cout << "quality: dihedral angles " << q.min_dihedral_deg << " to "
                << q.max_dihedral_deg << " deg (" << q.n_below_10_deg
                << " cells below 10 deg), radius-edge ratio mean "
                << q.mean_radius_edge << ", max " << q.max_radius_edge
                << std::endl;

      MeshDescription in_metres = mesh;
      for (auto &p : in_metres.vertices)
        p *= 1e-3;
      check_mesh(in_metres, out);
      write_gmsh(in_metres, 1e-3, out);
      std::cout << "wrote " << out << " (mm)" << std::endl;

      if (!skull_out.empty())
        {
          timer.restart();
          const unsigned int n_triangles =
            write_enclosing_surface(image,
                                    skull_gap,
                                    skull_closing,
                                    skull_facet_size,
                                    skull_facet_distance(options.facet_distance,
                                                         skull_gap,
                                                         skull_facet_size),
                                    skull_out);
          const Obstacle skull(skull_out, 1e-3, true);
          double         min_gap = 1e9, max_gap = 0, sum = 0;
          unsigned int   outside = 0;
          const auto     nodes   = boundary_nodes(mesh);
          for (const unsigned int v : nodes)
            {
              const double gap = skull.gap(in_metres.vertices[v]).gap * 1e3;
              min_gap          = std::min(min_gap, gap);
              max_gap          = std::max(max_gap, gap);
              sum += gap;
              outside += gap < 0;
            }
          std::cout << "skull " << skull_out << ": " << n_triangles
                    << " triangles, gap " << skull_gap << " mm, in "
                    << timer.wall_time()
                    << " s; distance from the mesh's surface nodes to it: min "
                    << min_gap << ", mean " << sum / nodes.size() << ", max "
                    << max_gap << " mm" << std::endl;
          if (skull_gap > 0 && min_gap <= 0)
            throw InputError(
              skull_out,
              "--skull-gap",
              "a surface node of the mesh lies outside the skull (gap " +
                number_text(min_gap) +
                " mm); expected a gap larger than --facet-distance");
          if (min_gap < 0)
            std::cout << "skull: " << outside << " of " << nodes.size()
                      << " surface nodes of the mesh lie outside it (by up "
                         "to "
                      << -min_gap
                      << " mm): the target crosses the skull; restshape "
                         "iterates towards their projection onto it "
                         "(the admissible target)"
                      << std::endl;
        }
    }
  catch (const std::exception &exc)
    {
      std::cerr << "restshape-mesh: error: " << one_line_message(exc)
                << std::endl;
      return 1;
    }
  return 0;
}
