// The face lists of an ASCII OFF file, checked before CGAL's scanner reads
// them (it converts a negative index to an unsigned one: undefined
// behaviour, and a vertex far out of range).
#ifndef restshape_contact_off_faces_h
#define restshape_contact_off_faces_h

#include <string>

namespace RestShape
{
  /**
   * For an ASCII OFF file (any header variant ending in OFF, 3d): every
   * face line gives a vertex count of at least 3 followed by as many
   * whole-number indices from 0 to the number of vertices minus 1. Throws
   * InputError naming @p file and @p parameter otherwise; binary OFF and
   * other formats are left to CGAL.
   */
  void
  check_off_faces(const std::string &file, const std::string &parameter);
} // namespace RestShape

#endif
