// Checks of a mesh as read.
#include <restshape/base/input_error.h>
#include <restshape/mesh/mesh_checks.h>
#include <restshape/mesh/mesh_parameters.h>

#include <array>
#include <cmath>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /**
     * Signed volume measure at every corner of a cell (tetrahedron: one
     * value; hexahedron: the eight corner Jacobian determinants), and the
     * longest edge, for the orientation check.
     */
    std::vector<double>
    corner_determinants(const std::vector<Point<3>> &v,
                        const CellData<3>           &cell,
                        double                      &longest_edge)
    {
      const auto         &i = cell.vertices;
      std::vector<double> dets;
      longest_edge = 0;
      for (unsigned int a = 0; a < i.size(); ++a)
        for (unsigned int b = a + 1; b < i.size(); ++b)
          longest_edge = std::max(longest_edge, v[i[a]].distance(v[i[b]]));
      if (i.size() == 4)
        dets.push_back(triple_product(v[i[1]] - v[i[0]],
                                      v[i[2]] - v[i[0]],
                                      v[i[3]] - v[i[0]]));
      else
        for (unsigned int corner = 0; corner < 8; ++corner)
          {
            // Edge vectors along the three reference directions, taken in
            // the positive direction whatever the corner.
            std::array<Tensor<1, 3>, 3> e;
            for (unsigned int d = 0; d < 3; ++d)
              {
                const unsigned int bit   = 1u << d;
                const unsigned int lower = corner & ~bit;
                e[d]                     = v[i[lower | bit]] - v[i[lower]];
              }
            dets.push_back(triple_product(e[0], e[1], e[2]));
          }
      return dets;
    }
  } // namespace

  void
  check_mesh(const MeshDescription &mesh, const std::string &file)
  {
    for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
      for (unsigned int d = 0; d < 3; ++d)
        if (!std::isfinite(mesh.vertices[v][d]))
          throw InputError(file,
                           mesh_file_parameter,
                           "vertex " + std::to_string(v + 1) +
                             " has a coordinate that is not a finite number");

    unsigned int n_inverted = 0, n_degenerate = 0, first_bad = 0;
    for (unsigned int c = 0; c < mesh.cells.size(); ++c)
      {
        double     longest_edge = 0;
        const auto dets =
          corner_determinants(mesh.vertices, mesh.cells[c], longest_edge);
        const double scale    = std::pow(longest_edge, 3);
        bool         inverted = false, degenerate = !(longest_edge > 0);
        for (const double det : dets)
          {
            if (std::abs(det) <= 1e-12 * scale)
              degenerate = true;
            else if (det < 0)
              inverted = true;
          }
        if ((inverted || degenerate) && n_inverted + n_degenerate == 0)
          first_bad = c;
        n_inverted += (inverted && !degenerate);
        n_degenerate += degenerate;
      }
    if (n_inverted + n_degenerate > 0)
      throw InputError(file,
                       mesh_file_parameter,
                       std::to_string(n_inverted) + " inverted and " +
                         std::to_string(n_degenerate) +
                         " zero-volume cells (first: cell " +
                         std::to_string(first_bad + 1) +
                         " in file order); expected every cell with positive "
                         "volume in gmsh vertex order");
  }
} // namespace RestShape
