// Joints: what holds two bodies (or a body and the world) together, and the constraint rows each
// kind makes at the bodies' states. A joint's equality rows (a ball's point, a hinge's two
// axes, a slider's line, a weld's pose, a rigid rod's length) keep C = 0; its one-sided rows
// (limits, a rope's length, a distance's range) keep C >= 0; a motor drives a speed with a
// bounded effort. physics/joint_solve.hpp solves them.
//
// Every row is a direction in the two bodies' velocities: its rate is
// Ċ = linear_a·v_a + angular_a·ω_a + linear_b·v_b + angular_b·ω_b (world frame), and an impulse λ
// along it gives body a the linear impulse λ linear_a and the angular impulse λ angular_a (and b
// likewise). `curvature` is J̇v, what C̈ is when neither body accelerates: with it the rows hold
// at the acceleration level inside every stage of an integrator (Baraff, "Linear-time dynamics
// using Lagrange multipliers", SIGGRAPH 1996; Catto, "Modeling and Solving Constraints", GDC 2009).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "physics/rigid_body.hpp"

namespace tumble::physics {

enum class JointKind { ball, hinge, slider, fixed, distance };

// body_b of a joint held to the world.
inline constexpr std::uint32_t kWorldBody = UINT32_MAX;

// A bound on a joint's coordinate: rad for a hinge (its angle from t = 0), m for a slider (its
// travel from t = 0).
struct JointLimits {
  double lower = 0.0;
  double upper = 0.0;
};

// A motor drives the joint's speed (rad/s for a hinge, m/s for a slider) towards `speed` with at
// most `max_effort` (N m for a hinge, N for a slider).
struct JointMotor {
  double speed = 0.0;
  double max_effort = 0.0;
};

struct Joint {
  std::string name;
  JointKind kind = JointKind::ball;
  std::uint32_t a = 0;           // a body's index
  std::uint32_t b = kWorldBody;  // another's, or kWorldBody
  Vec3 anchor_a = Vec3::Zero();  // the joint's point on a, a's body frame (m)
  Vec3 anchor_b = Vec3::Zero();  // on b, b's body frame (the world frame for the world) (m)
  // Hinge: the axis; slider: the direction of travel. Unit, in a's and in b's body frames.
  Vec3 axis_a = Vec3::UnitZ();
  Vec3 axis_b = Vec3::UnitZ();
  // Two unit vectors normal to axis_b and to each other, b's body frame.
  Vec3 normal_b[2] = {Vec3::UnitX(), Vec3::UnitY()};
  // a's orientation in b's frame at t = 0: conj(q_b) q_a, where angles are measured from.
  Quat rest = Quat::Identity();
  std::optional<JointLimits> limits;
  std::optional<JointMotor> motor;
  // Distance: the length kept between the anchors within [min_length, max_length] (m); equal,
  // a rigid rod. With stiffness > 0 a spring of rest_length (the anchors' distance at t = 0)
  // pulls between them instead (N/m, with damping N s/m), the range then only a stop.
  double min_length = 0.0;
  double max_length = 0.0;
  double rest_length = 0.0;
  double stiffness = 0.0;
  double damping = 0.0;
  bool collide_connected = false;  // whether a and b still collide with each other
};

// A joint of `kind` between bodies a and b (b may be kWorldBody) placed at the bodies' `states`
// (t = 0): its anchors at the world points `anchor_a` and `anchor_b` (one point for all kinds but
// a distance), its axis along the world `axis` (any length but 0; hinge and slider). The rest
// orientation is the bodies' now; a distance is a rigid rod of the anchors' distance now. Limits,
// motor, range and spring are the caller's to set.
Joint place_joint(JointKind kind, std::uint32_t a, std::uint32_t b,
                  std::span<const BodyState> states, const Vec3& anchor_a /* m, world */,
                  const Vec3& anchor_b /* m, world */, const Vec3& axis = Vec3::UnitZ());

// A body as a joint sees it: the world is a body that never moves.
struct JointBody {
  Vec3 position = Vec3::Zero();  // world (m)
  Mat3 rotation = Mat3::Identity();
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();          // world (m/s)
  Vec3 angular_velocity = Vec3::Zero();  // world (rad/s)
  static JointBody of(const BodyState& state);
};

// One constraint row between a joint's two bodies (above).
struct JointRow {
  std::uint32_t joint = 0;  // its joint's index, where the caller numbers them
  std::uint32_t a = 0;
  std::uint32_t b = kWorldBody;
  Vec3 linear_a = Vec3::Zero();
  Vec3 angular_a = Vec3::Zero();  // m for a linear row, 1 for an angular one
  Vec3 linear_b = Vec3::Zero();
  Vec3 angular_b = Vec3::Zero();
  double error = 0.0;      // C (m or rad)
  double curvature = 0.0;  // J̇v (m/s² or rad/s²)
};

// Whether the joint is a distance that is a rigid rod (no range, no spring).
inline bool is_rigid_distance(const Joint& joint) {
  return joint.kind == JointKind::distance && joint.stiffness == 0.0 &&
         joint.min_length == joint.max_length;
}

// The joint's equality rows at the two bodies (b the world's when the joint is held to it):
// ball 3, hinge 5, slider 5, fixed 6, a rigid distance 1, a ranged or sprung distance none.
void equality_rows(const Joint& joint, const JointBody& a, const JointBody& b,
                   std::vector<JointRow>& out);

// The joint's coordinate and its rate: a hinge's angle of a relative to b about its axis since
// t = 0 (rad, in (-π, π]) and its rate (rad/s); a slider's travel of a's anchor relative to b's
// along the axis (m, m/s); a distance's length between the anchors (m, m/s); none for a ball or a
// fixed joint.
struct JointCoordinate {
  double value = 0.0;
  double rate = 0.0;
};
std::optional<JointCoordinate> joint_coordinate(const Joint& joint, const JointBody& a,
                                                const JointBody& b);

// The row along the joint's coordinate (its rate is JointCoordinate::rate), with error 0 and no
// curvature: where limits, motors and a distance's range act.
JointRow coordinate_row(const Joint& joint, const JointBody& a, const JointBody& b);

// The world points of the two anchors (m).
Vec3 anchor_a_world(const Joint& joint, const JointBody& a);
Vec3 anchor_b_world(const Joint& joint, const JointBody& b);
// How far apart the joint's two anchors are at the bodies' `states` (m): 0 for a ball, a hinge
// or a weld that holds.
double joint_opening(const Joint& joint, std::span<const BodyState> states);

// The joint's kind as the scene names it ("ball", "hinge", ...).
const char* joint_kind_name(JointKind kind);

}  // namespace tumble::physics
