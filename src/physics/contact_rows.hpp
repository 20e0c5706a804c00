// The one place that turns manifolds into solver rows (Catto, "Iterative Dynamics with Temporal
// Coherence", GDC 2005: a normal row per point; a friction patch per manifold,
// contact_solver.hpp), for planes and pairs alike, and takes the solve's impulses back to the
// manifolds by index. Every solve builds its rows here: an impact with the planes, a body resting
// alone, a converged island, a sub-stepped one and the sub-steps that find points again. A new
// shape brings manifolds, a joint its own rows; neither adds a way of building these.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/contact_island.hpp"
#include "physics/contact_memory.hpp"

namespace tumble::physics {

// Where a manifold's rows sit in ContactRows: its points (and positions) [first, first + slots),
// the slots past its count empty (no row, far apart, in no patch), and its friction patch.
struct RowSlots {
  std::uint32_t first = 0;
  std::uint32_t slots = 0;
  std::uint32_t patch = 0;
};
// Room for a manifold of up to `slots` points at the end of `rows`.
RowSlots add_slots(ContactRows& rows, std::uint32_t slots);

// A pose the rows are written at: a body's centre (m, world) and its body-to-world rotation.
struct PoseRef {
  const Vec3& position;
  const Mat3& rotation;
};
// World position of a body point (body frame, m) of the body at `pose`.
inline Vec3 world_point(const PoseRef& pose, const Vec3& body_point) {
  return pose.position + pose.rotation * body_point;
}

// A body's manifold with a plane, as its rows need it. The rows start from the manifold's
// impulses (its points' normal ones; its friction, world frame, when keeps_friction).
struct PlaneManifoldRows {
  const Manifold& manifold;
  const Plane& plane;
  const Material& material;  // of the body and the plane, combined
  std::uint32_t body;        // the body's index among rows.bodies
  const Mat3& rotation;      // the body's at the pose the rows are for
  ManifoldRef source;
  bool keeps_friction;
  // The body's rounding (shapes.hpp): a round body's rows measure its points' cores (a sphere's
  // centre, a capsule's ends), which stand its radius off the plane whichever way it has turned,
  // and push at the point below each.
  double rounding = 0.0;
};

// A pair's manifold, as its rows need it. The solver pushes its first body along the normal,
// which points from A to B: B is the rows' first body (A when B is static, pushed along −normal).
// The projection measures a point's separation as the manifold's plus the anchors' relative
// motion along the normal since `base`, the poses at which the manifold's separations hold.
struct PairManifoldRows {
  const PairManifold& manifold;
  const Material& material;  // of the two bodies, combined
  // The indices of A and B among rows.bodies, or kStatic for a static body (one of them at most).
  std::uint32_t a, b;
  const Mat3& a_rotation;  // A's at the pose the rows are for
  const Mat3& b_rotation;
  PoseRef a_base, b_base;
  // s: a point apart by s may approach at s / speculative_step (Catto, "Speculative contacts",
  // 2013); 0: no such speed (a sub-stepped solve measures each sub-step's separations).
  double speculative_step;
  ManifoldRef source;
  bool keeps_friction;
  // A's and B's shapes: a round body's anchor is the point of its core under the contact (a
  // sphere's centre, a point of a capsule's segment) and its arm stays where the manifold put it,
  // so that a ball's point does not turn away with the ball within a step (found at the step's
  // start, a rolling ball's point turned off its contact, and the ball ran 0.7% fast down a static
  // ramp and sank 0.06 mm into it).
  const Shape& a_shape;
  const Shape& b_shape;
};

// The manifold's rows onto the end of `rows` (its count of slots), or into `at`.
void append_rows(const PlaneManifoldRows& manifold, ContactRows& rows);
void write_rows(const PlaneManifoldRows& manifold, const RowSlots& at, ContactRows& rows);
void append_rows(const PairManifoldRows& manifold, ContactRows& rows);
void write_rows(const PairManifoldRows& manifold, const RowSlots& at, ContactRows& rows);

// What a row carries from one sub-step's rows to the next when its manifold is found again
// (island_solve.cpp): per slot the accumulated normal impulse (N s), and the patch's friction
// (world frame).
struct CarriedImpulses {
  double impulse[kMaxManifoldPoints] = {};
  PatchImpulses friction;
};
// Into `carried`, for each point of `now` whose feature the manifold `then` (in `at`) has, that
// point's carried values, and into now's points the impulses of then's.
template <class Manifold>
void carry_by_feature(Manifold& now, const Manifold& then, const RowSlots& at,
                      const ContactRows& rows, CarriedImpulses& carried) {
  for_each_match(now, then, [&](int k, int j) {
    now.points[static_cast<std::size_t>(k)].impulses =
        then.points[static_cast<std::size_t>(j)].impulses;
    const ContactConstraint& c = rows.points[at.first + static_cast<std::uint32_t>(j)];
    carried.impulse[k] = c.normal_impulse;
  });
}
// The friction impulses of the patch in `at` (world frame, N s and N m s).
PatchImpulses patch_impulses(const FrictionPatch& patch);
// The carried values into the rows in `at`, written again for the manifold found now, the
// friction turned onto the new tangents.
void restore(const CarriedImpulses& carried, const RowSlots& at, ContactRows& rows);

// The rows' accumulated impulses back to the manifolds they were built from (each patch's
// source): per body its plane manifolds, and the step's pairs.
void store_impulses(const ContactRows& rows, std::span<std::vector<Manifold>> plane_manifolds,
                    std::span<PairContact> pairs);

}  // namespace tumble::physics
