// Meshes of simple bodies for tests and benchmarks (the shapes of the
// analytic cases), written to gmsh by restshape-gridgen.
#ifndef restshape_generated_meshes_h
#define restshape_generated_meshes_h

#include <deal.II/grid/tria.h>

namespace RestShape
{
  /**
   * A hemisphere of radius @p radius with its dome down: pole at the
   * origin, flat face at z = radius, centre of the sphere (0, 0, radius).
   * Hexahedra: deal.II's half ball refined @p refinements times on its
   * spherical manifold, then graded towards the pole: distances r from the
   * pole are scaled by (r / r_max)^((grading - 1)(1 - z / radius)), which
   * refines near the pole and leaves the flat top in place; the curved
   * boundary is projected back onto the sphere. A small contact zone at
   * the pole is resolved this way. Cells with a face on the flat top get label
   * 2, the others label 1. Units are those of @p radius.
   */
  void
  make_hemisphere(dealii::Triangulation<3> &tria,
                  const double              radius,
                  const unsigned int        refinements,
                  const double              grading);
} // namespace RestShape

#endif
