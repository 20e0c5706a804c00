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

std::string frame_limit_problem(double duration, std::int64_t fps) {
  const double frames = std::round(duration * static_cast<double>(fps));
  if (frames <= static_cast<double>(kMaxFrames)) return {};
  char count[32];
  std::snprintf(count, sizeof count, "%.6g", frames);
  return "duration × fps asks for " + std::string(count) + " frames, more than the limit of " +
         std::to_string(kMaxFrames);
}

}  // namespace tumble::scene
