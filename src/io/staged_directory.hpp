// A folder that appears whole or not at all: written under a hidden temporary name beside its
// final path, then swapped into place by commit(). A folder already at the final path is
// replaced in one step (renameat2 with RENAME_EXCHANGE), so a reader sees the old output or the
// new one, never a mix, and then deleted.
#pragma once

#include <string>
#include <vector>

#include "common/result.hpp"

namespace tumble::io {

class StagedDirectory {
 public:
  // Creates the final path's missing parent folders and "<parent>/.<name>.partial-<pid>". The
  // final path must end in a plain name (not "", "." or "..") and hold no NUL byte: the temporary
  // folder is named after it, and removed again. On failure the parents it created are removed.
  static Result<StagedDirectory> create(std::string final_path);
  // Unless committed: removes the temporary folder and everything in it, and the parent folders
  // create() made (those still empty).
  ~StagedDirectory();
  StagedDirectory(StagedDirectory&& other) noexcept;
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;
  StagedDirectory& operator=(StagedDirectory&&) = delete;

  const std::string& path() const { return temporary_path_; }  // write here

  // Puts the folder in place, replacing what was there. On failure the final path is as it was.
  Result<void> commit();

  // After a successful commit: "" or why the replaced folder could not be deleted, naming where
  // it was left. The new folder is in place either way.
  const std::string& leftover() const { return leftover_; }

 private:
  explicit StagedDirectory(std::string final_path);  // error_ says whether it was created
  void remove_temporary();

  std::string final_path_;
  std::string temporary_path_;
  std::vector<std::string> created_parents_;  // outermost first
  std::string error_;                         // why the constructor failed, for create()
  std::string leftover_;
  bool committed_ = false;
};

}  // namespace tumble::io
