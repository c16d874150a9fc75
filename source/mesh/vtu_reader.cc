// VTK XML unstructured grids (.vtu): ASCII, inline base64 and appended
// (raw or base64) data arrays, uncompressed or zlib-compressed, 32- or
// 64-bit headers, as ParaView, meshio and VTK write them.
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <restshape/base/input_error.h>
#include <restshape/mesh/mesh_formats.h>
#include <restshape/mesh/vtk_grid.h>
#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace RestShape
{
  namespace
  {
    using boost::property_tree::ptree;
    using Bytes = std::vector<unsigned char>;

    const std::string vtu_format = "a VTK XML unstructured grid (.vtu)";

    /// What every data array of the file shares, and how to fail.
    struct VtuFile
    {
      std::string file, parameter;
      bool        header_64       = false; // header_type="UInt64"
      bool        compressed      = false; // vtkZLibDataCompressor
      bool        appended_base64 = false;
      std::string appended; // the bytes after '_' of <AppendedData>

      [[noreturn]] void
      fail(const std::string &message) const
      {
        throw InputError(file, parameter, message + "; expected " + vtu_format);
      }
    };

    Bytes
    decode_base64(const std::string &text, const VtuFile &f)
    {
      static const std::string alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      Bytes        out;
      unsigned int buffer = 0;
      int          bits   = 0;
      for (const char c : text)
        {
          if (c == '=' || std::isspace(static_cast<unsigned char>(c)))
            continue;
          const auto value = alphabet.find(c);
          if (value == std::string::npos)
            f.fail(std::string("'") + c + "' in base64 data");
          buffer = (buffer << 6) | unsigned(value);
          bits += 6;
          if (bits >= 8)
            {
              bits -= 8;
              out.push_back((buffer >> bits) & 0xff);
            }
        }
      return out;
    }

    std::uint64_t
    header_word(const Bytes &bytes, const std::size_t i, const VtuFile &f)
    {
      const std::size_t size = f.header_64 ? 8 : 4;
      if ((i + 1) * size > bytes.size())
        f.fail("a data array ends inside its header");
      std::uint64_t word = 0;
      std::memcpy(&word, bytes.data() + i * size, size); // little endian
      return word;
    }

    /// Words in the header of a binary block: one (the byte count), or
    /// three plus one per compressed block.
    std::size_t
    header_words(const Bytes &first_words, const VtuFile &f)
    {
      return f.compressed ? 3 + header_word(first_words, 0, f) : 1;
    }

    /// The largest ratio of data to zlib-compressed bytes.
    constexpr std::uint64_t max_zlib_ratio = 1032;

    /// The data bytes of a binary block whose header is followed by
    /// @p payload: as stored, or the zlib blocks uncompressed.
    Bytes
    block_data(const Bytes &header, Bytes payload, const VtuFile &f)
    {
      if (!f.compressed)
        {
          payload.resize(
            std::min<std::size_t>(payload.size(), header_word(header, 0, f)));
          return payload;
        }
      const std::uint64_t n_blocks = header_word(header, 0, f);
      const std::uint64_t block    = header_word(header, 1, f),
                          last     = header_word(header, 2, f);
      Bytes       data;
      std::size_t at = 0;
      for (std::uint64_t b = 0; b < n_blocks; ++b)
        {
          const std::uint64_t stored = header_word(header, 3 + b, f);
          uLongf size = (b + 1 == n_blocks && last != 0) ? last : block;
          if (at + stored > payload.size())
            f.fail("a compressed data array is shorter than its header says");
          // zlib expands by at most 1032:1.
          if (size > max_zlib_ratio * stored + 1024)
            f.fail("a compressed block claims " + std::to_string(size) +
                   " bytes from " + std::to_string(stored));
          const std::size_t old = data.size();
          data.resize(old + size);
          if (uncompress(
                data.data() + old, &size, payload.data() + at, stored) != Z_OK)
            f.fail("a zlib block of a data array does not uncompress");
          data.resize(old + size);
          at += stored;
        }
      return data;
    }

    /// A binary block in base64: the header encoded on its own and then the
    /// data (VTK, deal.II), or both in one stream.
    Bytes
    base64_block(const std::string &text, const VtuFile &f)
    {
      std::string clean;
      for (const char c : text)
        if (!std::isspace(static_cast<unsigned char>(c)))
          clean += c;
      const std::size_t word = f.header_64 ? 8 : 4;
      const auto  chars = [](std::size_t bytes) { return (bytes + 2) / 3 * 4; };
      const Bytes first = decode_base64(clean.substr(0, chars(word)), f);
      const std::size_t n_header = header_words(first, f) * word;
      const std::size_t split    = chars(n_header);
      if (split <= clean.size() && clean[split - 1] == '=')
        return block_data(decode_base64(clean.substr(0, split), f),
                          decode_base64(clean.substr(split), f),
                          f);
      const Bytes all = decode_base64(clean, f);
      if (all.size() < n_header)
        f.fail("a data array ends inside its header");
      return block_data(Bytes(all.begin(), all.begin() + n_header),
                        Bytes(all.begin() + n_header, all.end()),
                        f);
    }

    /// A block of the raw appended data at @p offset.
    Bytes
    raw_block(const std::size_t offset, const VtuFile &f)
    {
      if (offset >= f.appended.size())
        f.fail("a data array's offset lies beyond the appended data");
      const auto *start =
        reinterpret_cast<const unsigned char *>(f.appended.data() + offset);
      const Bytes       rest(start, start + (f.appended.size() - offset));
      const std::size_t word     = f.header_64 ? 8 : 4;
      const std::size_t n_header = header_words(rest, f) * word;
      if (n_header > rest.size())
        f.fail("a data array ends inside its header");
      return block_data(Bytes(rest.begin(), rest.begin() + n_header),
                        Bytes(rest.begin() + n_header, rest.end()),
                        f);
    }

    /// Numbers of the given VTK type from little-endian bytes.
    std::vector<double>
    numbers(const Bytes &bytes, const std::string &type, const VtuFile &f)
    {
      const auto convert = [&](auto zero) {
        using T = decltype(zero);
        std::vector<double> out(bytes.size() / sizeof(T));
        for (std::size_t i = 0; i < out.size(); ++i)
          {
            T value;
            std::memcpy(&value, bytes.data() + i * sizeof(T), sizeof(T));
            out[i] = static_cast<double>(value);
          }
        return out;
      };
      if (type == "Int8")
        return convert(std::int8_t());
      if (type == "UInt8")
        return convert(std::uint8_t());
      if (type == "Int16")
        return convert(std::int16_t());
      if (type == "UInt16")
        return convert(std::uint16_t());
      if (type == "Int32")
        return convert(std::int32_t());
      if (type == "UInt32")
        return convert(std::uint32_t());
      if (type == "Int64")
        return convert(std::int64_t());
      if (type == "UInt64")
        return convert(std::uint64_t());
      if (type == "Float32")
        return convert(float());
      if (type == "Float64")
        return convert(double());
      f.fail("data array type '" + type + "'");
    }

    /// A count or offset attribute ("NumberOfCells"): a whole number >= 0,
    /// 0 if absent.
    std::size_t
    attribute_count(const ptree       &element,
                    const std::string &name,
                    const VtuFile     &f)
    {
      const std::string text         = element.get("<xmlattr>." + name, "0");
      char             *end          = nullptr;
      errno                          = 0;
      const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
      if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0)
        f.fail(name + "=\"" + text + "\"; expected a whole number >= 0");
      return value;
    }

    /// The values of a <DataArray>, @p expected of them.
    std::vector<double>
    data_array(const ptree &array, const std::size_t expected, const VtuFile &f)
    {
      const std::string   name   = array.get("<xmlattr>.Name", "");
      const std::string   type   = array.get("<xmlattr>.type", "");
      const std::string   format = array.get("<xmlattr>.format", "ascii");
      std::vector<double> values;
      if (format == "ascii")
        {
          std::istringstream in(array.data());
          double             x;
          while (in >> x)
            values.push_back(x);
        }
      else if (format == "binary")
        values = numbers(base64_block(array.data(), f), type, f);
      else if (format == "appended")
        {
          const std::size_t offset = attribute_count(array, "offset", f);
          if (offset > f.appended.size())
            f.fail("data array '" + name +
                   "' has an offset beyond the appended data");
          values = numbers(f.appended_base64 ?
                             base64_block(f.appended.substr(offset), f) :
                             raw_block(offset, f),
                           type,
                           f);
        }
      else
        f.fail("data array '" + name + "' has format '" + format + "'");
      if (values.size() != expected)
        f.fail("data array '" + name + "' has " +
               std::to_string(values.size()) + " values where " +
               std::to_string(expected) + " belong");
      for (const double v : values)
        if (!std::isfinite(v))
          f.fail("data array '" + name + "' holds a value that is not finite");
      return values;
    }

    /// The <DataArray> named @p name among the children of @p parent.
    const ptree &
    named_array(const ptree &parent, const std::string &name, const VtuFile &f)
    {
      for (const auto &[tag, child] : parent)
        if (tag == "DataArray" && child.get("<xmlattr>.Name", "") == name)
          return child;
      f.fail("no '" + name + "' array in <Cells>");
    }

    /// XML elements nested deeper than this are refused before parsing
    /// (the parser recurses once per level: 200,000 levels crashed it).
    constexpr unsigned int max_nesting = 64;

    void
    check_nesting(const std::string &text, const VtuFile &f)
    {
      unsigned int depth = 0;
      for (std::size_t at = text.find('<'); at != std::string::npos;
           at             = text.find('<', at + 1))
        {
                      const char next = at + 1 < text.size() ? text[at + 1] : '\0';
                      if (next == '/')
            depth -= depth > 0;
          else if (next != '?' && next != '!')
            {
                          const auto close = text.find('>', at);
                          if (close != std::string::npos && text[close - 1] == '/')
                continue; // <empty/>
              if (++depth > max_nesting)
                f.fail("XML elements nested more than " +
                       std::to_string(max_nesting) + " deep");
            }
        }
    }

    /// Split off the appended data (raw bytes are not XML) and parse the
    /// rest.
    ptree
    parse(std::string text, VtuFile &f)
    {
      const auto tag = text.find("<AppendedData");
      if (tag != std::string::npos)
        {
          const auto open  = text.find('>', tag);
          const auto start = text.find('_', open);
          const auto end   = text.rfind("</AppendedData>");
          if (open == std::string::npos || start == std::string::npos ||
              end == std::string::npos || end < start)
            f.fail("a malformed <AppendedData> section");
          f.appended_base64 =
            text.substr(tag, open - tag).find("base64") != std::string::npos;
          f.appended = text.substr(start + 1, end - start - 1);
          text       = text.substr(0, tag) + "</VTKFile>";
        }
      check_nesting(text, f);
      std::istringstream in(text);
      ptree              tree;
      try
        {
          boost::property_tree::read_xml(in, tree);
        }
      catch (const std::exception &e)
        {
          f.fail("not readable as XML (" + std::string(e.what()) + ")");
        }
      return tree;
    }

    /// Header attributes: an unstructured grid, little endian, no other
    /// compressor than zlib.
    const ptree &
    read_header(const ptree &tree, VtuFile &f)
    {
      const auto root = tree.get_child_optional("VTKFile");
      if (!root || root->get("<xmlattr>.type", "") != "UnstructuredGrid")
        f.fail("no <VTKFile type=\"UnstructuredGrid\">");
      if (root->get("<xmlattr>.byte_order", "LittleEndian") != "LittleEndian")
        f.fail("big-endian data");
      f.header_64 = root->get("<xmlattr>.header_type", "UInt32") == "UInt64";
      const std::string compressor = root->get("<xmlattr>.compressor", "");
      if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
        f.fail("compressor '" + compressor + "'");
      f.compressed    = !compressor.empty();
      const auto grid = root->get_child_optional("UnstructuredGrid");
      if (!grid || grid->count("Piece") != 1)
        f.fail("not exactly one <Piece> in <UnstructuredGrid>");
      return grid->get_child("Piece");
    }

    /// The values, which must be whole numbers (a connectivity of 0.5, a
    /// label of 1.5 were truncated).
    std::vector<long>
    whole_numbers(const std::vector<double> &values,
                  const std::string         &name,
                  const VtuFile             &f)
    {
      for (const double v : values)
        if (v != std::floor(v) || std::abs(v) > 9.2e18)
          f.fail("data array '" + name + "' holds " + number_text(v) +
                 ", not a whole number");
      return std::vector<long>(values.begin(), values.end());
    }
  } // namespace

  MeshDescription
  read_vtu_mesh(const std::string &file,
                const double       length_unit,
                const std::string &parameter)
  {
    VtuFile f;
    f.file      = file;
    f.parameter = parameter;
    std::ifstream in(file, std::ios::binary);
    if (!in)
      f.fail("not a readable file");
    std::ostringstream text;
    text << in.rdbuf();
    const ptree       tree     = parse(text.str(), f);
    const ptree      &piece    = read_header(tree, f);
    const std::size_t n_points = attribute_count(piece, "NumberOfPoints", f),
                      n_cells  = attribute_count(piece, "NumberOfCells", f);
    const auto points          = piece.get_child_optional("Points.DataArray");
    const auto cells           = piece.get_child_optional("Cells");
    if (!points || !cells)
      f.fail("no <Points> or no <Cells> in the <Piece>");
    VtkGrid                   grid;
    const std::vector<double> xyz = data_array(*points, 3 * n_points, f);
    for (std::size_t p = 0; p < n_points; ++p)
      grid.points.emplace_back(length_unit * xyz[3 * p],
                               length_unit * xyz[3 * p + 1],
                               length_unit * xyz[3 * p + 2]);
    grid.types =
      whole_numbers(data_array(named_array(*cells, "types", f), n_cells, f),
                    "types",
                    f);
    const std::vector<long> offsets =
      whole_numbers(data_array(named_array(*cells, "offsets", f), n_cells, f),
                    "offsets",
                    f);
    if (n_cells > 0 && offsets.back() < 0)
      f.fail("the offsets of <Cells> are negative");
    const ptree &connectivity_array = named_array(*cells, "connectivity", f);
    const std::vector<long> connectivity =
      whole_numbers(data_array(connectivity_array,
                               n_cells == 0 ? 0 : std::size_t(offsets.back()),
                               f),
                    "connectivity",
                    f);
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        const long begin = c == 0 ? 0 : offsets[c - 1];
        if (begin > offsets[c] || offsets[c] > long(connectivity.size()))
          f.fail("the offsets of <Cells> are not increasing");
        grid.cells.emplace_back(connectivity.begin() + begin,
                                connectivity.begin() + offsets[c]);
      }
    const ptree no_arrays;
    const auto  cell_data = piece.get_child_optional("CellData");
    for (const auto &[tag, array] : cell_data ? *cell_data : no_arrays)
      if (tag == "DataArray" &&
          array.get("<xmlattr>.NumberOfComponents", 1) == 1)
        grid.arrays[array.get("<xmlattr>.Name", "")] =
          whole_numbers(data_array(array, n_cells, f),
                        array.get("<xmlattr>.Name", ""),
                        f);
    return vtk_grid_to_mesh(grid, file, parameter, vtu_format);
  }
} // namespace RestShape
