#include "render/sketch_layer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/text_layout.hpp"

namespace tumble::render {
namespace {

// `color` (sRGB-encoded, straight) at `coverage` (0-1) "over" the pixel at index i; on a
// transparent frame its alpha "over" the alpha below, the colour as over the background colour
// (made straight at the end: straight_alpha.hpp).
void blend(io::Image& image, std::size_t i, const Rgba& color, double coverage) {
  const double a = std::clamp(color.w() * coverage, 0.0, 1.0);
  if (a <= 0.0) return;
  std::uint8_t* rgb = image.rgb.data() + 3 * i;
  for (int c = 0; c < 3; ++c) {
    rgb[c] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(color[c], 0.0, 1.0) * a +
                                                   static_cast<double>(rgb[c]) * (1.0 - a)));
  }
  if (!image.alpha.empty()) {
    image.alpha[i] = static_cast<std::uint8_t>(std::lround(255.0 * a + image.alpha[i] * (1.0 - a)));
  }
}

// The distance from p to the segment from a to b.
double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                           const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double along = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + along * ab)).norm();
}

void draw_stroke(const Stroke& stroke, io::Image& image) {
  if (stroke.points.empty()) return;
  const double scale = scale_to_frame(1.0, image.height);  // px per px at 720 rows
  const double half = 0.5 * std::max(stroke.width * scale, 1.0);
  std::vector<Eigen::Vector2d> points;
  points.reserve(stroke.points.size());
  for (const Eigen::Vector2d& p : stroke.points) points.push_back(p * scale);
  Eigen::Vector2d low = points[0], high = points[0];
  for (const Eigen::Vector2d& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const int x0 = std::max(0, static_cast<int>(std::floor(low.x() - half - 1.0)));
  const int y0 = std::max(0, static_cast<int>(std::floor(low.y() - half - 1.0)));
  const int x1 = std::min(image.width - 1, static_cast<int>(std::ceil(high.x() + half + 1.0)));
  const int y1 = std::min(image.height - 1, static_cast<int>(std::ceil(high.y() + half + 1.0)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d centre(x + 0.5, y + 0.5);
      double nearest = distance_to_segment(centre, points[0], points[0]);
      for (std::size_t k = 1; k < points.size(); ++k) {
        // Only segments whose box, grown by the half width and a pixel, holds the pixel.
        const Eigen::Vector2d& a = points[k - 1];
        const Eigen::Vector2d& b = points[k];
        if (centre.x() < std::min(a.x(), b.x()) - half - 1.0 ||
            centre.x() > std::max(a.x(), b.x()) + half + 1.0 ||
            centre.y() < std::min(a.y(), b.y()) - half - 1.0 ||
            centre.y() > std::max(a.y(), b.y()) + half + 1.0) {
          continue;
        }
        nearest = std::min(nearest, distance_to_segment(centre, a, b));
      }
      const double coverage = std::clamp(half + 0.5 - nearest, 0.0, 1.0);
      if (coverage > 0.0) {
        blend(image, static_cast<std::size_t>(y) * image.width + x, stroke.color, coverage);
      }
    }
  }
}

}  // namespace

std::vector<PixelBox> panel_boxes(const std::vector<Panel>& panels, int width, int height) {
  std::vector<PixelBox> out;
  const double scale = scale_to_frame(1.0, height);
  for (const Panel& panel : panels) {
    const int x0 = std::clamp(static_cast<int>(std::lround(panel.corner.x() * scale)), 0, width);
    const int y0 = std::clamp(static_cast<int>(std::lround(panel.corner.y() * scale)), 0, height);
    const int x1 = std::clamp(
        static_cast<int>(std::lround((panel.corner.x() + panel.size.x()) * scale)), 0, width);
    const int y1 = std::clamp(
        static_cast<int>(std::lround((panel.corner.y() + panel.size.y()) * scale)), 0, height);
    if (x1 > x0 && y1 > y0) out.push_back({x0, y0, x1 - x0, y1 - y0});
  }
  return out;
}

void draw_sketch(const std::vector<Panel>& panels, const std::vector<Stroke>& strokes,
                 io::Image& image) {
  for (const Panel& panel : panels) {
    const auto box = panel_boxes({panel}, image.width, image.height);
    if (box.empty()) continue;
    for (int y = box[0].y; y < box[0].y + box[0].height; ++y) {
      for (int x = box[0].x; x < box[0].x + box[0].width; ++x) {
        blend(image, static_cast<std::size_t>(y) * image.width + x, panel.color, 1.0);
      }
    }
  }
  for (const Stroke& stroke : strokes) draw_stroke(stroke, image);
}

}  // namespace tumble::render
