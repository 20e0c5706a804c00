#include "io/atomic_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

// How a path is written.
struct Target {
  std::string path;     // the file to create or replace: the path, or the name its links lead to
  int stream = -1;      // the standard stream (1 or 2) the path is, when it is one of them
  bool direct = false;  // written as it is: a stream, FIFO, device or folder (no rename over it)
};

Target target_of(const std::string& path) {
  struct stat followed;
  if (::stat(path.c_str(), &followed) == 0) {
    if (!S_ISREG(followed.st_mode)) return {path, -1, true};
    // /dev/stdout into a file: write through the stream, which keeps an append (>>) an append.
    for (const int stream : {STDOUT_FILENO, STDERR_FILENO}) {
      struct stat stream_status;
      if (::fstat(stream, &stream_status) == 0 && stream_status.st_dev == followed.st_dev &&
          stream_status.st_ino == followed.st_ino) {
        return {path, stream, true};
      }
    }
  }
  // A new file or a regular one, perhaps named by a chain of links: replace what they lead to,
  // so that a link stays a link and a dangling one comes to name the new file.
  fs::path resolved = path;
  for (int hop = 0; hop < 40; ++hop) {  // 40: the kernel's own limit on a chain of links
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(resolved, error))) break;
    const fs::path link = fs::read_symlink(resolved, error);
    if (error) break;
    resolved = link.is_absolute() ? link : resolved.parent_path() / link;
  }
  return {resolved.string(), -1, false};
}

}  // namespace

AtomicFile::AtomicFile(std::string path, Durability durability)
    : path_(std::move(path)), durability_(durability) {
  const Target target = target_of(path_);
  target_path_ = target.path;
  if (target.stream >= 0) {
    const int copy = ::dup(target.stream);
    file_ = copy < 0 ? nullptr : ::fdopen(copy, "wb");
    if (copy >= 0 && !file_) ::close(copy);
  } else if (target.direct) {
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
