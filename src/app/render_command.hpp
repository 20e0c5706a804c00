// `tumble render`: a scene to PNG frames and an MP4, off-screen.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "io/png_io.hpp"

namespace tumble::app {

struct RenderOptions {
  std::string scene_path;
  std::string output_root = "output";     // files go to <output_root>/<scene output directory>/
  std::optional<int> width, height, fps;  // override the scene's [render] values
  std::optional<std::int64_t> first_frame, end_frame;  // --frames A:B renders A .. B-1
  bool frames = true;
  bool video = true;
  bool quiet = false;
  bool verbose = false;
  bool serial = false;  // one thread: the reference the pipelined path must match byte for byte
  io::PngSettings png;  // fast by default; see io/png_io.hpp
};

// Runs the command; progress and messages go to `err`. Returns the process exit code.
int run_render(const RenderOptions& options, std::FILE* err);

}  // namespace tumble::app
