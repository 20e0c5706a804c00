#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <stdio_ext.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <utility>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

// How a path is written.
struct Target {
  std::string path;     // the file to create or replace: the path, or the name its links lead to
  int stream = -1;      // the open file descriptor the path names, when it names one
  bool direct = false;  // written as it is: a stream, FIFO, device or folder (no rename over it)
  int mode = -1;        // permission bits of the regular file replaced, or -1 for a new file
  bool loop = false;    // a chain of links too long to follow
};

// N for "/dev/fd/N", "/proc/self/fd/N", and 0, 1, 2 for /dev/stdin, stdout and stderr: a file
// descriptor tumble was handed (`--out /dev/fd/3 3>>log`), whatever it leads to. -1 otherwise.
int descriptor_named(const std::string& path) {
  for (const auto& [name, number] :
       {std::pair<const char*, int>{"/dev/stdin", 0}, {"/dev/stdout", 1}, {"/dev/stderr", 2}}) {
    if (path == name) return number;
  }
  for (const std::string prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (path.size() <= prefix.size() || path.rfind(prefix, 0) != 0) continue;
    int number = 0;
    const char* const end = path.data() + path.size();
    const auto [after, error] = std::from_chars(path.data() + prefix.size(), end, number);
    if (error == std::errc() && after == end) return number;
  }
  return -1;
}

Target target_of(const std::string& path) {
  const std::string normal = fs::path(path).lexically_normal().string();  // "/dev//fd/3" too
  if (const int stream = descriptor_named(normal); stream >= 0 && ::fcntl(stream, F_GETFD) != -1) {
    return {path, stream, true};
  }
  struct stat followed;
  if (::stat(path.c_str(), &followed) == 0) {
    if (!S_ISREG(followed.st_mode)) return {path, -1, true};
    // Standard output or error spelt another way: write through the stream, which keeps an
    // append (>>) an append.
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
  Target target{.path = path};
  fs::path resolved = path;
  std::error_code error;
  int hops = 0;
  for (; hops < 40 && fs::is_symlink(fs::symlink_status(resolved, error)); ++hops) {
    const fs::path link = fs::read_symlink(resolved, error);
    if (error) break;
    resolved = link.is_absolute() ? link : resolved.parent_path() / link;
  }
  // 40: the kernel's own limit on a chain of links; a chain of exactly 40 ends in a file.
  target.loop = hops == 40 && fs::is_symlink(fs::symlink_status(resolved, error));
  target.path = resolved.string();
  if (::stat(target.path.c_str(), &followed) == 0) target.mode = followed.st_mode & 07777;
  return target;
}

}  // namespace

AtomicFile::AtomicFile(std::string path, Durability durability)
    : path_(std::move(path)), durability_(durability) {
  const Target target = target_of(path_);
  target_path_ = target.path;
  if (target.loop) {
    errno = ELOOP;
    fail("cannot create");
  } else if (target.stream >= 0) {
    const int copy = ::dup(target.stream);
    file_ = copy < 0 ? nullptr : ::fdopen(copy, "wb");
    if (copy >= 0 && !file_) ::close(copy);
    if (!file_) fail("cannot write");
  } else if (target.direct) {
    file_ = std::fopen(path_.c_str(), "wb");
    if (!file_) fail("cannot create");
  } else {
    // A new name, never an existing file or link (O_EXCL, O_NOFOLLOW): a link planted at a
    // predictable name would otherwise be written through, to anywhere.
    static std::atomic<unsigned> next{0};
    std::string candidate;
    for (int attempt = 0; attempt < 100 && !file_; ++attempt) {
      candidate = target_path_ + ".tmp-" + std::to_string(::getpid()) + "-" +
                  std::to_string(next.fetch_add(1));
      const int descriptor =
          ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
      if (descriptor < 0 && errno == EEXIST) continue;
      if (descriptor >= 0) file_ = ::fdopen(descriptor, "wb");
      if (descriptor >= 0 && !file_) ::close(descriptor);
      break;
    }
    if (file_) temporary_path_ = candidate;  // only ever ours to remove
    if (!file_ && target.mode >= 0) {
      fail("cannot create the temporary file " + candidate + " to replace it");
    } else if (!file_) {
      fail("cannot create");
    } else if (target.mode >= 0) {
      ::fchmod(::fileno(file_), static_cast<mode_t>(target.mode));  // keep its permissions
    }
  }
}

Result<AtomicFile> AtomicFile::open(std::string path, Durability durability) {
  AtomicFile file(std::move(path), durability);
  if (!file.file_ || !file.error_.empty()) return Error{file.error_};
  return file;
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)),
      target_path_(std::move(other.target_path_)),
      temporary_path_(std::exchange(other.temporary_path_, {})),
      file_(std::exchange(other.file_, nullptr)),
      error_(std::move(other.error_)),
      committed_(other.committed_),
      durability_(other.durability_) {}

AtomicFile::~AtomicFile() {
  // Not committed: what is still buffered is dropped, not written, so that closing a FIFO or
  // pipe nobody reads cannot block.
  if (file_ && !committed_) __fpurge(file_);
  if (file_) std::fclose(file_);
  if (!committed_ && !temporary_path_.empty()) std::remove(temporary_path_.c_str());
}

void AtomicFile::fail(const std::string& what) {
  if (error_.empty()) error_ = path_ + ": " + what + ": " + std::strerror(errno);
}

Result<void> AtomicFile::commit() {
  if (!file_) return Error{error_};
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
  if (!error_.empty()) return Error{error_};
  if (temporary_path_.empty()) {
    committed_ = true;  // written directly
    return Result<void>::success();
  }
  if (std::rename(temporary_path_.c_str(), target_path_.c_str()) != 0) {
    fail("cannot rename temporary file into place");
    return Error{error_};
  }
  committed_ = true;
  return Result<void>::success();
}

Result<void> write_file_atomically(const std::string& path, const std::string& bytes) {
  Result<AtomicFile> file = AtomicFile::open(path);
  if (!file) return Error{file.error()};
  std::fwrite(bytes.data(), 1, bytes.size(), file->stream());
  return file->commit();
}

}  // namespace tumble::io
