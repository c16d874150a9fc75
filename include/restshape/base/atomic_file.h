// Writing a file under a temporary name and renaming it into place, so that
// an interrupted or failed run never leaves a half-written result and never
// destroys an earlier one before the new one is complete.
#ifndef restshape_atomic_file_h
#define restshape_atomic_file_h

#include <deal.II/base/mpi.h>

#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace RestShape
{
  /**
   * Call @p write on a stream to "<path>.tmp-<pid>", then rename it to
   * @p path. Throws InputError naming @p parameter if the file cannot be
   * written.
   */
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write,
                        const std::string &parameter = "Output/Directory");

  /**
   * The same for writers that need a file name whose extension tells the
   * format (libnifti, CGAL's readers and writers): @p write writes to the
   * temporary name "<dir>/.tmp-<pid>-<name>" it is given and returns false
   * on failure, with @p message used for the error. The file is then
   * renamed to @p path.
   */
  void
  write_named_file_atomically(
    const std::string                              &path,
    const std::function<bool(const std::string &)> &write,
    const std::string                              &parameter,
    const std::string                              &message);

  /**
   * Files of one result that appear together or not at all (a mesh and its
   * skull): each is written under a staging name in its own directory
   * ("<dir>/.staged-<pid>-<name>", same extension), and commit() renames
   * them all into place once every one was written. Staged files not
   * committed are removed by the destructor and by an interruption.
   */
  class StagedFiles
  {
  public:
    StagedFiles()                    = default;
    StagedFiles(const StagedFiles &) = delete;
    StagedFiles &
    operator=(const StagedFiles &) = delete;
    ~StagedFiles();

    /// The name to write @p path under until commit().
    std::string
    stage(const std::string &path);

    /// Rename every staged file to its final name. Throws InputError
    /// naming @p parameter of a file that cannot be renamed.
    void
    commit(const std::string &parameter);

  private:
    /// (staging name, final name)
    std::vector<std::pair<std::string, std::string>> files;
  };

  /**
   * Runs @p write (which writes @p file) where @p this_rank_writes; a
   * failure to write (InputError) on any rank is an OutputFailure naming
   * @p file on every rank of @p comm, so that no rank waits for another.
   */
  void
  write_on_every_rank(const MPI_Comm               comm,
                      const std::string           &file,
                      const std::function<void()> &write,
                      bool                         this_rank_writes);

  /**
   * Make this process the one owner of @p directory for as long as it
   * runs: an exclusive lock (flock) on @p directory/.restshape.lock, held
   * until the process ends (the kernel releases it even after SIGKILL).
   * Throws InputError naming @p parameter if another process holds it
   * (with its pid): two runs into one directory would mix their results.
   */
  void
  claim_directory(const std::string &directory,
                  const std::string &parameter = "Output/Directory");

  /**
   * Create @p directory (and parents) if needed and check that files can be
   * created in it. Throws InputError naming @p parameter otherwise.
   */
  void
  ensure_writable_directory(const std::string &directory,
                            const std::string &parameter = "Output/Directory");
} // namespace RestShape

#endif
