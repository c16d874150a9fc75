// Checks of a mesh as read: finite coordinates, positive cell volumes.
#ifndef restshape_mesh_mesh_checks_h
#define restshape_mesh_mesh_checks_h

#include <restshape/mesh/mesh_description.h>

#include <string>

namespace RestShape
{
  /**
   * Check coordinates and cell orientation: every vertex finite, every cell
   * with a positive Jacobian determinant at its corners (deal.II's vertex
   * order). Throws InputError naming @p file for NaN coordinates and for
   * inverted or zero-volume cells.
   */
  void
  check_mesh(const MeshDescription &mesh, const std::string &file);

} // namespace RestShape

#endif
