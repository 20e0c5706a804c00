#include "physics/patch_friction.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tumble::physics {
namespace {

constexpr std::size_t kMostPoints = 8;

// ∫ |ρ| dA over the triangle of the origin and the segment from `p` to `q` (plane coordinates,
// m), taken in polar coordinates about the origin: with d the distance of the segment's line and
// t the coordinate along it from the foot of the perpendicular, ∫∫ r² dr dθ = ∫ d³/(3 cos³u) du,
// whose antiderivative is (1/6)(d t √(d² + t²) + d³ asinh(t / d)).
double moment_of_triangle(const std::array<double, 2>& p, const std::array<double, 2>& q) {
  const double ex = q[0] - p[0], ey = q[1] - p[1];
  const double length = std::hypot(ex, ey);
  if (length == 0.0) return 0.0;
  const double d = std::abs(p[0] * ey - p[1] * ex) / length;  // distance of the line (m)
  const double tp = (p[0] * ex + p[1] * ey) / length;         // along it, from its foot (m)
  const double tq = tp + length;
  const auto antiderivative = [d](double t) {
    return (d * t * std::sqrt(d * d + t * t) + d * d * d * std::asinh(t / d)) / 6.0;
  };
  return d == 0.0 ? 0.0 : antiderivative(tq) - antiderivative(tp);
}

}  // namespace

double patch_twist_arm(std::span<const Vec3> points, const Vec3& normal, const Vec3& centre) {
  const std::size_t count = std::min(points.size(), kMostPoints);
  if (count < 2) return 0.0;
  // Plane coordinates about the centre, from a basis normal to the normal.
  const Vec3 u = normal.unitOrthogonal();
  const Vec3 w = normal.cross(u);
  std::array<std::array<double, 2>, kMostPoints> flat;
  std::array<double, kMostPoints> angle;
  std::array<std::size_t, kMostPoints> order;
  double extent = 0.0;  // the patch's largest distance from the centre (m)
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 offset = points[i] - centre;
    flat[i] = {offset.dot(u), offset.dot(w)};
    angle[i] = std::atan2(flat[i][1], flat[i][0]);
    order[i] = i;
    extent = std::max(extent, std::hypot(flat[i][0], flat[i][1]));
  }
  std::sort(order.begin(), order.begin() + count,
            [&](std::size_t a, std::size_t b) { return angle[a] < angle[b]; });
  double area = 0.0, moment = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const auto& p = flat[order[k]];
    const auto& q = flat[order[(k + 1) % count]];
    area += 0.5 * std::abs(p[0] * q[1] - p[1] * q[0]);
    moment += moment_of_triangle(p, q);
  }
  // Points along a line (an edge on a face, two corners) span no area: uniform pressure along a
  // segment of length L about its middle has the mean distance L / 4.
  if (area <= 1e-9 * extent * extent) {
    double low = 0.0, high = 0.0;
    const double dx = flat[order[0]][0], dy = flat[order[0]][1];
    const double norm = std::hypot(dx, dy);
    if (norm == 0.0) return 0.0;
    for (std::size_t i = 0; i < count; ++i) {
      const double along = (flat[i][0] * dx + flat[i][1] * dy) / norm;
      low = std::min(low, along);
      high = std::max(high, along);
    }
    return (high - low) / 4.0;
  }
  return moment / area;
}

}  // namespace tumble::physics
