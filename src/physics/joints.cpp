#include "physics/joints.hpp"

#include <cmath>

namespace tumble::physics {
namespace {

// ω × (ω × r): the acceleration of a point at r from the centre of a body turning at ω with no
// angular acceleration (m/s²).
Vec3 centripetal(const Vec3& omega, const Vec3& r) {
  return omega.cross(omega.cross(r));
}

// The two anchors, their arms from the centres (world), and their relative velocity.
struct Anchors {
  Vec3 arm_a, arm_b;  // R r (m)
  Vec3 apart;         // p_a - p_b (m)
  Vec3 closing;       // ṗ_a - ṗ_b (m/s)
};

Anchors anchors(const Joint& joint, const JointBody& a, const JointBody& b) {
  Anchors out;
  out.arm_a = a.rotation * joint.anchor_a;
  out.arm_b = b.rotation * joint.anchor_b;
  out.apart = a.position + out.arm_a - b.position - out.arm_b;
  out.closing = a.velocity + a.angular_velocity.cross(out.arm_a) - b.velocity -
                b.angular_velocity.cross(out.arm_b);
  return out;
}

// A row along the world direction `d` between the anchors: ḋ·d, the direction's own turn with
// b (when `turns_with_b`) counted in b's angular part.
JointRow linear_row(const Joint& joint, const Anchors& at, const Vec3& d, bool turns_with_b) {
  JointRow row{.a = joint.a, .b = joint.b};
  row.linear_a = d;
  row.angular_a = at.arm_a.cross(d);
  row.linear_b = -d;
  row.angular_b = -(turns_with_b ? at.apart + at.arm_b : at.arm_b).cross(d);
  return row;
}

JointRow angular_row(const Joint& joint, const Vec3& axis) {
  JointRow row{.a = joint.a, .b = joint.b};
  row.angular_a = axis;
  row.angular_b = -axis;
  return row;
}

// The relative point's acceleration when neither body accelerates (m/s²).
Vec3 anchor_curvature(const Anchors& at, const JointBody& a, const JointBody& b) {
  return centripetal(a.angular_velocity, at.arm_a) - centripetal(b.angular_velocity, at.arm_b);
}

void point_rows(const Joint& joint, const Anchors& at, const JointBody& a, const JointBody& b,
                std::vector<JointRow>& out) {
  const Vec3 curvature = anchor_curvature(at, a, b);
  for (int i = 0; i < 3; ++i) {
    JointRow row = linear_row(joint, at, Vec3::Unit(i), false);
    row.error = at.apart[i];
    row.curvature = curvature[i];
    out.push_back(row);
  }
}

// a's orientation must stay b's times the rest: three rows, the error the rotation vector (rad,
// world) that takes q_b rest to q_a.
void lock_rows(const Joint& joint, const JointBody& a, const JointBody& b,
               std::vector<JointRow>& out) {
  Quat off = a.orientation * (b.orientation * joint.rest).conjugate();
  if (off.w() < 0.0) off.coeffs() = -off.coeffs();
  const double s = off.vec().norm();
  const Vec3 error = s > 0.0 ? Vec3(2.0 * std::atan2(s, off.w()) / s * off.vec()) : Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    JointRow row = angular_row(joint, Vec3::Unit(i));
    row.error = error[i];
    out.push_back(row);
  }
}

// a's axis stays normal to b's two normals: C = a·p, a·q; Ċ = (ω_a - ω_b)·(a × p).
void hinge_rows(const Joint& joint, const JointBody& a, const JointBody& b,
                std::vector<JointRow>& out) {
  const Vec3 axis = a.rotation * joint.axis_a;
  const Vec3 relative = a.angular_velocity - b.angular_velocity;
  for (const Vec3& normal_b : joint.normal_b) {
    const Vec3 p = b.rotation * normal_b;
    const Vec3 u = axis.cross(p);
    JointRow row = angular_row(joint, u);
    row.error = axis.dot(p);
    const Vec3 u_rate =
        a.angular_velocity.cross(axis).cross(p) + axis.cross(b.angular_velocity.cross(p));
    row.curvature = relative.dot(u_rate);
    out.push_back(row);
  }
}

// a's anchor stays on b's line through b's anchor along the axis: C = t·(p_a - p_b) for b's two
// normals t.
void line_rows(const Joint& joint, const Anchors& at, const JointBody& a, const JointBody& b,
               std::vector<JointRow>& out) {
  const Vec3 curvature = anchor_curvature(at, a, b);
  for (const Vec3& normal_b : joint.normal_b) {
    const Vec3 t = b.rotation * normal_b;
    const Vec3 t_rate = b.angular_velocity.cross(t);
    JointRow row = linear_row(joint, at, t, true);
    row.error = t.dot(at.apart);
    row.curvature = centripetal(b.angular_velocity, t).dot(at.apart) +
                    2.0 * t_rate.dot(at.closing) + t.dot(curvature);
    out.push_back(row);
  }
}

}  // namespace

JointBody JointBody::of(const BodyState& state) {
  return {.position = state.position(),
          .rotation = state.rotation(),
          .orientation = state.orientation(),
          .velocity = state.velocity(),
          .angular_velocity = state.angular_velocity()};
}

double joint_opening(const Joint& joint, std::span<const BodyState> states) {
  const JointBody b = joint.b == kWorldBody ? JointBody{} : JointBody::of(states[joint.b]);
  return (anchor_a_world(joint, JointBody::of(states[joint.a])) - anchor_b_world(joint, b)).norm();
}

Joint place_joint(JointKind kind, std::uint32_t a, std::uint32_t b,
                  std::span<const BodyState> states, const Vec3& anchor_a, const Vec3& anchor_b,
                  const Vec3& axis) {
  Joint joint;
  joint.kind = kind;
  joint.a = a;
  joint.b = b;
  const JointBody body_a = JointBody::of(states[a]);
  const JointBody body_b = b == kWorldBody ? JointBody{} : JointBody::of(states[b]);
  joint.anchor_a = body_a.rotation.transpose() * (anchor_a - body_a.position);
  joint.anchor_b = body_b.rotation.transpose() * (anchor_b - body_b.position);
  const Vec3 unit = axis.normalized();
  joint.axis_a = body_a.rotation.transpose() * unit;
  joint.axis_b = body_b.rotation.transpose() * unit;
  // b's normals: from the world axis least along the axis, so that a joint is placed the same
  // way every time.
  Eigen::Index least = 0;
  joint.axis_b.cwiseAbs().minCoeff(&least);
  joint.normal_b[0] = joint.axis_b.cross(Vec3::Unit(least)).normalized();
  joint.normal_b[1] = joint.axis_b.cross(joint.normal_b[0]);
  joint.rest = body_b.orientation.conjugate() * body_a.orientation;
  const double length = (anchor_a - anchor_b).norm();
  joint.min_length = joint.max_length = joint.rest_length = length;
  return joint;
}

Vec3 anchor_a_world(const Joint& joint, const JointBody& a) {
  return a.position + a.rotation * joint.anchor_a;
}
Vec3 anchor_b_world(const Joint& joint, const JointBody& b) {
  return b.position + b.rotation * joint.anchor_b;
}

void equality_rows(const Joint& joint, const JointBody& a, const JointBody& b,
                   std::vector<JointRow>& out) {
  switch (joint.kind) {
    case JointKind::ball:
      point_rows(joint, anchors(joint, a, b), a, b, out);
      return;
    case JointKind::hinge:
      point_rows(joint, anchors(joint, a, b), a, b, out);
      hinge_rows(joint, a, b, out);
      return;
    case JointKind::slider:
      line_rows(joint, anchors(joint, a, b), a, b, out);
      lock_rows(joint, a, b, out);
      return;
    case JointKind::fixed:
      point_rows(joint, anchors(joint, a, b), a, b, out);
      lock_rows(joint, a, b, out);
      return;
    case JointKind::distance: {
      if (!is_rigid_distance(joint)) return;
      const Anchors at = anchors(joint, a, b);
      const double length = at.apart.norm();
      if (!(length > 0.0)) return;  // a rod of length 0 has no direction; the loader refuses it
      const Vec3 u = at.apart / length;
      JointRow row = linear_row(joint, at, u, false);
      row.error = length - joint.max_length;
      const double along = u.dot(at.closing);
      row.curvature =
          u.dot(anchor_curvature(at, a, b)) + (at.closing.squaredNorm() - along * along) / length;
      out.push_back(row);
      return;
    }
  }
}

JointRow coordinate_row(const Joint& joint, const JointBody& a, const JointBody& b) {
  switch (joint.kind) {
    case JointKind::hinge:
      return angular_row(joint, b.rotation * joint.axis_b);
    case JointKind::slider: {
      const Anchors at = anchors(joint, a, b);
      return linear_row(joint, at, b.rotation * joint.axis_b, true);
    }
    case JointKind::distance: {
      const Anchors at = anchors(joint, a, b);
      const double length = at.apart.norm();
      return linear_row(joint, at, length > 0.0 ? Vec3(at.apart / length) : Vec3::UnitY(), false);
    }
    case JointKind::ball:
    case JointKind::fixed:
      break;
  }
  return JointRow{.a = joint.a, .b = joint.b};
}

std::optional<JointCoordinate> joint_coordinate(const Joint& joint, const JointBody& a,
                                                const JointBody& b) {
  const auto rate = [&](const JointRow& row) {
    return row.linear_a.dot(a.velocity) + row.angular_a.dot(a.angular_velocity) +
           row.linear_b.dot(b.velocity) + row.angular_b.dot(b.angular_velocity);
  };
  switch (joint.kind) {
    case JointKind::hinge: {
      Quat turn = b.orientation.conjugate() * a.orientation * joint.rest.conjugate();
      if (turn.w() < 0.0) turn.coeffs() = -turn.coeffs();
      const double angle = 2.0 * std::atan2(turn.vec().dot(joint.axis_b), turn.w());
      return JointCoordinate{.value = angle, .rate = rate(coordinate_row(joint, a, b))};
    }
    case JointKind::slider: {
      const Anchors at = anchors(joint, a, b);
      return JointCoordinate{.value = (b.rotation * joint.axis_b).dot(at.apart),
                             .rate = rate(coordinate_row(joint, a, b))};
    }
    case JointKind::distance: {
      const Anchors at = anchors(joint, a, b);
      return JointCoordinate{.value = at.apart.norm(), .rate = rate(coordinate_row(joint, a, b))};
    }
    case JointKind::ball:
    case JointKind::fixed:
      break;
  }
  return std::nullopt;
}

const char* joint_kind_name(JointKind kind) {
  switch (kind) {
    case JointKind::ball:
      return "ball";
    case JointKind::hinge:
      return "hinge";
    case JointKind::slider:
      return "slider";
    case JointKind::fixed:
      return "fixed";
    case JointKind::distance:
      return "distance";
  }
  return "?";
}

}  // namespace tumble::physics
