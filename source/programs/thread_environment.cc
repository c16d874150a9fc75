// DEAL_II_NUM_THREADS checked before deal.II reads it. deal.II's static
// initialisation (MultithreadInfo) throws on a value that is not a whole
// number above zero, before main(), which ends the program with SIGABRT
// and a stack trace. A function in the executable's .preinit_array runs
// before any shared library's initialisers: it refuses such a value with
// one line and exit code 1. Only the C library is ready then: no C++
// streams, no allocation.
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace
{
  /// Whether @p text is a whole number from 1 to 1,000,000.
  bool
  is_thread_count(const char *text)
  {
    constexpr long most_threads = 1000000;
    char          *end          = nullptr;
    const long     n            = std::strtol(text, &end, 10);
    return *text != '\0' && *end == '\0' && n >= 1 && n <= most_threads;
  }

  void
  write_text(const char *text)
  {
    const ssize_t ignored = write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
  }

  /// The value of @p name in @p envp (getenv() is not ready yet).
  const char *
  environment_value(char **envp, const char *name)
  {
    const std::size_t n = std::strlen(name);
    for (char **e = envp; e != nullptr && *e != nullptr; ++e)
      if (std::strncmp(*e, name, n) == 0 && (*e)[n] == '=')
        return *e + n + 1;
    return nullptr;
  }

  void
  check_thread_environment(int, char **argv, char **envp)
  {
    const char *value = environment_value(envp, "DEAL_II_NUM_THREADS");
    if (value == nullptr || is_thread_count(value))
      return;
    const char *slash   = argv != nullptr && argv[0] != nullptr ?
                            std::strrchr(argv[0], '/') :
                            nullptr;
    const char *program = slash != nullptr                      ? slash + 1 :
                          argv != nullptr && argv[0] != nullptr ? argv[0] :
                                                                  "restshape";
    write_text(program);
    write_text(": error: environment variable DEAL_II_NUM_THREADS='");
    write_text(value);
    write_text("': expected a whole number of threads from 1 up (or leave "
               "it unset: all cores)\n");
    _exit(1);
  }
} // namespace

// Not const: a const pointer is not placed in the array that runs.
__attribute__((section(".preinit_array"), used)) static void (
  *restshape_preinit)(int, char **, char **) = &check_thread_environment;
