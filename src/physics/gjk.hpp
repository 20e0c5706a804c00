// The distance between two convex shapes' cores, or how deep they overlap: the GJK distance
// algorithm (Gilbert, Johnson & Keerthi, IEEE J. Robotics and Automation 4(2), 1988), its simplex
// reduced by the subset test of Johnson's algorithm; where the cores overlap, the expanding
// polytope algorithm (van den Bergen, "Proximity Queries and Penetration Depth Computation on 3D
// Game Objects", GDC 2001) gives the least translation that parts them. A shape's core is the
// shape without its rounding (shapes.hpp): a box, a cylinder or a hull itself, a capsule's segment,
// a sphere's centre. Pure geometry; no allocation.
#pragma once

#include "physics/pair_contact.hpp"

namespace tumble::physics {

// The point of the shape's core farthest along `direction` (world frame, need not be unit): its
// support point (world, m). Ties go to a fixed choice, so the result is deterministic.
Vec3 core_support(const ShapePose& shape, const Vec3& direction);

struct CoreDistance {
  double distance = 0.0;        // between the cores (m); negative: how deep they overlap
  Vec3 normal = Vec3::UnitY();  // unit, world, from A towards B: moving B along it parts them
  Vec3 on_a = Vec3::Zero();     // A's core point nearest B's (or deepest in it), world (m)
  Vec3 on_b = Vec3::Zero();     // and B's
};

// The signed distance between the cores of two shapes, at least one of them a solid (a box, a
// cylinder or a hull: the difference of the cores then has a volume). Separated or overlapping,
// to within 1e-8 m (a curved cylinder's; polytopes' mostly to round-off), short of the true depth
// where EPA runs out of corners (the test of random pairs: within 1e-5 m).
// `guess`: the normal (unit, from A towards B) the pair had lately, or zero: GJK starts from the
// cores' support points along it, which saves most of its rounds where bodies move little from
// step to step (a curved cylinder's 15 come down to a few).
CoreDistance core_distance(const ShapePose& a, const ShapePose& b,
                           const Vec3& guess = Vec3::Zero());

}  // namespace tumble::physics
