// Files that appear whole or not at all: written under a temporary name beside the target,
// flushed, then renamed over it. A target that is not a regular file (a FIFO, a device) or that
// is tumble's own standard output or error (/dev/stdout into a file) is written directly, since
// renaming over it would replace it; a symbolic link has the file it names replaced (or created,
// if dangling), and stays a link.
#pragma once

#include <cstdio>
#include <string>

#include "common/result.hpp"

namespace tumble::io {

class AtomicFile {
 public:
  // Whether commit() waits for the data to reach the disk before the rename. Without it the file
  // still appears whole or not at all to every process, and a crash of tumble cannot leave half a
  // file; only a power cut could. Video frames skip it: an fsync per frame costs more wall time
  // than writing the PNG.
  enum class Durability { synced, unsynced };

  // Opens "<path>.tmp-<pid>-<n>" for writing (or the target itself, see above); the error names
  // the path and the system's reason.
  static Result<AtomicFile> open(std::string path, Durability durability = Durability::synced);
  ~AtomicFile();  // removes the temporary file unless commit() succeeded
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile& operator=(AtomicFile&&) = delete;

  std::FILE* stream() { return file_; }

  // Flushes, closes and renames onto the final path. On failure (a write that failed before
  // included) nothing is left at either name. Once only.
  Result<void> commit();

 private:
  AtomicFile(std::string path, Durability durability);  // error_ says whether it opened
  void fail(const std::string& what);

  std::string path_;            // as given, for messages
  std::string target_path_;     // where the file ends up: path_, or what its links name
  std::string temporary_path_;  // "" when writing the target directly
  std::FILE* file_ = nullptr;
  std::string error_;
  bool committed_ = false;
  Durability durability_;
};

// `bytes` as the whole of the file at `path`, through an AtomicFile (synced); the error names the
// path.
Result<void> write_file_atomically(const std::string& path, const std::string& bytes);

}  // namespace tumble::io
