#include "render/occluders.hpp"

#include <algorithm>
#include <numeric>

#include <Eigen/Geometry>

namespace tumble::render {
namespace {

double reach_of(const Box& box) {
  return kOcclusionReach * box.size.maxCoeff();
}

}  // namespace

std::vector<std::array<int, kOccludersPerBody>> nearest_occluders(const std::vector<Box>& boxes) {
  const std::size_t n = boxes.size();
  std::vector<std::array<int, kOccludersPerBody>> out(n);
  for (auto& list : out) list.fill(-1);
  std::vector<double> radius(n);
  double widest = 0.0;  // the largest radius + reach of any body
  for (std::size_t i = 0; i < n; ++i) {
    radius[i] = 0.5 * boxes[i].size.norm();
    widest = std::max(widest, radius[i] + reach_of(boxes[i]));
  }
  // Sweep along x: only bodies whose centres are within radius + widest of each other can reach.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].position.x() < boxes[b].position.x();
  });
  std::vector<std::pair<double, int>> near;  // (gap, index)
  for (std::size_t at = 0; at < n; ++at) {
    const std::size_t i = order[at];
    near.clear();
    const double window = radius[i] + widest;
    const auto consider = [&](std::size_t j) {
      // Only a box's and a ball's forms are exact: the box around a capsule, cylinder or hull
      // would hide the sky from points of a neighbour that it does not cover.
      if (boxes[j].solid != Solid::box && boxes[j].solid != Solid::ball) return;
      const double gap = (boxes[i].position - boxes[j].position).norm() - radius[i] - radius[j];
      if (gap < reach_of(boxes[j])) near.emplace_back(std::max(gap, 0.0), static_cast<int>(j));
    };
    for (std::size_t k = at; k-- > 0;) {
      if (boxes[i].position.x() - boxes[order[k]].position.x() > window) break;
      consider(order[k]);
    }
    for (std::size_t k = at + 1; k < n; ++k) {
      if (boxes[order[k]].position.x() - boxes[i].position.x() > window) break;
      consider(order[k]);
    }
    const std::size_t kept = std::min<std::size_t>(near.size(), kOccludersPerBody);
    std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(kept), near.end());
    for (std::size_t k = 0; k < kept; ++k) out[i][k] = near[k].second;
  }
  return out;
}

std::vector<float> occluder_texels(const std::vector<Box>& boxes) {
  std::vector<float> out;
  const std::size_t rows = (boxes.size() + kOccludersPerRow - 1) / kOccludersPerRow;
  out.reserve(16 * kOccludersPerRow * rows);
  for (const Box& box : boxes) {
    const Eigen::Matrix3d rotation = box.orientation.normalized().toRotationMatrix();
    const double reach = reach_of(box);
    const Vec3 half = 0.5 * box.size;
    const double texels[16] = {box.position.x(), box.position.y(),
                               box.position.z(), box.solid == Solid::ball ? -reach : reach,
                               rotation(0, 0),   rotation(1, 0),
                               rotation(2, 0),   half.x(),
                               rotation(0, 1),   rotation(1, 1),
                               rotation(2, 1),   half.y(),
                               rotation(0, 2),   rotation(1, 2),
                               rotation(2, 2),   half.z()};
    for (const double value : texels) out.push_back(static_cast<float>(value));
  }
  out.resize(16 * kOccludersPerRow * rows, 0.0f);
  return out;
}

}  // namespace tumble::render
