// Reading the mesh formats other codes write: VTK legacy and XML
// unstructured grids and Abaqus input files, beside gmsh (gmsh_io.h);
// read_mesh() picks the reader by the file's extension.
#ifndef restshape_mesh_mesh_formats_h
#define restshape_mesh_mesh_formats_h

#include <restshape/mesh/mesh_description.h>

#include <string>

namespace RestShape
{
  /**
   * Read a VTK legacy ASCII unstructured grid (.vtk, file versions up to
   * 5.1) into a description in metres: linear tetrahedra (VTK type 10) or
   * hexahedra (12), other 3d cells refused, lower-dimensional cells
   * ignored. Labels: the cell-data integer array named label, labels,
   * MaterialID, material_id, gmsh:physical, CellEntityIds or region (the
   * first found), else the only cell array. Throws InputError naming @p file
   * and @p parameter.
   */
  MeshDescription
  read_vtk_mesh(const std::string &file,
                const double       length_unit,
                const std::string &parameter);

  /**
   * Read a VTK XML unstructured grid (.vtu; one piece, little endian;
   * data arrays in ASCII, inline base64 or appended raw/base64 data,
   * uncompressed or zlib-compressed, 32- or 64-bit headers) into a
   * description in metres; cells and labels as for read_vtk_mesh().
   * Throws InputError naming @p file and @p parameter.
   */
  MeshDescription
  read_vtu_mesh(const std::string &file,
                const double       length_unit,
                const std::string &parameter);

  /**
   * Read an Abaqus input file (.inp): *Node and *Element blocks of type
   * C3D4 or C3D8 (other 3d types refused, 2d ones ignored), labels from
   * element sets (the ELSET= of an *Element block and *Elset blocks,
   * GENERATE ranges too): the sets are numbered 1, 2, ... in the order
   * they first appear and carry their names; an element in several sets
   * takes the last one. Throws InputError naming @p file and @p parameter.
   */
  MeshDescription
  read_abaqus_mesh(const std::string &file,
                   const double       length_unit,
                   const std::string &parameter);

  /**
   * Read a mesh by its extension: .msh (gmsh, any version), .vtk, .vtu or
   * .inp;
   * others are an InputError naming @p parameter and the formats.
   */
  MeshDescription
  read_mesh(const std::string &file,
            const double       length_unit,
            const std::string &parameter = "Mesh/File");

  /// The names of a mesh file's labels without reading its cells (gmsh
  /// $PhysicalNames, Abaqus element set names; none for VTK).
  LabelNames
  read_mesh_label_names(const std::string &file);
} // namespace RestShape

#endif
