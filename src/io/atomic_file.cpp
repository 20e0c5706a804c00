#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

// Where the bytes go, and whether that is a file to replace by a rename ("" when not: a device,
// a FIFO, a folder, a dangling link, which are opened and written as they are).
std::string replaceable_target(const std::string& path) {
  // /dev/stdout, /dev/fd/3, /proc/self/fd/1: a stream tumble was handed, whatever it leads to.
  if (path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0) return {};
  std::error_code error;
  const fs::file_status status = fs::symlink_status(path, error);
  if (!fs::exists(status)) return path;  // a new file
  if (fs::is_regular_file(status)) return path;
  if (!fs::is_symlink(status) || !fs::is_regular_file(fs::status(path, error))) return {};
  const fs::path target = fs::canonical(path, error);
  return error ? std::string() : target.string();
}

}  // namespace

AtomicFile::AtomicFile(std::string path, Durability durability)
    : path_(std::move(path)), target_path_(replaceable_target(path_)), durability_(durability) {
  if (target_path_.empty()) {
    target_path_ = path_;
    file_ = std::fopen(path_.c_str(), "wb");
  } else {
    temporary_path_ = target_path_ + ".tmp-" + std::to_string(::getpid());
    file_ = std::fopen(temporary_path_.c_str(), "wb");
  }
  if (!file_) fail("cannot create");
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  if (!committed_ && !temporary_path_.empty()) std::remove(temporary_path_.c_str());
}

void AtomicFile::fail(const std::string& what) {
  if (error_.empty()) error_ = path_ + ": " + what + ": " + std::strerror(errno);
}

bool AtomicFile::commit() {
  if (!file_) return false;
  // The flush first: after a failed write it usually fails again with the reason (EFBIG,
  // ENOSPC), which ferror alone cannot give.
  if (std::fflush(file_) != 0) fail("write failed");
  if (std::ferror(file_)) {
    errno = EIO;
    fail("write failed");
  }
  const bool sync = durability_ == Durability::synced && !temporary_path_.empty();
  if (error_.empty() && sync && ::fsync(::fileno(file_)) != 0) fail("write failed");
  if (std::fclose(file_) != 0) fail("write failed");
  file_ = nullptr;
  if (!error_.empty()) return false;
  if (temporary_path_.empty()) {
    committed_ = true;  // written directly
    return true;
  }
  if (std::rename(temporary_path_.c_str(), target_path_.c_str()) != 0) {
    fail("cannot rename temporary file into place");
    return false;
  }
  committed_ = true;
  return true;
}

}  // namespace tumble::io
