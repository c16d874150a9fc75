#include <restshape/base/child_process.h>
#include <restshape/mesh/child_reader.h>

#include <cstdint>
#include <string>

namespace RestShape
{
  namespace
  {
    void
    put_points(const std::vector<dealii::Point<3>> &points, ByteWriter &out)
    {
      out.put<std::uint64_t>(points.size());
      for (const auto &p : points)
        for (unsigned int d = 0; d < 3; ++d)
          out.put<double>(p[d]);
    }

    std::vector<dealii::Point<3>>
    get_points(ByteReader &in)
    {
      std::vector<dealii::Point<3>> points(in.checked_count(24));
      for (auto &p : points)
        for (unsigned int d = 0; d < 3; ++d)
          p[d] = in.get<double>();
      return points;
    }

    std::string
    serialize(const MeshDescription &mesh)
    {
      ByteWriter out;
      put_points(mesh.vertices, out);
      out.put<std::uint64_t>(mesh.cells.size());
      for (const auto &cell : mesh.cells)
        {
          out.put<std::uint32_t>(cell.vertices.size());
          for (const unsigned int v : cell.vertices)
            out.put<std::uint32_t>(v);
          out.put<std::uint32_t>(cell.material_id);
        }
      put_points(mesh.targets, out);
      out.put<std::uint64_t>(mesh.mass_ratios.size());
      for (const double r : mesh.mass_ratios)
        out.put<double>(r);
      put_points(mesh.rest_nodes.edge_nodes, out);
      put_points(mesh.rest_nodes.equilibria, out);
      return out.str();
    }

    MeshDescription
    deserialize(ByteReader &in)
    {
      MeshDescription mesh;
      mesh.vertices = get_points(in);
      mesh.cells.resize(in.checked_count(8));
      for (auto &cell : mesh.cells)
        {
          cell.vertices.resize(in.get<std::uint32_t>());
          for (auto &v : cell.vertices)
            v = in.get<std::uint32_t>();
          cell.material_id = in.get<std::uint32_t>();
        }
      mesh.targets = get_points(in);
      mesh.mass_ratios.resize(in.checked_count(8));
      for (double &r : mesh.mass_ratios)
        r = in.get<double>();
      mesh.rest_nodes.edge_nodes = get_points(in);
      mesh.rest_nodes.equilibria = get_points(in);
      return mesh;
    }
  } // namespace

  MeshDescription
  read_in_child_process(const std::function<MeshDescription()> &read,
                        const std::string                      &file,
                        const std::string                      &parameter,
                        const std::string                      &expected)
  {
    MeshDescription mesh;
    run_in_child_process([&]() { return serialize(read()); },
                         [&mesh](ByteReader &in) { mesh = deserialize(in); },
                         file,
                         parameter,
                         expected);
    return mesh;
  }
} // namespace RestShape
