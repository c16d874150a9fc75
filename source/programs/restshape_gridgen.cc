// restshape-gridgen: structured meshes for tests and benchmarks.
//
//   restshape-gridgen --size LX,LY,LZ --subdivisions NX,NY,NZ
//       [--origin X,Y,Z] [--cell-type tetrahedra|tetrahedra24|hexahedra]
//       [--label L] [--slab AXIS:MIN:MAX:LABEL]... --out FILE.msh
//
// A box [origin, origin + size] (units as given, usually mm) split into
// NX x NY x NZ hexahedra, or each hexahedron into six tetrahedra (the
// Freudenthal split along the main diagonal, conforming across cells), or
// into 24 tetrahedra through face and cell centres (deal.II's
// convert_hypercube_to_simplex_mesh: a mesh with the symmetries of the box).
// Every cell gets label L (default 1), then each --slab relabels the cells
// whose centroid satisfies MIN <= coordinate AXIS <= MAX.
//
//   restshape-gridgen --hemisphere R --refinements N [--grading G]
//       [--cell-type ...] --out FILE.msh
//
// A hemisphere, dome down with its pole at the origin (see
// make_hemisphere()): label 2 for the cells on the flat top, 1 below.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>

#include <restshape/base/command_line.h>
#include <restshape/base/input_error.h>
#include <restshape/base/interruption.h>
#include <restshape/base/mpi_start.h>
#include <restshape/base/version.h>
#include <restshape/mesh/generated_meshes.h>
#include <restshape/mesh/gmsh_io.h>
#include <restshape/mesh/labelled_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

namespace
{
  /// --help: the usage comment at the top of this file.
  const char *const usage =
    "restshape-gridgen: structured meshes for tests and benchmarks.\n"
    "\n"
    "  restshape-gridgen --size LX,LY,LZ --subdivisions NX,NY,NZ\n"
    "      [--origin X,Y,Z] [--cell-type tetrahedra|tetrahedra24|hexahedra]\n"
    "      [--label L] [--slab AXIS:MIN:MAX:LABEL]... --out FILE.msh\n"
    "\n"
    "A box [origin, origin + size] (units as given, usually mm) split into\n"
    "NX x NY x NZ hexahedra, or each hexahedron into six tetrahedra (the\n"
    "Freudenthal split along the main diagonal, conforming across cells), or\n"
    "into 24 tetrahedra through face and cell centres (deal.II's\n"
    "convert_hypercube_to_simplex_mesh: a mesh with the symmetries of the box).\n"
    "Every cell gets label L (default 1), then each --slab relabels the cells\n"
    "whose centroid satisfies MIN <= coordinate AXIS <= MAX.\n"
    "\n"
    "  restshape-gridgen --hemisphere R --refinements N [--grading G]\n"
    "      [--cell-type ...] --out FILE.msh\n"
    "\n"
    "A hemisphere, dome down with its pole at the origin (see\n"
    "make_hemisphere()): label 2 for the cells on the flat top, 1 below.\n";
} // namespace

using namespace dealii;
using namespace RestShape;

namespace
{
  struct Slab
  {
    unsigned int axis;
    double       min, max;
    Label        label;
  };

  /// --slab AXIS:MIN:MAX:LABEL.
  Slab
  parse_slab(const std::string &text)
  {
    const std::string option = "--slab";
    const auto        f      = Utilities::split_string_list(text, ':');
    if (f.size() != 4 || f[0].size() != 1 || f[0][0] < 'x' || f[0][0] > 'z')
      throw InputError("",
                       option,
                       "got '" + text +
                         "'; expected AXIS:MIN:MAX:LABEL, e.g. z:0:5:2");
    const double label = parse_number(option, f[3]);
    if (label < 0 || label > max_label || label != std::floor(label))
      throw InputError("",
                       option,
                       "label '" + f[3] + "' of '" + text +
                         "' is not a whole number from 0 to " +
                         std::to_string(max_label));
    return {unsigned(f[0][0] - 'x'),
            parse_number(option, f[1]),
            parse_number(option, f[2]),
            Label(label)};
  }
  /// Options of the box.
  struct BoxSettings
  {
    std::array<double, 3>       size, origin;
    std::array<unsigned int, 3> n{{1, 1, 1}};
    std::string                 cell_type;
    Label                       label = 1;
    std::vector<Slab>           slabs;
  };

  BoxSettings
  read_box(const ToolOptions &cl)
  {
    BoxSettings b;
    b.size                  = cl.triple("--size", {{1, 1, 1}});
    b.origin                = cl.triple("--origin", {{0, 0, 0}});
    const auto subdivisions = cl.triple("--subdivisions", {{1, 1, 1}});
    for (unsigned int d = 0; d < 3; ++d)
      {
        b.n[d] = static_cast<unsigned int>(subdivisions[d]);
        if (subdivisions[d] < 1 || b.n[d] != subdivisions[d])
          throw InputError("",
                           "--subdivisions",
                           "expected three whole numbers >= 1, got '" +
                             cl.text("--subdivisions") + "'");
      }
    b.cell_type = cl.choice("--cell-type",
                            "tetrahedra",
                            {"tetrahedra", "tetrahedra24", "hexahedra"});
    b.label     = cl.integer("--label", 1, 0, max_label);
    for (const std::string &slab : cl.all("--slab"))
      b.slabs.push_back(parse_slab(slab));
    return b;
  }

  /// Write @p tria as gmsh and say what was written.
  void
  write_triangulation(const Triangulation<3> &tria,
                      const std::string      &out,
                      const std::string      &cells)
  {
    write_gmsh(
      tria, [&](unsigned int v) { return tria.get_vertices()[v]; }, 1.0, out);
    std::cout << out << ": " << tria.n_active_cells() << " " << cells << ", "
              << tria.n_used_vertices() << " vertices" << std::endl;
  }

  void
  write_hemisphere(const ToolOptions &cl, const std::string &out)
  {
    const double       radius      = cl.non_negative("--hemisphere", 0);
    const unsigned int refinements = cl.integer("--refinements", 0, 0, 8);
    const double       grading     = cl.positive("--grading", 1);
    const std::string  cell_type =
      cl.choice("--cell-type",
                "tetrahedra",
                {"tetrahedra", "tetrahedra24", "hexahedra"});
    Triangulation<3> hexes, tria;
    make_hemisphere(hexes, radius, refinements, grading);
    if (cell_type != "hexahedra")
      GridGenerator::convert_hypercube_to_simplex_mesh(hexes, tria);
    else
      tria.copy_triangulation(hexes);
    write_triangulation(tria, out, "cells");
  }

  /// The six tetrahedra of the Freudenthal split of hexahedron @p hex
  /// (vertices in deal.II's lexicographic order): one per path 0 -> 7
  /// along the axes, positively oriented.
  void
  add_freudenthal_tetrahedra(const std::array<unsigned int, 8> &hex,
                             const Label                        label,
                             MeshDescription                   &mesh)
  {
    std::array<unsigned int, 3> axes{{0, 1, 2}};
    do
      {
        CellData<3>  cell(4);
        unsigned int corner = 0;
        cell.vertices[0]    = hex[0];
        for (unsigned int s = 0; s < 3; ++s)
          {
            corner |= 1u << axes[s];
            cell.vertices[s + 1] = hex[corner];
          }
        const auto &v = mesh.vertices;
        const auto &c = cell.vertices;
        if (cross_product_3d(v[c[1]] - v[c[0]], v[c[2]] - v[c[0]]) *
              (v[c[3]] - v[c[0]]) <
            0)
          std::swap(cell.vertices[1], cell.vertices[2]);
        cell.material_id = label;
        mesh.cells.push_back(cell);
      }
    while (std::next_permutation(axes.begin(), axes.end()));
  }

  /// The box as hexahedra, or (cell type tetrahedra) six tetrahedra each;
  /// labels from --label and the slabs at each hexahedron's centre.
  MeshDescription
  box_mesh(const BoxSettings &b)
  {
    const auto     &n = b.n;
    MeshDescription mesh;
    const auto      vertex_index =
      [&](unsigned int i, unsigned int j, unsigned int k) {
        return (k * (n[1] + 1) + j) * (n[0] + 1) + i;
      };
    for (unsigned int k = 0; k <= n[2]; ++k)
      for (unsigned int j = 0; j <= n[1]; ++j)
        for (unsigned int i = 0; i <= n[0]; ++i)
          mesh.vertices.emplace_back(b.origin[0] + b.size[0] * i / n[0],
                                     b.origin[1] + b.size[1] * j / n[1],
                                     b.origin[2] + b.size[2] * k / n[2]);
    for (unsigned int k = 0; k < n[2]; ++k)
      for (unsigned int j = 0; j < n[1]; ++j)
        for (unsigned int i = 0; i < n[0]; ++i)
          {
            std::array<unsigned int, 8> hex;
            for (unsigned int v = 0; v < 8; ++v)
              hex[v] = vertex_index(i + (v & 1),
                                    j + ((v >> 1) & 1),
                                    k + ((v >> 2) & 1));
            Point<3> centre;
            for (const unsigned int v : hex)
              centre += mesh.vertices[v] / 8.;
            Label label = b.label;
            for (const Slab &s : b.slabs)
              if (centre[s.axis] >= s.min && centre[s.axis] <= s.max)
                label = s.label;
            if (b.cell_type == "tetrahedra")
              {
                add_freudenthal_tetrahedra(hex, label, mesh);
                continue;
              }
            CellData<3> cell(8);
            cell.vertices.assign(hex.begin(), hex.end());
            cell.material_id = label;
            mesh.cells.push_back(cell);
          }
    return mesh;
  }

  void
  write_box(const BoxSettings &b, const std::string &out)
  {
    const MeshDescription mesh = box_mesh(b);
    if (b.cell_type == "tetrahedra24")
      {
        Triangulation<3> hexes, tria;
        hexes.create_triangulation(mesh.vertices, mesh.cells, SubCellData());
        GridGenerator::convert_hypercube_to_simplex_mesh(hexes, tria);
        write_triangulation(tria, out, "tetrahedra");
        return;
      }
    write_gmsh(mesh, 1.0, out);
    std::cout << out << ": " << mesh.cells.size() << " " << b.cell_type << ", "
              << mesh.vertices.size() << " vertices" << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  RestShape::install_interrupt_handlers();
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const ToolOptions cl(argc,
                           argv,
                           {"--size",
                            "--origin",
                            "--subdivisions",
                            "--cell-type",
                            "--label",
                            "--slab",
                            "--out",
                            "--hemisphere",
                            "--refinements",
                            "--grading"});
      if (cl.version())
        {
          std::cout << version_text("restshape-gridgen") << std::endl;
          return 0;
        }
      if (cl.help())
        {
          std::cout << usage;
          return 0;
        }
      const std::string out =
        cl.required("--out", "the output mesh's file name (.msh)");
      if (cl.non_negative("--hemisphere", 0) > 0)
        write_hemisphere(cl, out);
      else
        write_box(read_box(cl), out);
    }
  catch (const std::exception &exc)
    {
      std::cerr << "restshape-gridgen: error: " << one_line_message(exc)
                << std::endl;
      return 1;
    }
  return 0;
}
