#include <restshape/base/input_error.h>
#include <restshape/contact/off_faces.h>

#include <fstream>
#include <sstream>
#include <vector>

namespace RestShape
{
  namespace
  {
    /// The words of the next line that has any (comments after '#' left
    /// out); false at the end of the file.
    bool
    next_words(std::istream &in, std::vector<std::string> &words)
    {
      std::string line;
      while (std::getline(in, line))
        {
          line = line.substr(0, line.find('#'));
          std::istringstream split(line);
          words.clear();
          for (std::string w; split >> w;)
            words.push_back(w);
          if (!words.empty())
            return true;
        }
      return false;
    }

    /// @p word as a whole number from 0 to @p limit - 1, or -1.
    long
    index_in(const std::string &word, const long limit)
    {
      if (word.empty() || word.size() > 18 ||
          word.find_first_not_of("0123456789") != std::string::npos)
        return -1;
      const long value = std::stol(word);
      return value < limit ? value : -1;
    }
  } // namespace

  void
  check_off_faces(const std::string &file, const std::string &parameter)
  {
    std::ifstream            in(file);
    std::vector<std::string> words;
    if (!next_words(in, words))
      return;
    const std::string header = words[0];
    const bool        is_off =
      header.size() >= 3 && header.compare(header.size() - 3, 3, "OFF") == 0;
    if (!is_off || header.find('n') != std::string::npos ||
        (words.size() > 1 && words[1] == "BINARY"))
      return; // not a plain ASCII 3d OFF file: CGAL decides
    // The counts follow the header on its line or on the next one.
    std::size_t first = 1;
    if (words.size() == 1)
      {
        if (!next_words(in, words))
          return;
        first = 0;
      }
    if (words.size() < first + 2)
      return;
    const long max_count  = 1L << 40;
    const long n_vertices = index_in(words[first], max_count);
    const long n_faces    = index_in(words[first + 1], max_count);
    if (n_vertices < 0 || n_faces < 0)
      return; // CGAL reports the header
    for (long v = 0; v < n_vertices; ++v)
      if (!next_words(in, words))
        return; // truncated: CGAL reports it
    const auto fail = [&](const long face, const std::string &what) {
      throw InputError(file,
                       parameter,
                       "face " + std::to_string(face + 1) + " " + what +
                         "; expected a vertex count of at least 3 and "
                         "indices from 0 to " +
                         std::to_string(n_vertices - 1));
    };
    for (long f = 0; f < n_faces && next_words(in, words); ++f)
      {
        const long n = index_in(words[0], max_count);
        if (n < 3)
          fail(f, "has the vertex count '" + words[0] + "'");
        if (long(words.size()) < n + 1)
          fail(f, "lists fewer than its " + words[0] + " vertices");
        for (long i = 1; i <= n; ++i)
          if (index_in(words[i], n_vertices) < 0)
            fail(f, "refers to vertex '" + words[i] + "'");
      }
  }
} // namespace RestShape
