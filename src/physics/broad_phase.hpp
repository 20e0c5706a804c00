// Which bodies may touch within a step: sweep and prune over axis-aligned bounding boxes (Baraff,
// "Dynamic Simulation of Non-Penetrating Rigid Bodies", 1992, ch. 7; Cohen et al., I-COLLIDE,
// 1995). The boxes are sorted along the axis their positions spread most on and each is compared
// only with those whose interval on that axis overlaps its own, so a step costs O(n log n + k) for
// n bodies and k close pairs, not O(n²).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "physics/rigid_body.hpp"

namespace tumble::physics {

// An axis-aligned box in the world (m).
struct Bounds {
  Vec3 lower = Vec3::Zero();
  Vec3 upper = Vec3::Zero();

  bool overlaps(const Bounds& other) const {
    return (lower.array() <= other.upper.array()).all() &&
           (other.lower.array() <= upper.array()).all();
  }
};

// The bounds of a box with half edge lengths `half_size` (m, body frame) at `position` (m, world)
// turned by `rotation` (body to world), grown by `margin` (m) on every side.
Bounds box_bounds(const Vec3& position, const Mat3& rotation, const Vec3& half_size, double margin);
// The smallest bounds holding both.
Bounds merged(const Bounds& a, const Bounds& b);

// A pair of body indices, first < second.
using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

// Into `out`: every pair (i, j), i < j, whose bounds overlap, in increasing (i, j) order, so that
// the order depends on nothing but the bounds (not on addresses or on the sort's tie-breaking).
// `order` is scratch kept between calls.
void overlapping_pairs(const std::vector<Bounds>& bounds, std::vector<std::uint32_t>& order,
                       std::vector<BodyPair>& out);

}  // namespace tumble::physics
