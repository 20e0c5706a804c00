// One render of a scene, from framing to the last encoded frame: shared by `tumble render` and
// `tumble bench pipeline`, which runs it several ways on the same scene.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/frame_pipeline.hpp"
#include "io/png_io.hpp"
#include "scene/scene.hpp"

namespace tumble::app {

struct RenderPlan {
  std::int64_t first = 0;  // frames first .. end-1
  std::int64_t end = 0;
  std::string frames_directory;  // PNG frames go here; "" = none
  std::string video_path;        // the MP4; "" = none
  io::PngSettings png;
  bool serial = false;  // one thread, for comparison (same bytes as the pipeline)
  std::string shader_directory;
  std::function<void(std::int64_t done)> on_frame_done = [](std::int64_t) {};
  std::function<bool()> stop_requested = [] { return false; };  // asked before each frame
};

struct BodyDiagnostics {
  double energy_start = 0.0, energy_end = 0.0;                      // J
  double angular_momentum_start = 0.0, angular_momentum_end = 0.0;  // |L| (kg m²/s)
};

struct RenderResult {
  std::string error;            // "" on success; then the video (if any) is complete
  PipelineReport pipeline;      // the frames
  double setup_seconds = 0.0;   // framing, renderer and encoder set-up (s, wall)
  double finish_seconds = 0.0;  // draining the encoder and closing the MP4 (s, wall)
  std::string renderer;         // the OpenGL implementation
  std::vector<BodyDiagnostics> bodies;
};

RenderResult render_scene(const scene::Scene& scene, const RenderPlan& plan);

// shaders/ beside an installed binary, else in the source tree this binary was built from;
// TUMBLE_SHADER_DIR overrides both. "" if none is found.
std::string find_shader_directory();

// How a render with [render] msaa = `msaa` smooths its edges, for reports: "edge filter" (the
// default), "none" (msaa = 1) or "MSAA 4".
std::string antialiasing_name(int msaa);

// Peak resident memory of this process so far (bytes).
std::int64_t peak_memory_bytes();

}  // namespace tumble::app
