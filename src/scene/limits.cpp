#include "scene/limits.hpp"

#include <cmath>
#include <cstdio>

namespace tumble::scene {

std::string pixel_limit_problem(std::int64_t width, std::int64_t height) {
  if (width * height <= kMaxPixels) return {};
  return std::to_string(width) + " × " + std::to_string(height) + " is " +
         std::to_string(width * height) + " pixels, more than the limit of " +
         std::to_string(kMaxPixels) + " (8192 × 4320)";
}

std::string frame_count_problem(double duration, std::int64_t fps) {
  const double frames = std::round(duration * static_cast<double>(fps));
  char text[160];
  if (frames < 1.0) {
    std::snprintf(text, sizeof text,
                  "duration × fps gives no frame (%.6g s at %lld frames/s); a scene needs a "
                  "duration of at least half a frame, %.6g s",
                  duration, static_cast<long long>(fps), 0.5 / static_cast<double>(fps));
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

}  // namespace tumble::scene
