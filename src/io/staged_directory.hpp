// A folder that appears whole or not at all: written under a hidden temporary name beside its
// final path, then swapped into place by commit(). A folder already at the final path is
// replaced in one step (renameat2 with RENAME_EXCHANGE), so a reader sees the old output or the
// new one, never a mix, and then deleted.
#pragma once

#include <string>

namespace tumble::io {

class StagedDirectory {
 public:
  // Creates the final path's parent folders and "<parent>/.<name>.partial-<pid>". Check ok() /
  // error() before use.
  explicit StagedDirectory(std::string final_path);
  ~StagedDirectory();  // removes the temporary folder and everything in it unless committed
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  const std::string& path() const { return temporary_path_; }  // write here
  const std::string& final_path() const { return final_path_; }

  // Puts the folder in place, replacing what was there. Returns false (see error()) on failure,
  // in which case the final path is as it was and the temporary folder is removed.
  bool commit();

 private:
  std::string final_path_;
  std::string temporary_path_;
  std::string error_;
  bool committed_ = false;
};

}  // namespace tumble::io
