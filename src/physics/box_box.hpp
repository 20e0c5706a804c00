// The contact of two boxes (narrow phase), as pure geometry: the separating-axis test over the
// 15 axes of two boxes, then either a face contact (the incident face clipped to the reference
// face, at most four points) or one edge–edge point. No solver state is read or written.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "physics/contact.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::physics {

// A box placed in the world.
struct BoxPose {
  Vec3 position = Vec3::Zero();      // centre, world frame (m)
  Mat3 rotation = Mat3::Identity();  // body-to-world; its columns are the body axes in the world
  Vec3 half_size = Vec3::Constant(0.5);  // half edge lengths along the body axes (m)
};

// One contact point of a pair of bodies.
//
// Feature ids say which features of the boxes made the point, so that a solver can match points
// from step to step (Box2D's feature pairs, erincatto/box2d docs/simulation.md). A face index is
// 2 axis + (1 on the + side); an edge index is 4 axis + the signs of its other two coordinates
// (bit 0: the lower axis, set when +). Bits of the id:
// - face contact: [0, 2) 0 when A holds the reference face, 1 when B does; [2, 5) reference face;
//   [5, 8) incident face; [8, 11) and [11, 14) the two lines the point lies on, the lower first:
//   0–3 an edge of the incident face, 4–7 a side of the reference face (4, 5: the lower other
//   axis, − then +; 6, 7: the higher). A corner of the incident face lies on two incident edges,
//   a clipped point on an incident edge and a side, a corner of the reference face on two sides.
// - edge contact: [0, 2) 2; [2, 6) A's edge; [6, 10) B's edge.
struct PairPoint {
  std::uint32_t feature = 0;
  Vec3 point_a = Vec3::Zero();  // the contact point relative to A's centre, A's body frame (m)
  Vec3 point_b = Vec3::Zero();  // the same point relative to B's centre, B's body frame (m)
  double separation = 0.0;      // along the normal, negative when overlapping (m)
  Impulses impulses;            // for warm starting; the narrow phase leaves them zero
  // Bit 0: the point lies on A's side as a cylinder's side touches, along a line across its axis
  // (anchored on the axis, as a capsule's point on its segment, so that it stays under the contact
  // as the cylinder rolls); bit 1: on B's.
  std::uint8_t on_axis = 0;
};

struct PairManifold {
  Vec3 normal = Vec3::Zero();  // unit, world frame, from A towards B
  int count = 0;
  std::array<PairPoint, kMaxManifoldPoints> points;
  PatchImpulses friction;  // of the manifold as a whole (physics/contact_solver.hpp)
  PatchMemo patch;
};

// Which of the 15 axes the separating-axis test chose.
enum class BoxAxisKind : std::uint8_t { face_a, face_b, edge_pair };

struct BoxAxis {
  BoxAxisKind kind = BoxAxisKind::face_a;
  int axis_a = 0;               // face_a: A's face normal axis (0–2); edge_pair: A's edge axis
  int axis_b = 0;               // face_b: B's face normal axis (0–2); edge_pair: B's edge axis
  Vec3 normal = Vec3::UnitY();  // unit, world frame, from A towards B
  double separation = 0.0;      // of the boxes' projections on the normal; < 0 overlapping (m)
};

// Edges closer to parallel than this sine give no axis: their cross product is noise, and the
// face axes already cover parallel edges (Box3D's B3_PARALLEL_EDGE_TOL, erincatto/box3d
// include/box3d/constants.h).
inline constexpr double kParallelEdgeSine = 0.005;

// How much a later kind of axis must beat the best earlier one to be chosen (m): B's faces must
// beat A's and edge pairs must beat faces by more than this, so a resting pair keeps its axis from
// step to step. Relative part: ODE's dBoxBox fudge_factor 1.05 (odedevs/ode ode/src/box.cpp);
// absolute part: Box3D's face bias 0.1 B3_LINEAR_SLOP = 0.5 mm (erincatto/box3d
// src/convex_manifold.c) and Box2D's 0.1 b2_linearSlop for polygon faces of B over A.
inline double box_axis_bias(double separation /* m */) {
  return 0.05 * std::abs(separation) + 0.0005;
}

// The axis of the separating-axis test over A's three face normals, B's three, and the nine
// cross products of their edges: the largest separation, with the bias above for ties.
BoxAxis box_box_axis(const BoxPose& a, const BoxPose& b);

// The contact of two boxes whose closest features are within `margin` (m) of touching: the
// points with separation below `margin` (speculative ones in [0, margin) included); count 0
// otherwise. Deterministic bit for bit; swapping A and B negates the normal and gives the same
// points, unless the two orders fall on different sides of a bias in box_box_axis.
PairManifold box_box_manifold(const BoxPose& a, const BoxPose& b, double margin);

}  // namespace tumble::physics
