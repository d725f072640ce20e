#pragma once
// A folder of outputs that belong together (a run's model, report and
// exports) replaced all at once: the files are written into a staging folder
// beside it, which one atomic rename (RENAME_EXCHANGE) then swaps in. A
// process killed at any moment leaves the previous outputs as they were, or
// all the new ones. Files in the folder that the new set does not hold (the
// user's own, another run's intermediates) are kept, as hard links.
//
// Where the swap would be unsafe the files are renamed in one by one (each
// atomic, the set not): the folder holds a subfolder or something other
// than files (moving it could strand it), it is the working folder or
// holds it (a shell in it would be left in the old one), it is a mount
// point, its parent takes no new folder, or the file system has no
// RENAME_EXCHANGE. `atomic()` says which. Then the files that describe the
// others (a run's report) go last and their old copies first, so that a
// process killed midway leaves no such file rather than one about a mix.
#include <string>
#include <vector>

namespace igaprep {

class OutputFolder {
 public:
  // Creates `dir` (create_output_folder) and the staging folder, and removes
  // staging folders left beside it by killed processes. Throws bad_input.
  explicit OutputFolder(std::string dir);
  // Without commit(): the staging folder is removed, `dir` untouched.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& dir() const { return dir_; }
  const std::string& staging() const { return staging_; }  // write the outputs here
  bool atomic() const { return atomic_; }
  bool committed() const { return committed_; }

  // Puts the staged files in place (see above) and removes the staging
  // folder. summaries: names of the staged files that describe the others
  // (moved last, their old copies removed first, when not atomic). Throws
  // bad_input when the file system refuses.
  void commit(const std::vector<std::string>& summaries = {});

 private:
  void commit_by_exchange(const std::vector<std::string>& summaries);
  void commit_file_by_file(const std::vector<std::string>& summaries);

  std::string dir_;
  std::string real_;  // dir_ with symlinks resolved: the folder the swap replaces
  std::string staging_;
  bool atomic_ = false;
  bool committed_ = false;
};

}  // namespace igaprep
