// The screen rectangle that holds a set of world points seen through a view-projection: the
// shadows' rectangle and the occlusion's (renderer.cpp, occlusion_layer.cpp), where a pass is
// drawn again. Internal to src/render/.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace tumble::render {

// A screen rectangle: x, y, width, height in pixels, GL's bottom-up rows.
using PixelRect = std::array<int, 4>;

class ScreenBounds {
 public:
  explicit ScreenBounds(const Eigen::Matrix4d& view_projection)
      : view_projection_(view_projection) {}

  // Takes in a world point; false when it lies behind the camera (then nothing short of the
  // whole screen holds the set).
  bool take_in(const Eigen::Vector3d& point) {
    const Eigen::Vector4d clip = view_projection_ * point.homogeneous();
    if (clip.w() <= 1e-9) return false;
    low_ = low_.cwiseMin(clip.head<2>() / clip.w());
    high_ = high_.cwiseMax(clip.head<2>() / clip.w());
    nearest_ = std::min(nearest_, clip.w());
    return true;
  }

  // Pixels a world length `length` (m) spans at most on a `height`-row picture, at the nearest
  // point taken in (a perspective projection: the view-projection's second row has the focal
  // scale as its length).
  double pixels_of(double length, int height) const {
    return length * view_projection_.row(1).head<3>().norm() * 0.5 * height / nearest_;
  }

  // The rectangle of whole pixels around the points, `margin` pixels wider each way, clamped to
  // width × height; nothing when no point was taken in or none is on the screen.
  std::optional<PixelRect> pixels(int width, int height, int margin) const {
    if (nearest_ == kNone) return std::nullopt;
    const auto pixel = [](double ndc, int size) { return 0.5 * (ndc + 1.0) * size; };
    const int x0 = std::max(0, static_cast<int>(std::floor(pixel(low_.x(), width))) - margin);
    const int y0 = std::max(0, static_cast<int>(std::floor(pixel(low_.y(), height))) - margin);
    const int x1 = std::min(width, static_cast<int>(std::ceil(pixel(high_.x(), width))) + margin);
    const int y1 = std::min(height, static_cast<int>(std::ceil(pixel(high_.y(), height))) + margin);
    if (x1 <= x0 || y1 <= y0) return std::nullopt;
    return PixelRect{x0, y0, x1 - x0, y1 - y0};
  }

 private:
  static constexpr double kNone = 1e30;
  Eigen::Matrix4d view_projection_;
  Eigen::Vector2d low_ = Eigen::Vector2d::Constant(kNone);
  Eigen::Vector2d high_ = Eigen::Vector2d::Constant(-kNone);
  double nearest_ = kNone;  // the smallest clip w taken in
};

}  // namespace tumble::render
