// A driver for the fuzz targets where libFuzzer is not linked (the GCC
// build of the test suite): replays inputs, or runs a short mutation
// campaign of its own (no coverage guidance) from a seed corpus.
//
//   fuzz_TARGET FILE|DIRECTORY...
//       run every file once (regression inputs, a corpus)
//   fuzz_TARGET --mutate LIMIT SEED CURRENT FILE|DIRECTORY...
//       mutate the files (bit flips, inserted, deleted, repeated and
//       spliced bytes, numbers replaced by extreme ones, truncation) with
//       a deterministic generator from SEED for LIMIT seconds ("4"), or
//       LIMIT executions ("500x": the same inputs on any machine); before
//       every run the input is written to CURRENT, so that a crash leaves
//       it there
//
// A finding aborts the process (fuzz_readers.cc); the driver prints the
// number of executions when it ends.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

namespace
{
  using Bytes = std::vector<uint8_t>;

  Bytes
  read_file(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
  }

  std::vector<std::string>
  files_of(const std::vector<std::string> &paths)
  {
    std::vector<std::string> files;
    for (const std::string &p : paths)
      if (std::filesystem::is_directory(p))
        {
          for (const auto &e : std::filesystem::directory_iterator(p))
            if (e.is_regular_file())
              files.push_back(e.path().string());
        }
      else
        files.push_back(p);
    std::sort(files.begin(), files.end());
    return files;
  }

  /// Numbers that break careless readers.
  const std::vector<std::string> extremes = {"-1",
                                             "0",
                                             "2147483648",
                                             "4294967296",
                                             "1e300",
                                             "-1e300",
                                             "nan",
                                             "inf",
                                             "1e-308",
                                             "1e400",
                                             "0.5",
                                             "99999999999999999999",
                                             "-0",
                                             "1e9",
                                             "65536",
                                             "-2147483649"};

  class Mutator
  {
  public:
    explicit Mutator(const unsigned long seed)
      : random(seed)
    {}

    Bytes
    mutate(const Bytes &input, const Bytes &other)
    {
      Bytes data = input;
      for (unsigned int n = 1 + below(4); n > 0; --n)
        step(data, other);
      return data;
    }

  private:
    std::mt19937_64 random;

    size_t
    below(const size_t n)
    {
      return n == 0 ? 0 : random() % n;
    }

    void
    step(Bytes &data, const Bytes &other)
    {
      const size_t at = below(data.size() + 1);
      switch (below(7))
        {
          case 0: // flip a bit
            if (!data.empty())
              data[below(data.size())] ^= uint8_t(1u << below(8));
            break;
          case 1: // insert random bytes
            for (size_t k = below(8) + 1; k > 0; --k)
              data.insert(data.begin() + at, uint8_t(random()));
            break;
          case 2: // delete a range
            data.erase(data.begin() + at,
                       data.begin() + std::min(data.size(), at + below(64)));
            break;
          case 3: // repeat a range many times (deep nesting, long lines)
            {
              const size_t length = std::min(data.size() - at, below(16) + 1);
              const Bytes  chunk(data.begin() + at, data.begin() + at + length);
              for (size_t k = below(2000); k > 0; --k)
                data.insert(data.begin() + at, chunk.begin(), chunk.end());
              break;
            }
          case 4: // replace a number by an extreme one
            replace_number(data);
            break;
          case 5: // splice another input
            if (!other.empty())
              {
                const size_t from = below(other.size());
                data.insert(data.begin() + at,
                            other.begin() + from,
                            other.begin() +
                              std::min(other.size(), from + below(256)));
              }
            break;
          default: // truncate
            data.resize(at);
        }
    }

    void
    replace_number(Bytes &data)
    {
      const auto digit = [&](const size_t i) {
        return i < data.size() && data[i] >= '0' && data[i] <= '9';
      };
      size_t i = below(data.size() + 1);
      while (i < data.size() && !digit(i))
        ++i;
      if (i >= data.size())
        return;
      size_t end = i;
      while (end < data.size() && (digit(end) || data[end] == '.' ||
                                   data[end] == 'e' || data[end] == '-'))
        ++end;
      const std::string &x = extremes[below(extremes.size())];
      data.erase(data.begin() + i, data.begin() + end);
      data.insert(data.begin() + i, x.begin(), x.end());
    }
  };

  void
  run(const Bytes &data)
  {
    LLVMFuzzerTestOneInput(data.data(), data.size());
  }
} // namespace

int
main(int argc, char **argv)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() >= 4 && args[0] == "--mutate")
    {
      const bool         by_count = !args[1].empty() && args[1].back() == 'x';
      const double       limit    = std::stod(args[1]);
      const std::string  current  = args[3];
      std::vector<Bytes> corpus;
      for (const std::string &f :
           files_of(std::vector<std::string>(args.begin() + 4, args.end())))
        corpus.push_back(read_file(f));
      if (corpus.empty())
        {
          std::cerr << "no seed input" << std::endl;
          return 1;
        }
      Mutator         mutator(std::stoul(args[2]));
      std::mt19937_64 pick(std::stoul(args[2]) + 1);
      const auto      start   = std::chrono::steady_clock::now();
      unsigned long   runs    = 0;
      const auto      elapsed = [&start]() {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
          .count();
      };
      while (by_count ? runs < limit : elapsed() < limit)
        {
          const Bytes data = mutator.mutate(corpus[pick() % corpus.size()],
                                            corpus[pick() % corpus.size()]);
          std::ofstream(current, std::ios::binary | std::ios::trunc)
            .write(reinterpret_cast<const char *>(data.data()), data.size());
          run(data);
          ++runs;
        }
      std::filesystem::remove(current);
      std::cout << runs << " executions from " << corpus.size()
                << " seeds, no finding" << std::endl;
      return 0;
    }
  const std::vector<std::string> files = files_of(args);
  for (const std::string &f : files)
    {
      std::cout << f << std::endl;
      run(read_file(f));
    }
  std::cout << files.size() << " inputs, no finding" << std::endl;
  return 0;
}
