#include "render/straight_alpha.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace tumble::render {

void make_alpha_straight(io::Image& image, const Color& background) {
  if (image.alpha.empty()) return;
  // The clear colour as the framebuffer stores it: GL rounds a float to the nearest 8-bit level.
  std::array<int, 3> clear{};
  for (int c = 0; c < 3; ++c) {
    clear[c] = static_cast<int>(std::lround(std::clamp(background[c], 0.0, 1.0) * 255.0));
  }
  for (std::size_t i = 0; i < image.alpha.size(); ++i) {
    const int alpha = image.alpha[i];
    if (alpha == 0 || alpha == 255) continue;
    std::uint8_t* pixel = &image.rgb[3 * i];
    for (int c = 0; c < 3; ++c) {
      // (colour − background × (1 − a)) / a, in 0-255 units with a = alpha / 255.
      const double straight = (255.0 * pixel[c] - clear[c] * (255.0 - alpha)) / alpha;
      pixel[c] = static_cast<std::uint8_t>(std::lround(std::clamp(straight, 0.0, 255.0)));
    }
  }
}

}  // namespace tumble::render
