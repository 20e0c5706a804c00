#include "view/joint_view.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::view {
namespace {

const render::Color kJointColor(0.32, 0.33, 0.36);  // sRGB: a dark steel grey

physics::JointBody body_at(const std::vector<physics::BodyState>& states, std::uint32_t i) {
  return i == physics::kWorldBody ? physics::JointBody{} : physics::JointBody::of(states[i]);
}

// The pin's radius for a joint on body `a` (m): a tenth of its smallest edge, within 5 mm and
// 5 cm, so that it shows on a chain's link and does not swallow a door.
double pin_radius(const scene::BodySpec& a) {
  return std::clamp(0.1 * a.size.minCoeff(), 0.005, 0.05);
}

// A cylinder of `radius` (m) from `from` to `to` (world, m): a render::Box of Solid::cylinder,
// whose axis is its body y.
render::Box cylinder_between(const physics::Vec3& from, const physics::Vec3& to, double radius) {
  const physics::Vec3 along = to - from;
  const double length = along.norm();
  const physics::Quat turn = length > 0.0
                                 ? physics::Quat::FromTwoVectors(physics::Vec3::UnitY(), along)
                                 : physics::Quat::Identity();
  return render::Box{.position = 0.5 * (from + to),
                     .orientation = turn,
                     .size = physics::Vec3(2.0 * radius, length, 2.0 * radius),
                     .color = kJointColor,
                     .solid = render::Solid::cylinder};
}

}  // namespace

std::vector<JointValue> joint_values(const physics::JointWorld& joints,
                                     const std::vector<physics::BodyState>& states, double t) {
  const std::vector<physics::Wrench> wrenches = physics::joint_wrenches(joints, states, t);
  std::vector<JointValue> out(joints.joints.size());
  for (std::size_t j = 0; j < out.size(); ++j) {
    const physics::Joint& joint = joints.joints[j];
    const physics::JointBody a = body_at(states, joint.a);
    const physics::JointBody b = body_at(states, joint.b);
    if (const auto at = physics::joint_coordinate(joint, a, b)) {
      out[j].coordinate = at->value;
      out[j].rate = at->rate;
    }
    out[j].force = wrenches[j].force;
    out[j].anchor = physics::anchor_a_world(joint, a);
  }
  return out;
}

std::vector<JointValue> joint_values(const physics::JointWorld& joints,
                                     const std::vector<physics::BodyState>& previous,
                                     const std::vector<physics::BodyState>& current, double alpha,
                                     double t_previous, double t_current) {
  if (alpha >= 1.0) return joint_values(joints, current, t_current);
  std::vector<JointValue> out = joint_values(joints, previous, t_previous);
  if (alpha == 0.0) return out;
  const std::vector<JointValue> after = joint_values(joints, current, t_current);
  for (std::size_t j = 0; j < out.size(); ++j) {
    const bool hinge = joints.joints[j].kind == physics::JointKind::hinge;  // angle in (-pi, pi]
    double change = after[j].coordinate - out[j].coordinate;
    if (hinge) change = std::remainder(change, 2.0 * M_PI);
    const double at = out[j].coordinate + alpha * change;
    out[j].coordinate = hinge && std::abs(at) > M_PI ? std::remainder(at, 2.0 * M_PI) : at;
    out[j].rate += alpha * (after[j].rate - out[j].rate);
    out[j].force += alpha * (after[j].force - out[j].force);
    out[j].anchor += alpha * (after[j].anchor - out[j].anchor);
  }
  return out;
}

bool draws_joints(const scene::Scene& scene) {
  return std::any_of(scene.joints.begin(), scene.joints.end(), [](const scene::JointSpec& j) {
    return j.visible && (j.kind == physics::JointKind::distance ||
                         j.kind == physics::JointKind::ball || j.kind == physics::JointKind::hinge);
  });
}

void add_joints(const scene::Scene& scene, const physics::JointWorld& joints,
                const std::vector<physics::BodyState>& states, render::FrameView& view) {
  for (std::size_t j = 0; j < scene.joints.size(); ++j) {
    const scene::JointSpec& spec = scene.joints[j];
    if (!spec.visible) continue;
    const physics::Joint& joint = joints.joints[j];
    const physics::JointBody a = body_at(states, joint.a);
    const physics::Vec3 on_a = physics::anchor_a_world(joint, a);
    const double radius = pin_radius(scene.bodies[spec.body_a]);
    switch (spec.kind) {
      case physics::JointKind::distance: {
        // A rod a quarter of a pin thick, or 0.6 % of its length if thicker, so that a long one
        // shows; a rope or a spring (which stretch) a fifth thinner.
        const physics::Vec3 on_b = physics::anchor_b_world(joint, body_at(states, joint.b));
        const double thick = std::max(0.25 * radius, 0.006 * joint.rest_length);
        const bool rod = physics::is_rigid_distance(joint);
        view.boxes.push_back(cylinder_between(on_a, on_b, (rod ? 1.0 : 0.8) * thick));
        break;
      }
      case physics::JointKind::ball:
        view.boxes.push_back(render::Box{.position = on_a,
                                         .size = physics::Vec3::Constant(3.0 * radius),
                                         .color = kJointColor,
                                         .solid = render::Solid::ball});
        break;
      case physics::JointKind::hinge: {
        const physics::Vec3 axis = a.rotation * joint.axis_a;
        view.boxes.push_back(
            cylinder_between(on_a - 3.0 * radius * axis, on_a + 3.0 * radius * axis, radius));
        break;
      }
      case physics::JointKind::slider:
      case physics::JointKind::fixed:
        break;
    }
  }
}

}  // namespace tumble::view
