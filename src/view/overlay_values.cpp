#include "view/overlay_values.hpp"

#include <algorithm>
#include <cstdio>
#include <variant>

#include "physics/forces.hpp"
#include "scene/scene_builder.hpp"
#include "scene/text_template.hpp"

namespace tumble::view {
std::string padded(std::string text, const scene::Placeholder& as) {
  if (static_cast<int>(text.size()) >= as.width) return text;
  const std::size_t missing = static_cast<std::size_t>(as.width) - text.size();
  switch (as.align) {
    case '<':
      return text.append(missing, as.fill);
    case '^':
      return std::string(missing / 2, as.fill) + text + std::string(missing - missing / 2, as.fill);
    case '=': {  // after the sign
      const std::size_t sign =
          !text.empty() && (text[0] == '+' || text[0] == '-' || text[0] == ' ');
      return text.insert(sign, missing, as.fill);
    }
    default:
      return std::string(missing, as.fill) + text;
  }
}

namespace {

using scene::BodyQuantity;

// printf's "%<sign>.<precision><conversion>", then padded to the width as Python pads.
std::string format_number(double value, const scene::Placeholder& as) {
  char pattern[6] = {'%'};
  std::size_t at = 1;
  if (as.sign != '-') pattern[at++] = as.sign;
  pattern[at++] = '.';
  pattern[at++] = '*';
  pattern[at++] = as.conversion;
  char text[64];  // "%+.17e" of any double, or "%+.17f" of one up to 10^40, fits
  const int length = std::snprintf(text, sizeof text, pattern, as.precision, value);
  std::string out;
  if (length >= 0 && static_cast<std::size_t>(length) < sizeof text) {
    out = text;
  } else {
    char wide[400];  // "%+.17f" of the largest double: 309 digits and 17 decimals
    std::snprintf(wide, sizeof wide, pattern, as.precision, value);
    out = wide;
  }
  return padded(std::move(out), as);
}

}  // namespace

physics::Vec3 body_quantity(BodyQuantity quantity, const physics::BodyState& state) {
  switch (quantity) {
    case BodyQuantity::position:
      return state.position();
    case BodyQuantity::velocity:
      return state.velocity();
    case BodyQuantity::speed:
      return physics::Vec3(state.velocity().norm(), 0.0, 0.0);
    case BodyQuantity::angular_velocity:
      return state.angular_velocity();
    case BodyQuantity::angular_speed:
      return physics::Vec3(state.angular_velocity().norm(), 0.0, 0.0);
    case BodyQuantity::angular_momentum:
      return state.angular_momentum();
    case BodyQuantity::kinetic_energy:
      return physics::Vec3(physics::kinetic_energy(state), 0.0, 0.0);
  }
  return physics::Vec3::Zero();
}

physics::Vec3 body_quantity(BodyQuantity quantity, const StepPair& steps, std::size_t body) {
  if (steps.alpha >= 1.0) return body_quantity(quantity, steps.current[body]);
  const physics::Vec3 before = body_quantity(quantity, steps.previous[body]);
  if (steps.alpha == 0.0) return before;
  return before + steps.alpha * (body_quantity(quantity, steps.current[body]) - before);
}

double placeholder_number(const scene::Placeholder& value, const StepPair& steps,
                          std::span<const JointValue> joints) {
  const int component = std::max(value.component, 0);
  if (value.source == scene::Placeholder::Source::joint) {
    const JointValue& joint = joints[value.joint];
    switch (value.joint_quantity) {
      case scene::JointQuantity::angle:
        return joint.coordinate;
      case scene::JointQuantity::speed:
        return joint.rate;
      case scene::JointQuantity::force:
        return joint.force[component];
    }
  }
  return body_quantity(value.quantity, steps, value.body)[component];
}

std::string format_value(const scene::Placeholder& value, const StepPair& steps, double t,
                         std::int64_t frame, std::span<const JointValue> joints) {
  physics::Vec3 quantity;
  bool vector = false;
  switch (value.source) {
    case scene::Placeholder::Source::time:
      return format_number(t, value);
    case scene::Placeholder::Source::frame: {
      std::string whole = std::to_string(frame);
      if (value.sign != '-' && frame >= 0) whole.insert(0, 1, value.sign);
      return padded(std::move(whole), value);
    }
    case scene::Placeholder::Source::body:
      quantity = body_quantity(value.quantity, steps, value.body);
      vector = scene::is_vector(value.quantity);
      break;
    case scene::Placeholder::Source::joint: {
      const JointValue& joint = joints[value.joint];
      switch (value.joint_quantity) {
        case scene::JointQuantity::angle:
          return format_number(joint.coordinate, value);
        case scene::JointQuantity::speed:
          return format_number(joint.rate, value);
        case scene::JointQuantity::force:
          quantity = joint.force;
          vector = true;
          break;
      }
      break;
    }
  }
  if (value.component >= 0) return format_number(quantity[value.component], value);
  if (!vector) return format_number(quantity.x(), value);
  // Appended one by one: GCC 12's -Wrestrict misreads "(" + std::string (a known bug).
  std::string out(1, '(');
  out.append(format_number(quantity.x(), value)).append(", ");
  out.append(format_number(quantity.y(), value)).append(", ");
  out.append(format_number(quantity.z(), value)).append(")");
  return out;
}

std::string format_text(const scene::TextTemplate& text, const StepPair& steps, double t,
                        std::int64_t frame, std::span<const JointValue> joints) {
  std::string out = text.pieces[0];
  for (std::size_t i = 0; i < text.values.size(); ++i) {
    out += format_value(text.values[i], steps, t, frame, joints);
    out += text.pieces[i + 1];
  }
  return out;
}

physics::Vec3 vector_value(const scene::VectorOverlay& overlay, const scene::BodySpec& body,
                           const StepPair& steps, const physics::BodyState& drawn, double t) {
  const auto interpolated = [&](auto of) {
    if (steps.alpha >= 1.0) return physics::Vec3(of(steps.current[overlay.body]));
    const physics::Vec3 before = of(steps.previous[overlay.body]);
    return steps.alpha == 0.0
               ? before
               : physics::Vec3(before + steps.alpha * (of(steps.current[overlay.body]) - before));
  };
  switch (overlay.quantity) {
    case scene::VectorQuantity::velocity:
      return interpolated([&](const physics::BodyState& state) {
        return physics::point_velocity(state, physics::body_point_to_world(state, overlay.point));
      });
    case scene::VectorQuantity::angular_velocity:
      return interpolated([](const physics::BodyState& state) { return state.angular_velocity(); });
    case scene::VectorQuantity::angular_momentum:
      return interpolated([](const physics::BodyState& state) { return state.angular_momentum(); });
    case scene::VectorQuantity::constant:
      return overlay.constant;
    case scene::VectorQuantity::joint_force:    // from the joint's values: add_vector draws it
    case scene::VectorQuantity::contact_force:  // from contact_forces: add_vector draws it
      return physics::Vec3::Zero();
    case scene::VectorQuantity::force:
    case scene::VectorQuantity::torque:
      break;
  }
  const physics::BodyConstants constants = scene::body_constants(body);
  physics::Wrench sum;
  for (const std::size_t law : overlay.laws) {
    const physics::Wrench wrench = physics::evaluate(body.forces[law], constants, drawn, t);
    sum.force += wrench.force;
    sum.torque += wrench.torque;
  }
  return overlay.quantity == scene::VectorQuantity::torque ? sum.torque : sum.force;
}

namespace {

// A body's contact points at the last step and their normal impulses (world frame).
void add_contact_points(const physics::ContactMemory& memory,
                        std::span<const physics::BodyState> states, std::size_t body,
                        physics::Vec3& weighted, double& weight, physics::Vec3& plain, int& count) {
  const auto add = [&](const physics::Vec3& point, double impulse) {
    weighted += impulse * point;
    weight += impulse;
    plain += point;
    ++count;
  };
  if (body < memory.planes.size()) {
    for (const physics::Manifold& manifold : memory.planes[body]) {
      for (int k = 0; k < manifold.count; ++k) {
        const physics::ContactPoint& p = manifold.points[static_cast<std::size_t>(k)];
        add(physics::body_point_to_world(states[body], p.body_point), p.impulses.normal);
      }
    }
  }
  for (const physics::PairContact& pair : memory.pairs) {
    const bool is_a = pair.bodies.first == body, is_b = pair.bodies.second == body;
    if (!is_a && !is_b) continue;
    for (int k = 0; k < pair.manifold.count; ++k) {
      const physics::PairPoint& p = pair.manifold.points[static_cast<std::size_t>(k)];
      add(physics::body_point_to_world(states[body], is_a ? p.point_a : p.point_b),
          p.impulses.normal);
    }
  }
}

}  // namespace

std::vector<BodyContact> contact_forces(const sim::Simulation& simulation) {
  const std::vector<physics::BodyState>& before = simulation.previous();
  const std::vector<physics::BodyState>& after = simulation.current();
  const std::vector<physics::BodyModel>& models = simulation.models();
  std::vector<BodyContact> out(after.size());
  const std::int64_t n = simulation.step_count();
  if (n == 0) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i].point = after[i].position();
    return out;
  }
  const double dt = simulation.dt();
  const double t0 = simulation.time_of_step(n - 1), t1 = simulation.time_of_step(n);  // s
  // The joints' forces over the step, as the trapezoid too.
  std::vector<physics::Vec3> joint_impulse(after.size(), physics::Vec3::Zero());
  const physics::JointWorld& joints = simulation.joints();
  if (!joints.joints.empty()) {
    const std::vector<physics::Wrench> at_start = physics::joint_wrenches(joints, before, t0);
    const std::vector<physics::Wrench> at_end = physics::joint_wrenches(joints, after, t1);
    for (std::size_t j = 0; j < joints.joints.size(); ++j) {
      const physics::Vec3 impulse = 0.5 * dt * (at_start[j].force + at_end[j].force);
      joint_impulse[joints.joints[j].a] += impulse;
      if (joints.joints[j].b != physics::kWorldBody) joint_impulse[joints.joints[j].b] -= impulse;
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    physics::Vec3 weighted = physics::Vec3::Zero(), plain = physics::Vec3::Zero();
    double weight = 0.0;
    int count = 0;
    add_contact_points(simulation.contact_memory(), after, i, weighted, weight, plain, count);
    out[i].point = weight > 0.0 ? physics::Vec3(weighted / weight)
                   : count > 0  ? physics::Vec3(plain / count)
                                : after[i].position();
    const bool penalty = std::any_of(
        models[i].forces.begin(), models[i].forces.end(),
        [](const auto& law) { return std::holds_alternative<physics::PenaltyContact>(law); });
    // Touching nothing at the step (impulse contact): no contact force, whatever rounding the
    // momentum balance below would leave.
    if (models[i].is_static || (count == 0 && !penalty)) continue;
    physics::Vec3 impulse = after[i].momentum() - before[i].momentum() - joint_impulse[i];
    for (const physics::ForceLaw& law : models[i].forces) {
      if (std::holds_alternative<physics::PenaltyContact>(law)) continue;  // the contact itself
      impulse -= 0.5 * dt *
                 (physics::evaluate(law, models[i].constants, before[i], t0).force +
                  physics::evaluate(law, models[i].constants, after[i], t1).force);
    }
    out[i].force = impulse / dt;
  }
  return out;
}

}  // namespace tumble::view
