// The walls of a mesh's cavities: the closed parts of its surface that
// enclose no tissue (the ventricles of a brain), apart from its outer
// surfaces.
#ifndef restshape_mesh_cavity_walls_h
#define restshape_mesh_cavity_walls_h

#include <deal.II/grid/tria.h>

#include <restshape/mesh/labelled_mesh.h>

#include <array>
#include <set>
#include <vector>

namespace RestShape
{
  /**
   * The surface of a mesh (LabelledMesh::at_surface()) split into its
   * connected parts (faces that share a vertex), from every rank. A part
   * is a cavity wall if the volume it encloses, by the divergence theorem
   * over its faces with the body's outward normals (1/3 sum x . n dA), is
   * negative: the region it bounds lies outside the body, inside it. An
   * outer surface encloses a positive volume. Collective over the mesh's
   * communicator.
   */
  class CavityWalls
  {
  public:
    explicit CavityWalls(const LabelledMesh &mesh);

    /// Whether face @p f of @p cell (owned or ghost, at the surface) lies
    /// on a cavity wall.
    bool
    contains(const dealii::CellAccessor<3, 3> &cell,
             const unsigned int                f) const;
    /// The number of cavities (connected walls) and of outer surfaces.
    unsigned int
    n_cavities() const
    {
      return cavities;
    }
    unsigned int
    n_outer_surfaces() const
    {
      return outer;
    }
    /// The volume each cavity encloses (m^3, mesh geometry).
    const std::vector<double> &
    cavity_volumes() const
    {
      return volumes;
    }

  private:
    /// A face by its sorted vertex coordinates (the same on every rank).
    using FaceKey = std::vector<double>;
    std::set<FaceKey>   walls;
    unsigned int        cavities = 0, outer = 0;
    std::vector<double> volumes;
  };
} // namespace RestShape

#endif
