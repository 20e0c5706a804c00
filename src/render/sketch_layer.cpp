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
  const double reach = half + 1.0;  // past it, no pixel centre is covered
  std::vector<Eigen::Vector2d> points;
  points.reserve(stroke.points.size());
  for (const Eigen::Vector2d& p : stroke.points) points.push_back(p * scale);
  Eigen::Vector2d low = points[0], high = points[0];
  for (const Eigen::Vector2d& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  // The stroke's pixels on the frame, and their coverage: each segment raises the coverage of
  // the pixels near it (the largest, so joints never blend twice), then all blend once. Each
  // segment visits only its own box: the cost is the stroke's length times its width.
  const int x0 = std::max(0, static_cast<int>(std::floor(low.x() - reach)));
  const int y0 = std::max(0, static_cast<int>(std::floor(low.y() - reach)));
  const int x1 = std::min(image.width - 1, static_cast<int>(std::ceil(high.x() + reach)));
  const int y1 = std::min(image.height - 1, static_cast<int>(std::ceil(high.y() + reach)));
  if (x1 < x0 || y1 < y0) return;
  const int width = x1 - x0 + 1;
  std::vector<float> coverage(static_cast<std::size_t>(width) * (y1 - y0 + 1), 0.0f);
  const auto cover = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const int sx0 = std::max(x0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - reach)));
    const int sy0 = std::max(y0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - reach)));
    const int sx1 = std::min(x1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + reach)));
    const int sy1 = std::min(y1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + reach)));
    for (int y = sy0; y <= sy1; ++y) {
      for (int x = sx0; x <= sx1; ++x) {
        const double d = distance_to_segment(Eigen::Vector2d(x + 0.5, y + 0.5), a, b);
        const float c = static_cast<float>(std::clamp(half + 0.5 - d, 0.0, 1.0));
        float& kept = coverage[static_cast<std::size_t>(y - y0) * width + (x - x0)];
        kept = std::max(kept, c);
      }
    }
  };
  if (points.size() == 1) cover(points[0], points[0]);
  for (std::size_t k = 1; k < points.size(); ++k) cover(points[k - 1], points[k]);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const float c = coverage[static_cast<std::size_t>(y - y0) * width + (x - x0)];
      if (c > 0.0f) blend(image, static_cast<std::size_t>(y) * image.width + x, stroke.color, c);
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
