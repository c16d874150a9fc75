#include <deal.II/fe/mapping_fe_field.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/numerics/data_out.h>

#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/forward/forward_results.h>
#include <restshape/io/output.h>
#include <restshape/io/vtu_cell_data.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <regex>
#include <sstream>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    void
    write_number(std::ostream &out, const double v)
    {
      if (std::isfinite(v))
        out << std::setprecision(10) << v;
      else
        out << "null";
    }
    /// |v| of a three-component field, evaluated where DataOut writes.
    class Magnitude : public DataPostprocessorScalar<3>
    {
    public:
      Magnitude(const std::string &name)
        : DataPostprocessorScalar<3>(name, update_values)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<3> &inputs,
        std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int p = 0; p < inputs.solution_values.size(); ++p)
          {
            double s = 0;
            for (unsigned int c = 0; c < 3; ++c)
              s += inputs.solution_values[p][c] * inputs.solution_values[p][c];
            computed[p](0) = std::sqrt(s);
          }
      }
    };

    /// The cell data of a VTU piece, one value per locally owned cell in
    /// the order DataOut writes their patches: the label and (under MPI)
    /// the rank as integers, the element-averaged von Mises stress and
    /// the extra cell fields.
    std::vector<VtuCellArray>
    cell_arrays(const ForwardProblem         &problem,
                const std::vector<CellField> &extra)
    {
      const MPI_Comm comm = problem.discretization()
                              .dof_handler()
                              .get_triangulation()
                              .get_communicator();
      std::vector<VtuCellArray> arrays = {{"label", true, {}},
                                          {"von_mises_Pa", false, {}},
                                          {"pressure_Pa", false, {}},
                                          {"volume_ratio", false, {}}};
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        arrays.push_back({"subdomain", true, {}});
      for (const CellField &f : extra)
        arrays.push_back({f.name, false, {}});
      const Vector<float> stress = von_mises_stress(problem);
      const VolumeFields  volume = volume_fields(problem);
      for (const auto &cell :
           problem.discretization().dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int i = cell->active_cell_index();
            arrays[0].values.push_back(cell->material_id());
            arrays[1].values.push_back(stress[i]);
            arrays[2].values.push_back(volume.pressure[i]);
            arrays[3].values.push_back(volume.volume_ratio[i]);
            unsigned int a = 4;
            if (arrays.size() > 4 + extra.size())
              arrays[a++].values.push_back(cell->subdomain_id());
            for (const CellField &f : extra)
              arrays[a++].values.push_back(f.values[i]);
          }
      return arrays;
    }
  } // namespace

  double
  OutputWriter::length_scale() const
  {
    return 1. / length_unit;
  }

  void
  Summary::set(const std::string &key, const Value &value)
  {
    for (auto &entry : entries)
      if (entry.first == key)
        {
          entry.second = value;
          return;
        }
    entries.emplace_back(key, value);
  }

  void
  remove_previous_results(const std::string &directory)
  {
    namespace fs = std::filesystem;
    static const std::regex ours(
      "summary\\.json|parameters\\.prm|solution\\.(pvd|visit)|"
      "(solution-[0-9]+|prestressed_state|scenario(_[^/]+)?)(\\.[0-9]+)?\\.(vtu|pvtu)|"
      "iterations\\.csv|convergence\\.(csv|txt)|nodes\\.csv|"
      "rest_shape\\.msh|prestress_comparison\\.csv|scenario(_[^/]+)?\\.csv|label_names\\.txt|"
      ".*\\.tmp-[0-9]+");
    std::error_code ec;
    for (const auto &entry : fs::directory_iterator(directory, ec))
      if (entry.is_regular_file(ec) &&
          std::regex_match(entry.path().filename().string(), ours))
        fs::remove(entry.path(), ec);
  }

  bool
  Summary::has(const std::string &key) const
  {
    for (const auto &entry : entries)
      if (entry.first == key)
        return true;
    return false;
  }

  namespace
  {
    /// The length of the valid UTF-8 sequence at @p i of @p text (0: the
    /// byte there does not begin one).
    std::size_t
    utf8_length(const std::string &text, const std::size_t i)
    {
      const auto        b = static_cast<unsigned char>(text[i]);
      const std::size_t n = b >= 0xf0 && b <= 0xf4 ? 4 :
                            b >= 0xe0              ? 3 :
                            b >= 0xc2 && b < 0xe0  ? 2 :
                                                     0;
      if (n == 0 || i + n > text.size())
        return 0;
      for (std::size_t k = 1; k < n; ++k)
        if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80)
          return 0;
      return n;
    }
  } // namespace

  void
  write_json_string(std::ostream &out, const std::string &text)
  {
    out << '"';
    for (std::size_t i = 0; i < text.size(); ++i)
      {
        const char c = text[i];
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\')
          out << '\\' << c;
        else if (c == '\n')
          out << "\\n";
        else if (c == '\t')
          out << "\\t";
        else if (u >= 0x20 && u < 0x7f)
          out << c;
        else if (const std::size_t n = u > 0x7f ? utf8_length(text, i) : 0;
                 n > 0)
          {
            out << text.substr(i, n);
            i += n - 1;
          }
        else
          {
            // A control character, or a byte that is not UTF-8 (as
            // Latin-1).
            char code[8];
            std::snprintf(code, sizeof(code), "\\u%04x", unsigned(u));
            out << code;
          }
      }
    out << '"';
  }

  void
  Summary::write(std::ostream &out) const
  {
    out << "{\n";
    for (unsigned int i = 0; i < entries.size(); ++i)
      {
        out << "  ";
        write_json_string(out, entries[i].first);
        out << ": ";
        const Value &v = entries[i].second;
        if (const double *x = std::get_if<double>(&v))
          write_number(out, *x);
        else if (const long *n = std::get_if<long>(&v))
          out << *n;
        else if (const bool *b = std::get_if<bool>(&v))
          out << (*b ? "true" : "false");
        else if (const std::string *s = std::get_if<std::string>(&v))
          write_json_string(out, *s);
        else
          {
            const auto &t = std::get<Tensor<1, 3>>(v);
            out << '[';
            for (unsigned int d = 0; d < 3; ++d)
              {
                write_number(out, t[d]);
                out << (d < 2 ? ", " : "]");
              }
          }
        out << (i + 1 < entries.size() ? ",\n" : "\n");
      }
    out << "}\n";
  }

  OutputWriter::OutputWriter(const std::string &directory,
                             const double       length_unit,
                             const MPI_Comm     comm)
    : length_unit_name(length_unit == 1.0 ? "m" : "mm")
    , directory(directory)
    , length_unit(length_unit)
    , comm(comm)
  {}

  std::string
  OutputWriter::path(const std::string &name) const
  {
    return directory + "/" + name;
  }

  void
  OutputWriter::write_text(
    const std::string                         &name,
    const std::function<void(std::ostream &)> &write) const
  {
    write_on_every_rank(
      comm,
      path(name),
      [&]() { write_file_atomically(path(name), write); },
      Utilities::MPI::this_mpi_process(comm) == 0);
  }

  void
  OutputWriter::try_write_text(
    const std::string                         &name,
    const std::function<void(std::ostream &)> &write) const
  {
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          write_file_atomically(path(name), write);
        }
      catch (const InputError &)
        {
          // The run already fails for a reason of its own.
        }
  }

  void
  OutputWriter::write_csv(const std::string                      &name,
                          const std::vector<std::string>         &header,
                          const std::vector<std::vector<double>> &rows) const
  {
    write_text(name, [&](std::ostream &out) {
      for (unsigned int i = 0; i < header.size(); ++i)
        out << header[i] << (i + 1 < header.size() ? "," : "\n");
      for (const auto &row : rows)
        for (unsigned int i = 0; i < row.size(); ++i)
          {
            write_number(out, row[i]);
            out << (i + 1 < row.size() ? "," : "\n");
          }
    });
  }

  void
  OutputWriter::write_fields(const ForwardProblem          &problem,
                             const unsigned int             step,
                             const double                   time,
                             const std::vector<NodalField> &extra_nodal,
                             const std::vector<CellField>  &extra_cell,
                             const std::string             &name)
  {
    const DoFHandler<3> &dof_handler = problem.discretization().dof_handler();
    const IndexSet      &owned = problem.discretization().locally_owned_dofs();
    const IndexSet &relevant = problem.discretization().locally_relevant_dofs();
    const double    to_unit  = 1. / length_unit;

    // Deformed geometry X + d, in the output length unit, as the Euler
    // vector of a MappingFEField.
    LinearAlgebra::distributed::Vector<double> euler(owned, relevant, comm);
    for (const Node &node : problem.discretization().owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        euler[node.dofs[c]] =
          (node.position[c] + problem.displacement()[node.dofs[c]]) * to_unit;
    euler.update_ghost_values();
    MappingFEField<3, 3, LinearAlgebra::distributed::Vector<double>> deformed(
      dof_handler, euler);

    // Displacement from the rest shape: d - w.
    VectorType displacement(owned, comm);
    displacement = problem.displacement();
    displacement -=
      problem.discretization().owned_copy(problem.rest_displacement());
    displacement *= to_unit;
    VectorType displacement_ghost(owned, relevant, comm);
    displacement_ghost = displacement;

    DataOut<3> data_out;
    data_out.attach_dof_handler(dof_handler);
    const auto as_vector =
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        3, DataComponentInterpretation::component_is_part_of_vector);
    const auto as_scalars =
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        3, DataComponentInterpretation::component_is_scalar);
    data_out.add_data_vector(
      displacement_ghost,
      std::vector<std::string>(3, "displacement_" + length_unit_name),
      DataOut<3>::type_dof_data,
      as_vector);
    std::vector<VectorType>                 scaled(extra_nodal.size());
    std::vector<std::unique_ptr<Magnitude>> magnitudes;
    for (unsigned int f = 0; f < extra_nodal.size(); ++f)
      {
        scaled[f].reinit(owned, relevant, comm);
        VectorType tmp(owned, comm);
        tmp = *extra_nodal[f].vector;
        tmp *= extra_nodal[f].scale;
        scaled[f]         = tmp;
        const bool vector = extra_nodal[f].names.size() == 1;
        data_out.add_data_vector(
          scaled[f],
          vector ? std::vector<std::string>(3, extra_nodal[f].names[0]) :
                   extra_nodal[f].names,
          DataOut<3>::type_dof_data,
          vector ? as_vector : as_scalars);
        if (!extra_nodal[f].magnitude_name.empty())
          {
            magnitudes.push_back(
              std::make_unique<Magnitude>(extra_nodal[f].magnitude_name));
            data_out.add_data_vector(scaled[f], *magnitudes.back());
          }
      }

    const unsigned int degree = problem.discretization().fe().degree;
    data_out.build_patches(deformed, degree, DataOut<3>::curved_inner_cells);
    DataOutBase::VtkFlags flags;
    flags.time = time;
    // zlib's fastest level, as the cell data's (vtu_cell_data.cc): deal.II's
    // default, its best compression, took 44 % of the P2 column's inverse
    // run (24 VTU files, tests/scenes/column_inverse_p2.prm).
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    // Lagrange cells for Q2 hexahedra. deal.II 9.4 writes P2 tetrahedra as
    // quadratic VTK tetrahedra (10 nodes) without this flag; with it, it
    // writes empty offsets and types, which no reader opens.
    flags.write_higher_order_cells =
      degree > 1 &&
      problem.discretization().fe().reference_cell().is_hyper_cube();
    data_out.set_flags(flags);
    const std::vector<VtuCellArray> cell_data =
      cell_arrays(problem, extra_cell);

    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const std::string  base =
      name.empty() ? "solution-" + Utilities::int_to_string(step, 4) : name;
    std::vector<std::string> pieces;
    for (unsigned int r = 0; r < n_ranks; ++r)
      pieces.push_back(n_ranks == 1 ?
                         base + ".vtu" :
                         base + "." + Utilities::int_to_string(r, 4) + ".vtu");
    write_on_every_rank(
      comm,
      path(pieces[rank]),
      [&]() {
        write_file_atomically(path(pieces[rank]), [&](std::ostream &out) {
          std::ostringstream vtu;
          data_out.write_vtu(vtu);
          out << add_cell_data(vtu.str(), cell_data);
        });
      },
      true);
    std::string record = pieces[0];
    if (n_ranks > 1)
      {
        record = base + ".pvtu";
        write_text(record, [&](std::ostream &out) {
          std::ostringstream pvtu;
          data_out.write_pvtu_record(pvtu, pieces);
          out << add_cell_data_to_record(pvtu.str(), cell_data);
        });
      }

    if (!name.empty())
      return;
    for (auto it = pvd_records.begin(); it != pvd_records.end();)
      it = (it->second == record) ? pvd_records.erase(it) : it + 1;
    pvd_records.emplace_back(time, record);
    for (auto it = visit_records.begin(); it != visit_records.end();)
      it = (it->second == pieces) ? visit_records.erase(it) : it + 1;
    visit_records.emplace_back(time, pieces);
    write_text("solution.pvd", [&](std::ostream &out) {
      DataOutBase::write_pvd_record(out, pvd_records);
    });
    write_text("solution.visit", [&](std::ostream &out) {
      DataOutBase::write_visit_record(out, visit_records);
    });
  }
} // namespace RestShape
