#include "scene/joint_tables.hpp"

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "scene/limits.hpp"
#include "sim/simulation.hpp"

namespace tumble::scene::detail {
namespace {

using physics::JointKind;

std::optional<JointKind> kind_from_name(const std::string& name) {
  for (const JointKind kind : {JointKind::ball, JointKind::hinge, JointKind::slider,
                               JointKind::fixed, JointKind::distance}) {
    if (name == physics::joint_kind_name(kind)) return kind;
  }
  return std::nullopt;
}

// The index of the body named by `key`, or kWorldBody for "world" where the world may stand.
std::uint32_t body_named(TableReader& in, const Scene& scene, const char* key,
                         const std::string& name, bool world_allowed) {
  if (name == "world") {
    if (!world_allowed) {
      in.fail(key, "body_a must be a body (\"world\" may only be body_b)");
    }
    return physics::kWorldBody;
  }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].name == name) return static_cast<std::uint32_t>(i);
  }
  std::string known;
  for (const BodySpec& body : scene.bodies) known += (known.empty() ? "" : ", ") + body.name;
  if (known.size() > 200) known = known.substr(0, 200) + "...";
  in.fail(key, "no body is named " + in_quotes(name) + " (bodies: " + known +
                   (world_allowed ? "; or \"world\")" : ")"));
}

// Refuses a key the joint's kind does not take.
void refuse_keys(TableReader& in, const std::string& kind,
                 std::initializer_list<const char*> keys) {
  for (const char* key : keys) {
    if (in.has(key)) in.fail(key, "a " + kind + " joint takes no " + key);
  }
}

void read_limits_and_motor(TableReader& in, JointSpec& joint) {
  const bool hinge = joint.kind == JointKind::hinge;
  const char* unit = hinge ? "rad" : "m";
  if (in.has("lower") || in.has("upper")) {
    constexpr double kNone = std::numeric_limits<double>::infinity();
    physics::JointLimits limits{.lower = in.optional_number("lower", -kNone),
                                .upper = in.optional_number("upper", kNone)};
    if (limits.lower > limits.upper) {
      in.fail("lower", "lower (" + format_number(limits.lower) + " " + unit + ") is above upper (" +
                           format_number(limits.upper) + " " + unit + ")");
    }
    // A hinge's angle is measured in (-π, π]: a limit outside it would never be reached.
    if (hinge) {
      for (const char* key : {"lower", "upper"}) {
        const double value = std::string(key) == "lower" ? limits.lower : limits.upper;
        if (in.has(key) && !(std::abs(value) <= std::numbers::pi)) {
          in.fail(key, "a hinge's angle runs from -π to π rad (got " + format_number(value) + ")");
        }
      }
    }
    if (!hinge) {
      if (in.has("lower"))
        vector_within(in, "lower", Vec3(limits.lower, 0, 0), sim::kMaxPosition, "m");
      if (in.has("upper"))
        vector_within(in, "upper", Vec3(limits.upper, 0, 0), sim::kMaxPosition, "m");
    }
    joint.limits = limits;
  }
  const char* effort = hinge ? "max_motor_torque" : "max_motor_force";
  const char* other = hinge ? "max_motor_force" : "max_motor_torque";
  if (in.has(other)) {
    in.fail(other, std::string("a ") + (hinge ? "hinge" : "slider") + "'s motor takes " + effort);
  }
  const bool speed = in.has("motor_speed"), most = in.has(effort);
  if (speed != most) {
    in.fail(speed ? "motor_speed" : effort,
            speed
                ? std::string("a motor needs its maximum: ") + effort + (hinge ? " (N m)" : " (N)")
                : std::string(effort) + " needs motor_speed (" + (hinge ? "rad/s" : "m/s") + ")");
  }
  if (speed) {
    physics::JointMotor motor{.speed = in.optional_number("motor_speed", 0.0),
                              .max_effort = in.optional_number(effort, 0.0)};
    require_positive(in, effort, motor.max_effort);
    if (hinge && !(std::abs(motor.speed) <= sim::kMaxAngularSpeed)) {
      in.fail("motor_speed",
              "past the " + format_number(sim::kMaxAngularSpeed) + " rad/s tumble can simulate");
    }
    if (!hinge && !(std::abs(motor.speed) <= sim::kMaxSpeed)) {
      in.fail("motor_speed",
              "past the " + format_number(sim::kMaxSpeed) + " m/s tumble can simulate");
    }
    joint.motor = motor;
  }
}

void read_distance(TableReader& in, JointSpec& joint) {
  joint.anchor_a =
      vector_within(in, "anchor_a", in.required_vector("anchor_a"), sim::kMaxPosition, "m");
  joint.anchor_b =
      vector_within(in, "anchor_b", in.required_vector("anchor_b"), sim::kMaxPosition, "m");
  const double start = (joint.anchor_a - joint.anchor_b).norm();
  joint.stiffness = in.optional_number("stiffness", 0.0);
  joint.damping = in.optional_number("damping", 0.0);
  require_non_negative(in, "stiffness", joint.stiffness);
  require_non_negative(in, "damping", joint.damping);
  if (joint.damping > 0.0 && joint.stiffness == 0.0) {
    in.fail("damping", "damping goes with a spring: give stiffness too");
  }
  const bool spring = joint.stiffness > 0.0;
  const bool has_min = in.has("min_length"), has_max = in.has("max_length");
  // A rod of the anchors' distance unless written; a rope is max_length alone (slack below it);
  // a spring has no stops unless written.
  joint.max_length =
      in.optional_number("max_length", spring ? std::numeric_limits<double>::infinity() : start);
  joint.min_length = in.optional_number("min_length", spring || has_max ? 0.0 : start);
  if (has_min) require_non_negative(in, "min_length", joint.min_length);
  if (has_max) require_positive(in, "max_length", joint.max_length);
  if (has_max && joint.max_length > sim::kMaxPosition) {
    in.fail("max_length",
            "past the " + format_number(sim::kMaxPosition) + " m tumble can simulate");
  }
  if (joint.min_length > joint.max_length) {
    in.fail(has_min ? "min_length" : "max_length",
            "min_length (" + format_number(joint.min_length) + " m) is above max_length (" +
                format_number(joint.max_length) + " m)");
  }
  if (!spring && joint.min_length == joint.max_length && !(joint.max_length > 0.0)) {
    in.fail("anchor_b",
            "the anchors are at one point: a rod of length 0 has no direction "
            "(use a ball joint)");
  }
  if (start < joint.min_length - 1e-9 || start > joint.max_length + 1e-9) {
    in.fail(start < joint.min_length ? "min_length" : "max_length",
            "the anchors start " + format_number(start) + " m apart, outside [" +
                format_number(joint.min_length) + ", " + format_number(joint.max_length) + "] m");
  }
}

JointSpec read_joint(TableReader& in, std::size_t index, const Scene& scene) {
  JointSpec joint;
  joint.name = in.optional_string("name", "joint" + std::to_string(index));
  if (!is_safe_name(joint.name)) in.fail("name", kSafeNameRule);
  const std::string kind = in.required_string("kind");
  const std::optional<JointKind> known = kind_from_name(kind);
  if (!known) {
    in.fail("kind", "unknown joint kind " + in_quotes(kind) +
                        " (expected ball, hinge, slider, fixed or distance)");
  }
  joint.kind = *known;
  joint.body_a = body_named(in, scene, "body_a", in.required_string("body_a"), false);
  joint.body_b = body_named(in, scene, "body_b", in.optional_string("body_b", "world"), true);
  if (joint.body_a == joint.body_b) {
    in.fail("body_b", "a joint holds two bodies: body_a and body_b are both " +
                          in_quotes(scene.bodies[joint.body_a].name));
  }
  const auto is_static = [&](std::uint32_t i) {
    return i == physics::kWorldBody || scene.bodies[i].is_static;
  };
  if (is_static(joint.body_a) && is_static(joint.body_b)) {
    in.fail(in.has("body_b") ? "body_b" : "body_a",
            "both ends are static (a static body or the world): the joint would hold nothing");
  }
  if (joint.kind == JointKind::distance) {
    refuse_keys(
        in, kind,
        {"anchor", "axis", "lower", "upper", "motor_speed", "max_motor_torque", "max_motor_force"});
    read_distance(in, joint);
  } else {
    refuse_keys(in, kind,
                {"anchor_a", "anchor_b", "min_length", "max_length", "stiffness", "damping"});
    joint.anchor_a = joint.anchor_b =
        vector_within(in, "anchor", in.required_vector("anchor"), sim::kMaxPosition, "m");
    if (joint.kind == JointKind::hinge || joint.kind == JointKind::slider) {
      const Vec3 axis = in.required_vector("axis");
      const double largest = axis.cwiseAbs().maxCoeff();
      if (!(largest > 0.0)) in.fail("axis", "must not be the zero vector");
      joint.axis = (axis / largest).normalized();
      read_limits_and_motor(in, joint);
    } else {
      refuse_keys(in, kind,
                  {"axis", "lower", "upper", "motor_speed", "max_motor_torque", "max_motor_force"});
    }
  }
  joint.collide_connected = in.optional_bool("collide_connected", joint.collide_connected);
  joint.visible = in.optional_bool("visible", joint.visible);
  in.reject_unknown_keys();
  return joint;
}

// The root of `i` in the union-find `root`.
std::size_t root_of(std::vector<std::size_t>& root, std::size_t i) {
  while (root[i] != i) i = root[i] = root[root[i]];
  return i;
}

}  // namespace

void read_joints(TableReader& root, Scene& scene) {
  if (!root.has("joints")) return;
  const toml::array* joints = root.table().get("joints")->as_array();
  if (!joints) root.fail("joints", "expected [[joints]] tables");
  std::set<std::string> names;
  for (const BodySpec& body : scene.bodies) names.insert(body.name);
  // Welds, by union-find over the bodies and the world (the last node): one that joins two
  // bodies already welded together closes a loop, whose rows say one thing twice.
  std::vector<std::size_t> welded(scene.bodies.size() + 1);
  for (std::size_t i = 0; i < welded.size(); ++i) welded[i] = i;
  const auto node = [&](std::uint32_t body) {
    return body == physics::kWorldBody ? scene.bodies.size() : body;
  };
  root.each_table(*joints, "joints", static_cast<std::size_t>(kMaxJoints), "a [[joints]] table",
                  [&](TableReader& in, std::size_t i) {
                    scene.joints.push_back(read_joint(in, i, scene));
                    const JointSpec& joint = scene.joints.back();
                    if (!names.insert(joint.name).second) {
                      in.fail("name", "the name " + in_quotes(joint.name) +
                                          " is taken (by a body or a joint): texts name joints "
                                          "and bodies alike, as {NAME.x}");
                    }
                    if (joint.kind != JointKind::fixed) return;
                    const std::size_t a = root_of(welded, node(joint.body_a));
                    const std::size_t b = root_of(welded, node(joint.body_b));
                    if (a == b) {
                      in.fail(in.has("body_b") ? "body_b" : "body_a",
                              "this weld closes a loop of fixed joints (" + in_quotes(joint.name) +
                                  "'s bodies are already welded together): it over-constrains "
                                  "them; leave it out");
                    }
                    welded[a] = b;
                  });
}

bool kept_from_colliding(const Scene& scene, std::size_t a, std::size_t b) {
  for (const JointSpec& joint : scene.joints) {
    if (joint.collide_connected) continue;
    if ((joint.body_a == a && joint.body_b == b) || (joint.body_a == b && joint.body_b == a)) {
      return true;
    }
  }
  return false;
}

}  // namespace tumble::scene::detail
