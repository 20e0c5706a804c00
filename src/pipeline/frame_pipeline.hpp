// The frame loop of `tumble render`: frame k is pulled from a source and drawn on the calling
// thread (which owns the OpenGL context) while earlier frames are pushed to the sinks, each on a
// worker thread of its own. Queues are bounded, so memory stays flat however long the video; each
// sink sees frames in order; an error in any stage stops every stage. The serial path does the
// same work in the same order on one thread, and must give the same bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "pipeline/frame_sinks.hpp"
#include "render/frame.hpp"
#include "render/renderer.hpp"

namespace tumble::pipeline {

// What frame k shows, as plain items for the renderer. Overlays add their items here.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // Frames are asked for in increasing order. An error (a blow-up, an interruption) stops the
  // run; its message becomes the run's error.
  virtual Result<render::FrameView> view(std::int64_t frame) = 0;
};

struct StageTime {
  double cpu = 0.0;   // s of CPU time spent in the stage, all threads
  double wall = 0.0;  // s between the stage's start and end of work, summed over frames
};

// CPU time of every thread of this process so far, user and system (s).
double process_cpu_seconds();

struct PipelineReport {
  std::int64_t frames_done = 0;  // frames that finished every stage
  StageTime simulate, render;
  std::vector<StageTime> sinks;  // one per sink, in the order given
  double wall = 0.0;             // s, the whole run
  double process_cpu = 0.0;      // s, every thread of the process during the run
};

// Runs frames [first, end) from `source`, drawn by `renderer`, into every sink. `on_frame_done`
// is called (serialised) as each frame finishes. No sink is finished here (FrameSink::finish).
// Succeeds when every frame went through every stage, else gives the first error; `report` holds
// the figures either way.
Result<void> run_frames(std::int64_t first, std::int64_t end, FrameSource& source,
                        render::Renderer& renderer, const std::vector<FrameSink*>& sinks,
                        bool serial, const std::function<void(std::int64_t done)>& on_frame_done,
                        PipelineReport& report);

}  // namespace tumble::pipeline
