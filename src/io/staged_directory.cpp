#include "io/staged_directory.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

// Removes a folder tree: "" or why it could not.
std::string remove_tree(const std::string& path) {
  std::error_code error;
  fs::remove_all(path, error);
  return error ? error.message() : std::string();
}

}  // namespace

StagedDirectory::StagedDirectory(std::string final_path) {
  // Lexically normal, so that the temporary folder and the final one are beside each other
  // however the path was spelt ("a/../b": "b", even when a does not exist).
  const fs::path target = fs::path(final_path).lexically_normal();
  final_path_ = target.string();
  const std::string name = target.filename().string();
  if (final_path.find('\0') != std::string::npos || name.empty() || name == "." || name == "..") {
    error_ = "cannot write output to \"" + final_path_ + "\": not a folder name";
    return;
  }
  const fs::path parent = target.parent_path();
  // The parents that do not exist yet, so that a failed render can take them away again.
  std::error_code error;
  for (fs::path folder = parent; !folder.empty() && !fs::exists(fs::symlink_status(folder, error));
       folder = folder.parent_path()) {
    created_parents_.insert(created_parents_.begin(), folder.string());
    if (folder == folder.root_path()) break;
  }
  if (!parent.empty()) fs::create_directories(parent, error);
  if (error) {
    error_ = "cannot create output folder " + parent.string() + ": " + error.message();
    return;
  }
  std::string hidden = ".";  // built by appending: GCC 12 warns wrongly on "." + string + ...
  hidden += name;
  hidden += ".partial-";
  hidden += std::to_string(::getpid());
  temporary_path_ = (parent / hidden).string();
  remove_tree(temporary_path_);  // left by an earlier run that had this process id
  if (!fs::create_directory(temporary_path_, error)) {
    error_ = "cannot create a folder in " + (parent.empty() ? std::string(".") : parent.string()) +
             ": " + (error ? error.message() : "it already exists");
    temporary_path_.clear();
  }
}

Result<StagedDirectory> StagedDirectory::create(std::string final_path) {
  StagedDirectory staged(std::move(final_path));
  if (!staged.error_.empty()) return Error{staged.error_};
  return staged;
}

StagedDirectory::StagedDirectory(StagedDirectory&& other) noexcept
    : final_path_(std::move(other.final_path_)),
      temporary_path_(std::move(other.temporary_path_)),
      created_parents_(std::move(other.created_parents_)),
      error_(std::move(other.error_)),
      leftover_(std::move(other.leftover_)),
      committed_(std::exchange(other.committed_, true)) {}  // the moved-from one removes nothing

StagedDirectory::~StagedDirectory() {
  if (committed_) return;
  if (!temporary_path_.empty()) remove_tree(temporary_path_);
  std::error_code ignored;  // fs::remove leaves a folder that is not empty
  for (auto folder = created_parents_.rbegin(); folder != created_parents_.rend(); ++folder) {
    fs::remove(*folder, ignored);
  }
}

void StagedDirectory::remove_temporary() {
  if (const std::string why = remove_tree(temporary_path_); !why.empty()) {
    leftover_ = "the earlier output, moved aside to " + temporary_path_ +
                ", could not be deleted (" + why + "); delete it by hand";
  }
}

Result<void> StagedDirectory::commit() {
  if (::rename(temporary_path_.c_str(), final_path_.c_str()) == 0) {
    committed_ = true;  // nothing was there, or an empty folder
    return Result<void>::success();
  }
  if (errno != ENOTEMPTY && errno != EEXIST) {
    return Error{"cannot put " + final_path_ + " in place: " + std::strerror(errno)};
  }
  // A folder is there: swap the two in one step, then delete the old one (now at the temporary
  // name).
  if (::renameat2(AT_FDCWD, temporary_path_.c_str(), AT_FDCWD, final_path_.c_str(),
                  RENAME_EXCHANGE) == 0) {
    committed_ = true;
    remove_temporary();
    return Result<void>::success();
  }
  if (errno != EINVAL && errno != ENOSYS) {
    return Error{"cannot replace " + final_path_ + ": " + std::strerror(errno)};
  }
  // A file system without the exchange: move the old folder aside first. A reader may find no
  // folder for a moment, but never a mixed one.
  const std::string new_path = temporary_path_;
  temporary_path_ += "-old";
  remove_tree(temporary_path_);
  if (::rename(final_path_.c_str(), temporary_path_.c_str()) != 0 ||
      ::rename(new_path.c_str(), final_path_.c_str()) != 0) {
    const std::string error = "cannot replace " + final_path_ + ": " + std::strerror(errno);
    ::rename(temporary_path_.c_str(), final_path_.c_str());  // put the old one back if moved
    temporary_path_ = new_path;  // the new folder: removed by the destructor
    return Error{error};
  }
  committed_ = true;
  remove_temporary();
  return Result<void>::success();
}

}  // namespace tumble::io
