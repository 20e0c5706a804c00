#include "physics/forces.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::physics {
namespace {

struct LawEvaluator {
  const BodyConstants& constants;
  const BodyState& state;
  double t;

  Wrench operator()(const Gravity& law) const {
    return {.force = constants.mass * law.acceleration, .torque = Vec3::Zero()};
  }
  Wrench operator()(const ConstantForce& law) const {
    return {.force = law.force, .torque = Vec3::Zero()};
  }
  Wrench operator()(const ConstantTorque& law) const {
    return {.force = Vec3::Zero(), .torque = law.torque};
  }
  Wrench operator()(const LinearDamping& law) const {
    return {.force = -law.coefficient * state.velocity(), .torque = Vec3::Zero()};
  }
  Wrench operator()(const AngularDamping& law) const {
    return {.force = Vec3::Zero(), .torque = -law.coefficient * state.angular_velocity()};
  }
  Wrench operator()(const ForceAtPoint& law) const {
    if (!acts_at(law, t)) return {};
    return force_at_world_point(state, law.force, body_point_to_world(state, law.point));
  }
  Wrench operator()(const Spring& law) const {
    if (!acts_at(law, t)) return {};
    const AnchorMotion anchor = anchor_motion(law, t);
    const Vec3 attachment = body_point_to_world(state, law.attachment);
    const Vec3 offset = attachment - anchor.position;
    const double length = offset.norm();
    // At zero length the direction is undefined; a zero-rest-length spring has zero force
    // there anyway, and any other spring passes through it in an instant.
    if (length == 0.0) return {};
    const Vec3 direction = offset / length;
    // A fixed anchor's velocity is exactly zero, and v - 0 is v to the bit.
    const double stretch_speed =
        (point_velocity(state, attachment) - anchor.velocity).dot(direction);
    const double magnitude =
        law.stiffness * (length - law.rest_length) + law.damping * stretch_speed;
    return force_at_world_point(state, -magnitude * direction, attachment);
  }
  Wrench operator()(const PenaltyContact& law) const { return penalty_contact_wrench(law, state); }
};

}  // namespace

AnchorMotion anchor_motion(const Spring& spring, double t) {
  const std::vector<AnchorKey>& keys = spring.anchor_keys;
  if (keys.empty()) return {.position = spring.anchor};
  if (t < keys.front().time) return {.position = keys.front().anchor};
  if (t >= keys.back().time) return {.position = keys.back().anchor};
  // The first key after t, and the last at or before it: keys[0].time <= t < keys.back().time.
  const auto next =
      std::upper_bound(keys.begin(), keys.end(), t,
                       [](double time, const AnchorKey& key) { return time < key.time; });
  const AnchorKey& from = *(next - 1);
  const AnchorKey& to = *next;
  double span = to.time - from.time;  // s; > 0, since distinct doubles never differ by 0
  double elapsed = t - from.time;     // s, in [0, span]
  const Vec3 velocity = (to.anchor - from.anchor) / span;  // m/s; 0 across an infinite span
  if (std::isinf(span)) {
    // Keys more than the double range apart: halving is exact for numbers that large.
    span = 0.5 * to.time - 0.5 * from.time;
    elapsed = 0.5 * t - 0.5 * from.time;
  }
  return {.position = from.anchor + (elapsed / span) * (to.anchor - from.anchor),
          .velocity = velocity};
}

Wrench force_at_world_point(const BodyState& state, const Vec3& force, const Vec3& world_point) {
  return {.force = force, .torque = (world_point - state.position()).cross(force)};
}

Wrench evaluate(const ForceLaw& law, const BodyConstants& constants, const BodyState& state,
                double t) {
  return std::visit(LawEvaluator{constants, state, t}, law);
}

Wrench total_wrench(const std::vector<ForceLaw>& laws, const BodyConstants& constants,
                    const BodyState& state, double t) {
  Wrench total;
  const LawEvaluator evaluator{constants, state, t};
  for (const ForceLaw& law : laws) {
    const Wrench w = std::visit(evaluator, law);
    total.force += w.force;
    total.torque += w.torque;
  }
  return total;
}

}  // namespace tumble::physics
