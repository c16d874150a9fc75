// What the unit tests that print one line per check share: expect() and
// the message of an InputError.
#ifndef restshape_tests_unit_checks_h
#define restshape_tests_unit_checks_h

#include <restshape/base/input_error.h>

#include <iostream>
#include <string>

namespace checks
{
  /// Checks that failed so far; main() returns failures == 0 ? 0 : 1.
  inline int failures = 0;

  /// Print "ok   what" or "FAIL what" and count a failure.
  inline void
  expect(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok   " : "FAIL ") << what << std::endl;
    failures += !ok;
  }

  /// The message of the InputError @p f throws, or "" if it throws none.
  template <typename F>
  std::string
  error_of(const F &f)
  {
    try
      {
        f();
      }
    catch (const RestShape::InputError &e)
      {
        return e.message;
      }
    return "";
  }
} // namespace checks

#endif
