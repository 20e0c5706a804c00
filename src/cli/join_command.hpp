// `tumble join OUT_DIR CHUNK_DIR...`: the chunk folders of one render (`tumble render --chunk
// I/N`, or --frames A:B) joined into one render folder, as a whole render would have written it:
// the PNG frames merged, the MP4 segments joined by stream copy (io::join_videos), and one
// report.json. Nothing is written unless every check passes.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "cli/command.hpp"

namespace tumble::cli {

struct JoinOptions {
  std::string out;                  // the render folder to write (replaced as a whole)
  std::vector<std::string> chunks;  // chunk folders, in any order
  bool quiet = false;
};

// The summary and the note of a stop by a signal go to `err`.
CommandResult run_join(const JoinOptions& options, std::FILE* err);

// `tumble join OUT CHUNK... [-q]`.
void add_join_command(CLI::App& app, Commands& commands);

}  // namespace tumble::cli
