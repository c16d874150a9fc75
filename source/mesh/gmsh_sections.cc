#include <restshape/base/input_error.h>
#include <restshape/mesh/gmsh_sections.h>

#include <fstream>
#include <sstream>

namespace RestShape
{
  namespace
  {
    /// The data lines of a section, up to its $End line; the first is its
    /// header. False if the file ends first.
    bool
    count_section_lines(std::istream      &in,
                        const std::string &end,
                        std::string       &header,
                        double            &n_lines)
    {
      std::string line;
      n_lines    = 0;
      bool first = true;
      while (std::getline(in, line))
        {
          if (!line.empty() && line.back() == '\r')
            line.pop_back();
          if (line == end)
            return true;
          if (line.find_first_not_of(" \t") == std::string::npos)
            continue;
          if (first)
            header = line;
          else
            ++n_lines;
          first = false;
        }
      return false;
    }

    /// Lines a section should have after its header: version 2 lists one
    /// line per node or element; version 4 a line per entity block plus a
    /// line per element, or two per node (tags, then coordinates).
    double
    expected_lines(const std::string &header,
                   const bool         version_4,
                   const bool         nodes,
                   double            &declared)
    {
      std::istringstream words(header);
      double             blocks = 0;
      if (version_4)
        words >> blocks;
      words >> declared;
      if (!words || declared < 0 || blocks < 0)
        return -1;
      if (!version_4)
        return declared;
      return blocks + (nodes ? 2 : 1) * declared;
    }
  } // namespace

  void
  check_gmsh_section_counts(const std::string &file,
                            const std::string &parameter)
  {
    std::ifstream in(file);
    std::string   line, format;
    if (!std::getline(in, line) || line.rfind("$MeshFormat", 0) != 0 ||
        !std::getline(in, format))
      return; // gmsh decides
    std::istringstream words(format);
    double             version = 0;
    int                binary  = 1;
    words >> version >> binary;
    if (!words || binary != 0 || (version < 2 || version >= 5) ||
        (version >= 3 && version < 4))
      return;
    const bool version_4 = version >= 4;
    while (std::getline(in, line))
      {
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        if (line != "$Nodes" && line != "$Elements")
          continue;
        const bool        nodes = line == "$Nodes";
        const std::string name  = nodes ? "nodes" : "elements";
        std::string       header;
        double            n_lines = 0, declared = 0;
        if (!count_section_lines(
              in, nodes ? "$EndNodes" : "$EndElements", header, n_lines))
          return; // truncated: gmsh reports it
        const double expected =
          expected_lines(header, version_4, nodes, declared);
        if (expected >= 0 && expected != n_lines)
          throw InputError(file,
                           parameter,
                           "$" + std::string(nodes ? "Nodes" : "Elements") +
                             " declares " + number_text(declared) + " " + name +
                             " but its section has " + number_text(n_lines) +
                             " lines where " + number_text(expected) +
                             " were expected; expected a well-formed gmsh "
                             ".msh mesh");
      }
  }
} // namespace RestShape
