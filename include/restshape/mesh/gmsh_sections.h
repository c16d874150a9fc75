// The counts a gmsh ASCII file declares, checked against what it lists.
#ifndef restshape_mesh_gmsh_sections_h
#define restshape_mesh_gmsh_sections_h

#include <string>

namespace RestShape
{
  /**
   * For an ASCII gmsh file (version 2 or 4), compare the number of lines of
   * its $Nodes and $Elements sections with the counts their headers
   * declare: gmsh's reader ignores what follows the declared count and
   * stops early on a shorter list. Throws InputError naming @p parameter on
   * a mismatch; binary files and other versions are left to gmsh.
   */
  void
  check_gmsh_section_counts(const std::string &file,
                            const std::string &parameter);
} // namespace RestShape

#endif
