// Reading a mesh with a third-party reader in a child process (see
// base/child_process.h): a reader that crashes or corrupts its heap on a
// malformed file (gmsh does, on some) takes only the child with it.
#ifndef restshape_mesh_child_reader_h
#define restshape_mesh_child_reader_h

#include <restshape/mesh/mesh_description.h>

#include <functional>
#include <string>

namespace RestShape
{
  /**
   * Call @p read in a forked child and return its vertices, cells, targets
   * and mass ratios (not the names) through a pipe. An InputError the child
   * throws is thrown again here with its message; a child that dies (a
   * signal, a sanitizer's exit) is an InputError naming @p file and
   * @p parameter with @p expected. Without fork(), @p read runs here.
   */
  MeshDescription
  read_in_child_process(const std::function<MeshDescription()> &read,
                        const std::string                      &file,
                        const std::string                      &parameter,
                        const std::string                      &expected);
} // namespace RestShape

#endif
