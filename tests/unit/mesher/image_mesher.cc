// The image mesher against a shape with a known answer.
//
// tests/data/sphere_labels.nii (tests/data/make_images.py): 2 mm voxels, the
// sform mirrors x and shifts the origin; label 1 is a ball of radius 18 mm
// around (16, 4, 34) mm, label 2 a ball of radius 8 mm inside it.
//  1. The header's map is honoured: voxel (12, 12, 12) is at the centre.
//  2. Mesh_3 (cell size 4 mm): every cell positively oriented despite the
//     mirror (check_mesh), the volumes of both labels match the voxelised
//     balls, the mesh is centred on (16, 4, 34) mm, quality is reported and
//     no sliver is left below 5 degrees.
//  3. The enclosing surface at 3 mm is accepted as an obstacle (closed,
//     outward, no self-intersection) and holds every surface node of the
//     mesh inside at a distance close to 3 mm.
#include <restshape/contact/obstacle.h>
#include <restshape/mesh/mesh_checks.h>
#include <restshape/mesh/mesh_description.h>
#include <restshape/mesher/image_mesher.h>

#include <cmath>
#include <map>

#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

int
main()
{
  const LabelledImage image =
    read_labelled_image("tests/data/sphere_labels.nii", "--image");
  const Point<3> centre(16, 4, 34);
  check_below("voxel (12,12,12) at the ball's centre (mm)",
              image.position(12, 12, 12).distance(centre),
              1e-12);
  const auto counts = image.label_counts();

  ImageMeshOptions options;
  options.cell_size      = 4;
  options.facet_size     = 4;
  options.facet_distance = 0.5;
  const MeshDescription mesh =
    mesh_labelled_image(image, options, image_components(image));

  MeshDescription in_metres = mesh;
  for (auto &p : in_metres.vertices)
    p *= 1e-3;
  bool valid = true;
  try
    {
      check_mesh(in_metres, "sphere");
    }
  catch (const std::exception &exc)
    {
      std::cout << exc.what() << std::endl;
      valid = false;
    }
  check_below("inverted or degenerate cells (0 = none)", valid ? 0 : 1, 0);

  // Volume per label against the voxel count, and the centroid.
  const MeshQuality q = mesh_quality(mesh);
  Tensor<1, 3>      moment;
  for (const auto &cell : mesh.cells)
    {
      const auto &v = mesh.vertices;
      const auto &c = cell.vertices;
      moment += cross_product_3d(v[c[1]] - v[c[0]], v[c[2]] - v[c[0]]) *
                (v[c[3]] - v[c[0]]) / 6 *
                (Tensor<1, 3>(v[c[0]]) + v[c[1]] + v[c[2]] + v[c[3]]) / 4;
    }
  std::map<unsigned int, double> volume = q.volume_per_label;
  const double                   total  = q.total_volume;
  const double                   voxel  = 8; // mm^3
  for (const unsigned int label : {1u, 2u})
    check_between("volume of label " + std::to_string(label) +
                    " / voxelised volume",
                  volume[label] / (counts.at(label) * voxel),
                  0.93,
                  1.03);
  check_between("volume of label 2 / (4/3 pi 8^3)",
                volume[2] / (4. / 3 * M_PI * 512),
                0.85,
                1.15);
  check_below("distance of the mesh centroid from (16, 4, 34) mm",
              (Point<3>(moment / total)).distance(centre),
              0.3);

  std::cout << mesh.vertices.size() << " nodes, " << mesh.cells.size()
            << " tetrahedra; dihedral angles " << q.min_dihedral_deg << " to "
            << q.max_dihedral_deg << " deg, radius-edge ratio max "
            << q.max_radius_edge << std::endl;
  check_between("smallest dihedral angle (deg)", q.min_dihedral_deg, 5, 90);

  // The enclosing surface.
  const unsigned int n_triangles =
    write_enclosing_surface(image, 3, 0, 3, 0.3, "image_mesher_skull.off");
  const Obstacle skull("image_mesher_skull.off", 1e-3, true);
  std::cout << "enclosing surface: " << n_triangles << " triangles"
            << std::endl;
  double min_gap = 1e9, max_gap = -1e9;
  for (const auto &p : in_metres.vertices)
    if (std::abs(p.distance(centre * 1e-3) - 18e-3) < 2e-3)
      {
        const double g = skull.gap(p).gap * 1e3;
        min_gap        = std::min(min_gap, g);
        max_gap        = std::max(max_gap, g);
      }
  check_between(
    "smallest distance of a surface node to the enclosing surface (mm)",
    min_gap,
    2,
    3.5);
  check_between(
    "largest distance of a surface node to the enclosing surface (mm)",
    max_gap,
    2.5,
    4.5);
  std::remove("image_mesher_skull.off");
  return exit_code();
}
