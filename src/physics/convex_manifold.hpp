// The contact of any two convex shapes that have no closed form of their own: a cylinder with a
// box, a capsule or a cylinder, and a hull with a box, a capsule, a cylinder or a hull. Their cores
// are measured by GJK, or by EPA where they overlap (physics/gjk.hpp); the manifold is then built
// from the features the normal meets, as Jolt's and Box3D's manifold builders do:
//
// - A face of either core whose separating axis is within box_axis_bias of the cores' distance
//   (a box's or a hull's face, a cylinder's end) is the reference face, A's before B's unless B's
//   beats it by the bias. The other shape's feature facing it (a box's or hull's face, a
//   capsule's segment, a cylinder's lowest rim points and lowest line) is clipped to the face's
//   side planes (Sutherland and Hodgman); up to four of the points below `margin` are kept: the
//   deepest, the farthest from it, then those that widen the patch most.
// - Else a line of either (a cylinder's side, a capsule's segment) meeting a line of the other
//   within 0.1 rad of parallel: the ends of the stretch where they lie side by side.
// - Else one point, between the cores' nearest (or deepest) points.
//
// A cylinder's end is clipped as the octagon inscribed in it. Pure geometry, as box_box.hpp.
#pragma once

#include "physics/pair_contact.hpp"

namespace tumble::physics {

// The contact of two shapes whose closest features are within `margin` (m) of touching, the normal
// from A towards B: up to four points with separation below `margin`; count 0 otherwise. Any pair
// but two spheres or two capsules (at least one of them a box, a cylinder or a hull).
// `guess`: the normal the pair had lately (core_distance's), or zero.
PairManifold convex_manifold(const ShapePose& a, const ShapePose& b, double margin,
                             const Vec3& guess = Vec3::Zero());

}  // namespace tumble::physics
