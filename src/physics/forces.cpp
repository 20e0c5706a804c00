#include "physics/forces.hpp"

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
    if (t < law.start || t >= law.end) return {};
    return force_at_world_point(state, law.force, body_point_to_world(state, law.point));
  }
  Wrench operator()(const Spring& law) const {
    const Vec3 attachment = body_point_to_world(state, law.attachment);
    const Vec3 offset = attachment - law.anchor;
    const double length = offset.norm();
    // At zero length the direction is undefined; a zero-rest-length spring has zero force
    // there anyway, and any other spring passes through it in an instant.
    if (length == 0.0) return {};
    const Vec3 direction = offset / length;
    const double stretch_speed = point_velocity(state, attachment).dot(direction);
    const double magnitude =
        law.stiffness * (length - law.rest_length) + law.damping * stretch_speed;
    return force_at_world_point(state, -magnitude * direction, attachment);
  }
  Wrench operator()(const PenaltyContact& law) const { return penalty_contact_wrench(law, state); }
};

}  // namespace

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
