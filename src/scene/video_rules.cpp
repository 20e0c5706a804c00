#include "scene/video_rules.hpp"

#include <algorithm>
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

// The rules each video format of [output] formats brings: an even size for 4:2:0 colour, a place
// for the alpha of a transparent background.
std::optional<BrokenRule> broken_format_rule(const Scene& scene) {
  if (!scene.output.video) return std::nullopt;
  const common::RenderSettings& r = scene.render;
  for (const common::VideoFormat format : scene.output.formats) {
    if (needs_even_size(format) && (r.width % 2 != 0 || r.height % 2 != 0)) {
      const bool odd_width = r.width % 2 != 0;
      return BrokenRule{{odd_width ? "render.width" : "render.height"},
                        "render",
                        std::string("must be even for ") +
                            (format == common::VideoFormat::mp4 ? "H.264" : "VP9") +
                            " yuv420p video, which stores colour per 2×2 pixels (got " +
                            std::to_string(odd_width ? r.width : r.height) +
                            "); or set [output] video = false (--no-video) for PNG frames only"};
    }
    if (r.transparent && !carries_alpha(format)) {
      return BrokenRule{{"output.formats", "render.background"},
                        "render",
                        std::string("a transparent background needs a format with alpha: ") +
                            video_format_name(format) +
                            " has none; write formats = [\"webm\"] (VP9 with alpha), or "
                            "video = false for RGBA PNG frames only"};
    }
  }
  return std::nullopt;
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
  if (std::optional<BrokenRule> broken = broken_format_rule(scene)) return broken;
  if (scene.output.poster_time && *scene.output.poster_time > scene.duration) {
    char problem[96];
    std::snprintf(problem, sizeof problem, "is after the end of the scene, at %.6g s",
                  scene.duration);
    return BrokenRule{{"output.poster_time"}, "output", problem};
  }
  if (!scene.output.frames && !scene.output.video && !scene.output.gltf && !scene.output.html) {
    return BrokenRule{{"output.video"},
                      "output",
                      "frames and video are both off: nothing to write (formats names no "
                      "\"gltf\" or \"html\")"};
  }
  return std::nullopt;
}

std::int64_t frame_count(const Scene& scene) {
  return static_cast<std::int64_t>(rounded_frames(scene.duration, scene.fps));
}

std::int64_t poster_frame(const Scene& scene) {
  const std::int64_t count = frame_count(scene);
  if (!scene.output.poster_time) return count / 2;
  const double nearest = std::round(*scene.output.poster_time * static_cast<double>(scene.fps));
  return std::min(static_cast<std::int64_t>(nearest), count - 1);
}

}  // namespace tumble::scene
