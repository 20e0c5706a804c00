// Contact of capsules: round shapes whose core is a segment (shapes.hpp), against a sphere or a
// capsule (the closest points of two segments) and against a box (the closest points of a segment
// and a box, or, with the segment inside the box, the separating axis of least overlap). A capsule
// lying along a face or along another capsule touches along a line: two points, the ends of the
// part of its segment over the face or beside the other segment (Box2D v3's b2CollideCapsules and
// Box3D's capsule-hull contact clip the same way).
#pragma once

#include "physics/box_box.hpp"
#include "physics/pair_contact.hpp"

namespace tumble::physics {

// The closest points of segments [p0, p1] and [q0, q1] (world, m): p0 + s (p1 − p0) and
// q0 + t (q1 − q0), s and t in [0, 1]. Parallel segments give the s of least value (Ericson,
// "Real-Time Collision Detection", 5.1.9).
struct SegmentParameters {
  double s = 0.0;
  double t = 0.0;
};
SegmentParameters closest_segment_points(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                         const Vec3& q1);

// Two round shapes (spheres or capsules: a sphere is a capsule of no length), the normal from A
// towards B: one point between the closest points of their cores, or two where two capsules lie
// side by side (their segments within 0.1 rad of parallel): the ends of the stretch where they
// overlap.
PairManifold round_round_manifold(const ShapePose& a, const ShapePose& b, double margin);

// A box and a capsule, the normal from the box towards the capsule. Over a face, the ends of the
// part of the segment above it (one of them, or both when the capsule lies along the face); by an
// edge or a corner, the one closest point; with the segment inside the box, the axis of least
// overlap among the box's faces and the crossings of its edges with the segment.
PairManifold box_capsule_manifold(const BoxPose& box, const ShapePose& capsule, double margin);

}  // namespace tumble::physics
