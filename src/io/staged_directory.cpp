#include "io/staged_directory.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

// Removes a folder tree; errors are ignored (it is a temporary folder of ours, or the old output
// already swapped out of the way).
void remove_tree(const std::string& path) {
  std::error_code ignored;
  fs::remove_all(path, ignored);
}

}  // namespace

StagedDirectory::StagedDirectory(std::string final_path) : final_path_(std::move(final_path)) {
  const fs::path target = fs::path(final_path_).lexically_normal();
  const fs::path parent = target.parent_path();
  std::string name = ".";  // built by appending: GCC 12 warns wrongly on "." + string + ...
  name += target.filename().string();
  name += ".partial-";
  name += std::to_string(::getpid());
  temporary_path_ = (parent / name).string();
  std::error_code error;
  if (!parent.empty()) fs::create_directories(parent, error);
  if (error) {
    error_ = "cannot create output folder " + parent.string() + ": " + error.message();
    return;
  }
  remove_tree(temporary_path_);  // left by an earlier run that had this process id
  if (!fs::create_directory(temporary_path_, error)) {
    error_ = "cannot create a folder in " + (parent.empty() ? std::string(".") : parent.string()) +
             ": " + (error ? error.message() : "it already exists");
  }
}

StagedDirectory::~StagedDirectory() {
  if (!committed_ && !temporary_path_.empty()) remove_tree(temporary_path_);
}

bool StagedDirectory::commit() {
  if (!error_.empty()) return false;
  if (::rename(temporary_path_.c_str(), final_path_.c_str()) == 0) {
    committed_ = true;  // nothing was there, or an empty folder
    return true;
  }
  if (errno != ENOTEMPTY && errno != EEXIST) {
    error_ = "cannot put " + final_path_ + " in place: " + std::strerror(errno);
    return false;
  }
  // A folder is there: swap the two in one step, then delete the old one (now at the temporary
  // name).
  if (::renameat2(AT_FDCWD, temporary_path_.c_str(), AT_FDCWD, final_path_.c_str(),
                  RENAME_EXCHANGE) == 0) {
    committed_ = true;
    remove_tree(temporary_path_);
    return true;
  }
  if (errno != EINVAL && errno != ENOSYS) {
    error_ = "cannot replace " + final_path_ + ": " + std::strerror(errno);
    return false;
  }
  // A file system without the exchange: move the old folder aside first. A reader may find no
  // folder for a moment, but never a mixed one.
  const std::string old_path = temporary_path_ + "-old";
  remove_tree(old_path);
  if (::rename(final_path_.c_str(), old_path.c_str()) != 0 ||
      ::rename(temporary_path_.c_str(), final_path_.c_str()) != 0) {
    error_ = "cannot replace " + final_path_ + ": " + std::strerror(errno);
    ::rename(old_path.c_str(), final_path_.c_str());  // put the old one back if it was moved
    return false;
  }
  committed_ = true;
  remove_tree(old_path);
  return true;
}

}  // namespace tumble::io
