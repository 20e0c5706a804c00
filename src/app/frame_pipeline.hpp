// The frame path of `tumble render`: frame k is simulated and drawn on the calling thread (which
// owns the OpenGL context) while earlier frames are written as PNG and encoded on two worker
// threads. Queues are bounded, so memory stays flat however long the video; the encoder sees
// frames in order; an error in any stage stops every stage. The serial path does the same work
// in the same order on one thread, and must give the same bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "io/image.hpp"
#include "render/frame.hpp"

namespace tumble::app {

// Either may throw std::exception to stop the run: its what() becomes the run's error.
struct FrameSource {
  std::function<render::FrameView(std::int64_t frame)> view;  // simulate to the frame's time
  std::function<void(const render::FrameView&, io::Image&)> draw;
};

// Each returns "" or a complete error message. An empty function switches the stage off.
struct FrameSinks {
  std::function<std::string(std::int64_t frame, const io::Image&)> png;
  std::function<std::string(const io::Image&)> video;  // called in frame order
};

struct StageTime {
  double cpu = 0.0;   // s of CPU time spent in the stage, all threads
  double wall = 0.0;  // s between the stage's start and end of work, summed over frames
};

struct PipelineReport {
  std::string error;             // "" when every frame went through every stage
  std::int64_t frames_done = 0;  // frames that finished every stage
  StageTime simulate, render, png, video;
  double wall = 0.0;         // s, the whole run
  double process_cpu = 0.0;  // s, every thread of the process during the run
};

// Runs frames [first, end). `on_frame_done` is called (serialised) as each frame finishes.
PipelineReport run_frames(std::int64_t first, std::int64_t end, const FrameSource& source,
                          const FrameSinks& sinks, bool serial,
                          const std::function<void(std::int64_t done)>& on_frame_done);

}  // namespace tumble::app
