// Force and torque laws. A body carries only the laws its scene lists, and only those are
// evaluated: a body with no laws costs nothing here.
#pragma once

#include <limits>
#include <variant>
#include <vector>

#include "physics/rigid_body.hpp"
#include "physics/shapes.hpp"

namespace tumble::physics {

// Uniform gravitational field: F = m g at the centre of mass.
struct Gravity {
  Vec3 acceleration = Vec3(0.0, -9.81, 0.0);  // g, world frame (m/s²)
};

// Constant force through the centre of mass.
struct ConstantForce {
  Vec3 force = Vec3::Zero();  // world frame (N)
};

// Constant torque about the centre of mass.
struct ConstantTorque {
  Vec3 torque = Vec3::Zero();  // world frame (N m)
};

// Viscous drag on the centre of mass: F = -c v.
struct LinearDamping {
  double coefficient = 0.0;  // c (N s/m)
};

// Viscous drag on the rotation: τ = -c ω.
struct AngularDamping {
  double coefficient = 0.0;  // c (N m s)
};

// A world-frame force applied at a point fixed in the body while start <= t < end.
struct ForceAtPoint {
  Vec3 force = Vec3::Zero();  // world frame (N)
  Vec3 point = Vec3::Zero();  // body frame, relative to the centre of mass (m)
  double start = -std::numeric_limits<double>::infinity();  // s
  double end = std::numeric_limits<double>::infinity();     // s
};

// Where a moving spring anchor is at one time.
struct AnchorKey {
  double time = 0.0;           // s
  Vec3 anchor = Vec3::Zero();  // world frame (m)
};

// A damped spring from a world anchor to a point fixed in the body, acting while
// start <= t < end. With d = P - anchor, l = |d|, u = d / l, v_P the velocity of P and v_a the
// anchor's, the force on P is -(k (l - l0) + c (v_P - v_a)·u) u. The anchor is fixed, or moves
// linearly between keys (a scripted mouse drag, Fiedler's "Spring Physics"). The damper acts on
// the velocity relative to the anchor, as a dashpot between two moving ends does: a body dragged
// at constant speed then trails the anchor by nothing, where Fiedler's v_P·u (his anchor never
// moves) would hold it back by a steady c v_a / k, like air drag. For a fixed anchor the two agree.
struct Spring {
  Vec3 anchor = Vec3::Zero();               // world frame (m); used when anchor_keys is empty
  std::vector<AnchorKey> anchor_keys = {};  // times strictly increasing; empty: fixed anchor
  Vec3 attachment = Vec3::Zero();           // body frame, relative to the centre of mass (m)
  double stiffness = 0.0;                   // k (N/m)
  double damping = 0.0;                     // c (N s/m)
  double rest_length = 0.0;                 // l0 (m)
  double start = -std::numeric_limits<double>::infinity();  // s
  double end = std::numeric_limits<double>::infinity();     // s
};

// A spring's anchor at one instant.
struct AnchorMotion {
  Vec3 position = Vec3::Zero();  // world frame (m)
  Vec3 velocity = Vec3::Zero();  // world frame (m/s)
};

// The anchor at time t (s): the fixed anchor at rest; else the first key's anchor at rest before
// its time, the last key's at rest from its time on, and in between the straight line between
// the two keys around t at that segment's velocity (at a key's own time, the segment after it,
// as a law's start <= t < end).
AnchorMotion anchor_motion(const Spring& spring, double t);

// Whether a timed law acts at time t (s): start <= t < end.
inline bool acts_at(const ForceAtPoint& law, double t) {
  return law.start <= t && t < law.end;
}
inline bool acts_at(const Spring& law, double t) {
  return law.start <= t && t < law.end;
}

// Penalty contact with static planes, after Fiedler's "Spring Physics": at each corner of the box
// inside a plane by d, a normal force F_n = max(0, k d − c v_n) (a damped spring that only
// pushes) and a friction force −μ F_n v_t / sqrt(|v_t|² + v_s²), Coulomb's law regularised below
// the slip speed v_s so that the force is smooth for the integrator. Added to every body by the
// scene builder when [physics] contact = "penalty"; never listed in a scene.
struct PenaltyContact {
  std::vector<Plane> planes;
  Vec3 half_size = Vec3::Constant(0.5);  // of the box, body frame (m)
  Material material = {};                // the body's own; combined with each plane's
  double stiffness = 0.0;                // k per corner (N/m)
  double damping = 0.0;                  // c per corner (N s/m)
  double slip_speed = 0.05;              // v_s (m/s)
};

using ForceLaw = std::variant<Gravity, ConstantForce, ConstantTorque, LinearDamping, AngularDamping,
                              ForceAtPoint, Spring, PenaltyContact>;

// Net force and torque on a body.
struct Wrench {
  Vec3 force = Vec3::Zero();   // world frame, through the centre of mass (N)
  Vec3 torque = Vec3::Zero();  // world frame, about the centre of mass (N m)
};

// A force F at world point p adds F and the torque (p - x) × F.
Wrench force_at_world_point(const BodyState& state, const Vec3& force /* N, world */,
                            const Vec3& world_point /* m */);

// The penalty contact forces on the box in this state (physics/penalty_contact.cpp).
Wrench penalty_contact_wrench(const PenaltyContact& law, const BodyState& state);

// One law's contribution at time t (s) in the given state.
Wrench evaluate(const ForceLaw& law, const BodyConstants& constants, const BodyState& state,
                double t);

// Sum over a body's laws.
Wrench total_wrench(const std::vector<ForceLaw>& laws, const BodyConstants& constants,
                    const BodyState& state, double t);

}  // namespace tumble::physics
