// Results on disk: VTU/PVTU fields with .pvd (ParaView) and .visit (VisIt)
// records, summary.json and .csv tables. Every file is written atomically.
#ifndef restshape_output_h
#define restshape_output_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <restshape/forward/forward_problem.h>

#include <functional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace RestShape
{
  /// @p text as a JSON string: quoted, with quotes, backslashes and
  /// control characters escaped (bytes above 127 pass: UTF-8 stays).
  void
  write_json_string(std::ostream &out, const std::string &text);

  /// A flat JSON object with keys in insertion order.
  class Summary
  {
  public:
    using Value =
      std::variant<double, long, bool, std::string, dealii::Tensor<1, 3>>;
    void
    set(const std::string &key, const Value &value);
    /// Whether @p key has a value.
    bool
    has(const std::string &key) const;
    void
    write(std::ostream &out) const;

  private:
    std::vector<std::pair<std::string, Value>> entries;
  };

  /// A field with one value per DoF (a displacement-like vector field, or
  /// three scalar fields stored in the x, y, z slots of each node).
  struct NodalField
  {
    const VectorType        *vector; // owned or ghosted
    std::vector<std::string> names;  // one name: vector field; three: scalars
    double                   scale = 1;
    std::string magnitude_name     = ""; // also write |vector| under this name
  };

  struct CellField
  {
    std::string           name;
    dealii::Vector<float> values; // per active cell
  };

  /**
   * Remove from @p directory the files a run of RestShape writes there
   * (summary.json, solution-*.vtu and their records, iterations.csv,
   * rest_shape.msh, ...), and temporary files left by a killed run, so
   * that the next run's results are never mixed with an earlier run's.
   * Other files and subdirectories (study/) stay.
   */
  void
  remove_previous_results(const std::string &directory);

  class OutputWriter
  {
  public:
    /// @p length_unit: metres per output length unit (the mesh's).
    OutputWriter(const std::string &directory,
                 const double       length_unit,
                 const MPI_Comm     comm);

    /**
     * Write the fields of @p problem at its current state as step
     * @p step (time value @p time in the .pvd record) on the deformed
     * geometry X + d: displacement (from the rest shape), element-averaged
     * von Mises stress, labels, plus @p extra_nodal and @p extra_cell.
     * Updates solution.pvd and solution.visit; if @p name is given, writes
     * NAME.vtu (or .pvtu) instead, outside the time series.
     */
    void
    write_fields(const ForwardProblem          &problem,
                 const unsigned int             step,
                 const double                   time,
                 const std::vector<NodalField> &extra_nodal = {},
                 const std::vector<CellField>  &extra_cell  = {},
                 const std::string             &name        = "");

    /// 1 / (metres per output length unit).
    double
    length_scale() const;

    /// write_text() on rank 0 alone, not collective, a failure ignored:
    /// for the summary of a run that already fails.
    void
    try_write_text(const std::string                         &name,
                   const std::function<void(std::ostream &)> &write) const;

    /// Write text from rank 0 only, atomically, into the directory.
    void
    write_text(const std::string                         &name,
               const std::function<void(std::ostream &)> &write) const;

    /// A CSV table (rank 0).
    void
    write_csv(const std::string                      &name,
              const std::vector<std::string>         &header,
              const std::vector<std::vector<double>> &rows) const;

    std::string
    path(const std::string &name) const;

    /// "mm" or "m": the unit of lengths in the VTU fields.
    std::string length_unit_name;

  private:
    const std::string                                        directory;
    const double                                             length_unit;
    const MPI_Comm                                           comm;
    std::vector<std::pair<double, std::string>>              pvd_records;
    std::vector<std::pair<double, std::vector<std::string>>> visit_records;
  };
} // namespace RestShape

#endif
