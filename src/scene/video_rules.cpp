#include "scene/video_rules.hpp"

#include <cmath>
#include <cstdio>

#include "scene/limits.hpp"

namespace tumble::scene {
namespace {

// duration × fps rounded, in double: a typo may ask for more frames than an int64 holds.
double rounded_frames(double duration, int fps) {
  return std::round(duration * static_cast<double>(fps));
}

std::string pixel_limit_problem(std::int64_t width, std::int64_t height) {
  if (width * height <= kMaxPixels) return {};
  return std::to_string(width) + " × " + std::to_string(height) + " is " +
         std::to_string(width * height) + " pixels, more than the limit of " +
         std::to_string(kMaxPixels) + " (8192 × 4320)";
}

std::string frame_count_problem(double duration, int fps) {
  const double frames = rounded_frames(duration, fps);
  char text[160];
  if (frames < 1.0) {
    std::snprintf(text, sizeof text,
                  "duration × fps gives no frame (%.6g s at %d frames/s); a scene needs a "
                  "duration of at least half a frame, %.6g s",
                  duration, fps, 0.5 / static_cast<double>(fps));
  } else if (frames > static_cast<double>(kMaxFrames)) {
    std::snprintf(text, sizeof text,
                  frames < 1e15
                      ? "duration × fps asks for %.0f frames, more than the limit of %lld"
                      : "duration × fps asks for %.3g frames, more than the limit of %lld",
                  frames, static_cast<long long>(kMaxFrames));
  } else {
    return {};
  }
  return text;
}

}  // namespace

std::optional<BrokenRule> broken_video_rule(const Scene& scene) {
  const common::RenderSettings& r = scene.render;
  if (std::string problem = pixel_limit_problem(r.width, r.height); !problem.empty()) {
    return BrokenRule{{"render.height", "render.width"}, "render", std::move(problem)};
  }
  if (std::string problem = frame_count_problem(scene.duration, scene.fps); !problem.empty()) {
    return BrokenRule{{"render.fps"}, "duration", std::move(problem)};
  }
  if (scene.output.video && (r.width % 2 != 0 || r.height % 2 != 0)) {
    const bool odd_width = r.width % 2 != 0;
    return BrokenRule{{odd_width ? "render.width" : "render.height"},
                      "render",
                      "must be even for H.264 yuv420p video, which stores colour per 2×2 "
                      "pixels (got " +
                          std::to_string(odd_width ? r.width : r.height) +
                          "); or set [output] video = false (--no-video) for PNG frames only"};
  }
  if (!scene.output.frames && !scene.output.video) {
    return BrokenRule{
        {"output.video"}, "output", "frames and video are both off: nothing to write"};
  }
  return std::nullopt;
}

std::int64_t frame_count(const Scene& scene) {
  return static_cast<std::int64_t>(rounded_frames(scene.duration, scene.fps));
}

}  // namespace tumble::scene
