// VTK cell data added to the VTU text deal.II writes.
#include <deal.II/base/utilities.h>

#include <restshape/io/vtu_cell_data.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace RestShape
{
  namespace
  {
    /// How the arrays of a VTU file are stored.
    enum class Encoding
    {
      ascii,
      base64,
      zlib_base64
    };

    /// The value of attribute @p name in the first element @p tag of
    /// @p text ("" if absent).
    std::string
    attribute(const std::string &text,
              const std::string &tag,
              const std::string &name)
    {
      const auto start = text.find("<" + tag);
      if (start == std::string::npos)
        return "";
      const auto end = text.find('>', start);
      const auto at  = text.find(" " + name + "=\"", start);
      if (at == std::string::npos || at > end)
        return "";
      const auto value = at + name.size() + 3;
      return text.substr(value, text.find('"', value) - value);
    }

    Encoding
    encoding_of(const std::string &vtu)
    {
      if (attribute(vtu, "VTKFile", "compressor") == "vtkZLibDataCompressor")
        return Encoding::zlib_base64;
      return vtu.find("format=\"binary\"") != std::string::npos ?
               Encoding::base64 :
               Encoding::ascii;
    }

    /// The raw little-endian bytes of the values (Int32 or Float64).
    std::vector<unsigned char>
    raw_bytes(const std::vector<double> &values, const bool integer)
    {
      std::vector<unsigned char> bytes;
      const std::size_t          size = integer ? 4 : 8;
      bytes.resize(values.size() * size);
      for (std::size_t i = 0; i < values.size(); ++i)
        if (integer)
          {
            const std::int32_t v = static_cast<std::int32_t>(values[i]);
            std::memcpy(&bytes[i * size], &v, size);
          }
        else
          std::memcpy(&bytes[i * size], &values[i], size);
      return bytes;
    }

    /// VTK's binary header (UInt32 words) followed by the data, each
    /// base64-encoded on its own.
    std::string
    binary_text(const std::vector<double> &values,
                const bool                 integer,
                const Encoding             encoding)
    {
      const std::vector<unsigned char> raw = raw_bytes(values, integer);
      std::vector<std::uint32_t>       header;
      std::vector<unsigned char>       data;
      if (encoding == Encoding::base64)
        {
          header = {static_cast<std::uint32_t>(raw.size())};
          data   = raw;
        }
      else
        {
          // One block: number of blocks, block size, size of the last
          // (partial) block, compressed sizes.
          uLongf size = compressBound(raw.size());
          data.resize(size);
          if (compress2(
                data.data(), &size, raw.data(), raw.size(), Z_BEST_SPEED) !=
              Z_OK)
            throw std::runtime_error("zlib could not compress a VTU array");
          data.resize(size);
          header = {1,
                    static_cast<std::uint32_t>(raw.size()),
                    static_cast<std::uint32_t>(raw.size()),
                    static_cast<std::uint32_t>(size)};
        }
      std::vector<unsigned char> header_bytes(header.size() * 4);
      std::memcpy(header_bytes.data(), header.data(), header_bytes.size());
      return dealii::Utilities::encode_base64(header_bytes) +
             dealii::Utilities::encode_base64(data);
    }

    std::string
    type_name(const VtuCellArray &array)
    {
      return array.integer ? "Int32" : "Float64";
    }

    /// One <DataArray> of cell data, each value repeated @p repeat times.
    std::string
    data_array(const VtuCellArray &array,
               const std::size_t   repeat,
               const Encoding      encoding)
    {
      std::vector<double> values;
      values.reserve(array.values.size() * repeat);
      for (const double v : array.values)
        values.insert(values.end(), repeat, v);
      std::ostringstream out;
      out << "    <DataArray type=\"" << type_name(array) << "\" Name=\""
          << array.name << "\" format=\""
          << (encoding == Encoding::ascii ? "ascii" : "binary") << "\">\n";
      if (encoding == Encoding::ascii || values.empty())
        {
          out.precision(17);
          for (const double v : values)
            {
              if (array.integer)
                out << static_cast<std::int32_t>(v) << ' ';
              else
                out << v << ' ';
            }
        }
      else
        out << binary_text(values, array.integer, encoding);
      out << "\n    </DataArray>\n";
      return out.str();
    }
  } // namespace

  namespace
  {
    /// @p text with @p section on the line after @p after, or before
    /// @p otherwise if @p text has no @p after.
    std::string
    insert_section(std::string        text,
                   const std::string &section,
                   const std::string &after,
                   const std::string &otherwise)
    {
      const auto at = text.find(after);
      text.insert(at == std::string::npos ? text.find(otherwise) :
                                            text.find('\n', at) + 1,
                  section);
      return text;
    }
  } // namespace

  std::string
  add_cell_data(const std::string &vtu, const std::vector<VtuCellArray> &arrays)
  {
    if (arrays.empty())
      return vtu;
    const std::size_t n_cells =
      std::stoul(attribute(vtu, "Piece", "NumberOfCells"));
    const std::size_t n_values = arrays[0].values.size();
    if (n_values == 0 ? n_cells != 0 : n_cells % n_values != 0)
      throw std::runtime_error("VTU cell data: " + std::to_string(n_values) +
                               " values for " + std::to_string(n_cells) +
                               " cells");
    const std::size_t repeat   = n_values == 0 ? 1 : n_cells / n_values;
    const Encoding    encoding = encoding_of(vtu);
    std::string       section  = "  <CellData>\n";
    for (const VtuCellArray &array : arrays)
      section += data_array(array, repeat, encoding);
    section += "  </CellData>\n";
    return insert_section(vtu, section, "</PointData>", "</Piece>");
  }

  std::string
  add_cell_data_to_record(const std::string               &pvtu,
                          const std::vector<VtuCellArray> &arrays)
  {
    if (arrays.empty())
      return pvtu;
    std::string section = "    <PCellData>\n";
    for (const VtuCellArray &array : arrays)
      section += "      <PDataArray type=\"" + type_name(array) + "\" Name=\"" +
                 array.name + "\"/>\n";
    section += "    </PCellData>\n";
    return insert_section(pvtu, section, "</PPointData>", "<PPoints>");
  }
} // namespace RestShape
