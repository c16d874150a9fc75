// Postprocessor: convergence.csv and, with exact solutions, convergence.txt
// with rates: one row per cycle; the exact errors also into summary.json and on
// screen.
#ifndef restshape_postprocess_convergence_postprocessor_h
#define restshape_postprocess_convergence_postprocessor_h

#include <deal.II/base/convergence_table.h>

#include <restshape/postprocess/postprocessor.h>

namespace RestShape
{
  class ConvergencePostprocessor : public Postprocessor
  {
  public:
    void
    execute(const PostprocessInput &in) override;

  private:
    /// Add the errors of @p field against @p exact to the row, the table,
    /// summary.json (keys prefixed by @p key) and the screen.
    void
    add_errors(const PostprocessInput  &in,
               const ExactDisplacement &exact,
               const VectorType        &field,
               const std::string       &key);

    /// @p table as text: a line "# N: name" per column (the rate columns
    /// named KEY_rate and explained), then the aligned rows.
    static std::string
    described_table(const dealii::ConvergenceTable &table);

    dealii::ConvergenceTable         table;
    std::vector<std::vector<double>> rows;
    /// Of the current cycle.
    std::vector<double>      row;
    std::vector<std::string> header, rated;
  };
} // namespace RestShape

#endif
