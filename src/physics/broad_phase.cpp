#include "physics/broad_phase.hpp"

#include <algorithm>

namespace tumble::physics {

Bounds box_bounds(const Vec3& position, const Mat3& rotation, const Vec3& half_size,
                  double margin) {
  // The box's reach along world axis k is Σ_i |R_ki| h_i.
  const Vec3 reach = rotation.cwiseAbs() * half_size + Vec3::Constant(margin);
  return {.lower = position - reach, .upper = position + reach};
}

Bounds merged(const Bounds& a, const Bounds& b) {
  return {.lower = a.lower.cwiseMin(b.lower), .upper = a.upper.cwiseMax(b.upper)};
}

void overlapping_pairs(const std::vector<Bounds>& bounds, std::vector<std::uint32_t>& order,
                       std::vector<BodyPair>& out) {
  out.clear();
  order.resize(bounds.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  // Sweep along the axis the boxes are most spread on (fewest overlapping intervals); ties broken
  // by index so the sort's result is unique.
  Vec3 sum = Vec3::Zero(), squares = Vec3::Zero();
  for (const Bounds& b : bounds) {
    sum += b.lower;
    squares += b.lower.cwiseProduct(b.lower);
  }
  const double count = static_cast<double>(bounds.size());
  int axis = 0;
  (squares - sum.cwiseProduct(sum) / std::max(count, 1.0)).maxCoeff(&axis);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const double la = bounds[a].lower[axis], lb = bounds[b].lower[axis];
    return la < lb || (la == lb && a < b);
  });
  for (std::size_t n = 0; n < order.size(); ++n) {
    const Bounds& first = bounds[order[n]];
    for (std::size_t m = n + 1; m < order.size(); ++m) {
      const Bounds& second = bounds[order[m]];
      if (second.lower[axis] > first.upper[axis]) break;  // sorted: no later one reaches back
      if (!first.overlaps(second)) continue;
      out.emplace_back(std::min(order[n], order[m]), std::max(order[n], order[m]));
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace tumble::physics
