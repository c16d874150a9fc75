// Running a third-party reader in a child process: a reader that crashes or
// corrupts its heap on a malformed file (gmsh's, CGAL's OFF scanner and
// face triangulation do, on some) takes only the child with it.
#ifndef restshape_base_child_process_h
#define restshape_base_child_process_h

#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>

namespace RestShape
{
  /// Bytes a child sends: values appended in their machine representation.
  class ByteWriter
  {
  public:
    void
    put(const void *data, const std::size_t n)
    {
      bytes.append(static_cast<const char *>(data), n);
    }
    template <typename T>
    void
    put(const T value)
    {
      put(&value, sizeof(T));
    }
    const std::string &
    str() const
    {
      return bytes;
    }

  private:
    std::string bytes;
  };

  /// Reads back what a ByteWriter wrote; std::runtime_error if it is short.
  class ByteReader
  {
  public:
    explicit ByteReader(std::string bytes)
      : bytes(std::move(bytes))
    {}
    template <typename T>
    T
    get()
    {
      T value{};
      if (position + sizeof(T) > bytes.size())
        throw std::runtime_error("short message from the child");
      std::memcpy(&value, bytes.data() + position, sizeof(T));
      position += sizeof(T);
      return value;
    }
    /// A count of items of at least @p item_bytes each that fits the rest.
    std::size_t
    checked_count(const std::size_t item_bytes)
    {
      const auto n = get<std::uint64_t>();
      if (n > (bytes.size() - position) / item_bytes)
        throw std::runtime_error("short message from the child");
      return n;
    }

  private:
    std::string bytes;
    std::size_t position = 0;
  };

  /**
   * Call @p work in a forked child and give the bytes it returns, through
   * a pipe, to @p parse here. An InputError or other exception the child
   * throws is thrown here as an InputError naming @p file and @p parameter
   * with its message; a child that dies (a signal, a sanitizer's exit) or
   * whose bytes @p parse finds short (std::runtime_error, as ByteReader
   * throws) is an InputError naming @p file and @p parameter with
   * @p expected. Without fork(), @p work runs here.
   */
  void
  run_in_child_process(const std::function<std::string()>      &work,
                       const std::function<void(ByteReader &)> &parse,
                       const std::string                       &file,
                       const std::string                       &parameter,
                       const std::string                       &expected);
} // namespace RestShape

#endif
