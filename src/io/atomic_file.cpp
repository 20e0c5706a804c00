#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace tumble::io {

AtomicFile::AtomicFile(std::string path, Durability durability)
    : path_(std::move(path)),
      temporary_path_(path_ + ".tmp-" + std::to_string(::getpid())),
      durability_(durability) {
  file_ = std::fopen(temporary_path_.c_str(), "wb");
  if (!file_) fail("cannot create");
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  if (!committed_) std::remove(temporary_path_.c_str());
}

void AtomicFile::fail(const std::string& what) {
  if (error_.empty()) error_ = path_ + ": " + what + ": " + std::strerror(errno);
}

bool AtomicFile::commit() {
  if (!file_) return false;
  if (std::ferror(file_)) {
    errno = EIO;
    fail("write failed");
  }
  if (std::fflush(file_) != 0) fail("write failed");
  if (error_.empty() && durability_ == Durability::synced && ::fsync(::fileno(file_)) != 0) {
    fail("write failed");
  }
  if (std::fclose(file_) != 0) fail("write failed");
  file_ = nullptr;
  if (!error_.empty()) return false;
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    fail("cannot rename temporary file into place");
    return false;
  }
  committed_ = true;
  return true;
}

}  // namespace tumble::io
