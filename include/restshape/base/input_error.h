// Errors a user can fix: bad input files, bad parameters, unusable meshes.
#ifndef restshape_input_error_h
#define restshape_input_error_h

#include <stdexcept>
#include <string>

namespace RestShape
{
  /**
   * An error in what the user gave us. It names the file, the parameter (as
   * "Subsection/Parameter", empty if the error is not about one parameter)
   * and what was expected. main() prints it as one line and exits with 1.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &file,
               const std::string &parameter,
               const std::string &message);

    /// The same error, attributed to another file (e.g. the .prm file).
    InputError
    in_file(const std::string &new_file) const;

    const std::string file;
    const std::string parameter;
    const std::string message;
  };

  /**
   * A numerical failure: a solver that did not converge, an inverted cell
   * during the solve. main() prints it as one line and exits with 2.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * The results could not be written once the run had begun (disk full,
   * the output directory removed, a closed stdout). Raised on every rank
   * alike. main() removes the partial results, records the failure in
   * summary.json where it still can, prints one line and exits with 5.
   */
  class OutputFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * One or more scenarios did not converge, while the rest shape (or the
   * forward equilibrium) did and its results are written. main() prints
   * it as one line and exits with 4.
   */
  class ScenarioFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * The "additional information" part of a deal.II exception (or what() of
   * any other exception), squeezed onto one line.
   */
  std::string
  one_line_message(const std::exception &exc);

  /// A number as a user wrote it: "1500", "0.45", "1e-10".
  std::string
  number_text(const double value);
} // namespace RestShape

#endif
