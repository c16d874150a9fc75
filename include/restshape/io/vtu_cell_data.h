// Cell data that deal.II's VTU writer cannot carry: integer arrays, and
// values per cell rather than per patch node.
#ifndef restshape_io_vtu_cell_data_h
#define restshape_io_vtu_cell_data_h

#include <string>
#include <vector>

namespace RestShape
{
  /**
   * One array of VTK cell data: one value per deal.II patch (a cell of the
   * mesh), written as Int32 (labels, ranks: exact up to 2,147,483,647) or
   * Float64. deal.II 9.4 writes every field as Float32 point data, so a
   * label above 16,777,216 comes out rounded, and a value per cell is
   * repeated at each of its patch's points.
   */
  struct VtuCellArray
  {
    std::string         name;
    bool                integer = false;
    std::vector<double> values;
  };

  /**
   * The VTU text @p vtu (as deal.II's DataOut::write_vtu() wrote it, one
   * patch per mesh cell) with @p arrays added as a <CellData> section. Each
   * patch's value is repeated over the VTK cells of that patch (the
   * NumberOfCells of the piece divided by the number of values). The data
   * are encoded as the file's own (zlib-compressed base64 when it names
   * vtkZLibDataCompressor, plain base64 when binary, else ASCII).
   */
  std::string
  add_cell_data(const std::string               &vtu,
                const std::vector<VtuCellArray> &arrays);

  /// The PVTU record @p pvtu with the <PCellData> entries of @p arrays.
  std::string
  add_cell_data_to_record(const std::string               &pvtu,
                          const std::vector<VtuCellArray> &arrays);
} // namespace RestShape

#endif
