// The lever arm of twist friction over a flat contact patch. Under uniform pressure over an area
// A, Coulomb friction resists turning about the normal with at most μ N r̄, where r̄ = (1/A) ∫ |ρ| dA
// is the mean distance of the area from the turning axis: (s/6)(√2 + ln(1 + √2)) ≈ 0.3826 s for a
// square of side s, 2R/3 for a disk. A manifold's corners are the patch's vertices, and their mean
// distance (the half-diagonal 0.7071 s for a square face) overstates the arm 1.85 times, so a
// spinning cube stopped in 2.42 s instead of 4.44 (issue Contact III; the formulas in
// ../shared/research/contact-hard.md §5).
#pragma once

#include <span>

#include "physics/rigid_body.hpp"

namespace tumble::physics {

// r̄ (m) of the convex patch whose vertices are `points` (world frame, in any order, at most a
// few), about the axis along the unit `normal` through `centre` (world frame, inside the patch):
// the area's mean distance for three or more points that span an area, a quarter of the length
// for points along a line (uniform pressure along a segment about its middle), 0 for one point.
double patch_twist_arm(std::span<const Vec3> points, const Vec3& normal, const Vec3& centre);

}  // namespace tumble::physics
