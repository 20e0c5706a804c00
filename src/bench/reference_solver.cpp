#include "bench/reference_solver.hpp"

#include "physics/contact.hpp"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <variant>
#include <vector>

namespace tumble::bench {
namespace {

using Real = long double;  // 64-bit mantissa on x86-64: about 3 more digits than double
using RealVec3 = Eigen::Matrix<Real, 3, 1>;
using RealQuat = Eigen::Quaternion<Real>;
using RealMat3 = Eigen::Matrix<Real, 3, 3>;

// x (3), p (3), q as w, x, y, z (4), L (3). A vector rather than a std::array: odeint copies its
// steppers' uninitialised std::array scratch space, which GCC rightly warns about.
using OdeState = std::vector<Real>;

RealVec3 real(const physics::Vec3& v) {
  return v.cast<Real>();
}

// The body at one instant, in long double: what every force law needs.
struct Kinematics {
  RealVec3 position;          // m, world
  RealVec3 velocity;          // m/s, world
  RealMat3 rotation;          // body to world
  RealVec3 angular_velocity;  // rad/s, world
};

struct RealWrench {
  RealVec3 force = RealVec3::Zero();   // N, world
  RealVec3 torque = RealVec3::Zero();  // N m about the centre, world
};

struct RealAnchorMotion {
  RealVec3 position;  // m, world
  RealVec3 velocity;  // m/s, world
};

// physics::anchor_motion again in long double, whose range holds any span between two keys. The
// segment is the one `piece` lies in, and its straight line is followed to t, so that a piece
// that ends on a key sees the segment before the key up to its end.
RealAnchorMotion anchor_motion(const physics::Spring& law, Real t, Real piece) {
  const std::vector<physics::AnchorKey>& keys = law.anchor_keys;
  if (keys.empty()) return {real(law.anchor), RealVec3::Zero()};
  if (piece < Real(keys.front().time)) return {real(keys.front().anchor), RealVec3::Zero()};
  if (piece >= Real(keys.back().time)) return {real(keys.back().anchor), RealVec3::Zero()};
  const auto next = std::upper_bound(
      keys.begin(), keys.end(), piece,
      [](Real time, const physics::AnchorKey& key) { return time < Real(key.time); });
  const physics::AnchorKey& from = *(next - 1);
  const physics::AnchorKey& to = *next;
  const Real span = Real(to.time) - Real(from.time);
  const RealVec3 change = real(to.anchor) - real(from.anchor);
  return {real(from.anchor) + ((t - Real(from.time)) / span) * change, change / span};
}

// The force laws of physics/forces.hpp, evaluated again in long double. What switches at a time
// (a law's start and end, the segment of a moving anchor) is decided at `piece`, a time strictly
// inside the piece of the run being integrated, so that each piece is one smooth ODE.
struct RealLawEvaluator {
  Real mass;
  const Kinematics& body;
  Real t;
  Real piece;
  RealWrench& out;

  void add_at_point(const RealVec3& force, const RealVec3& arm /* world, from the centre */) const {
    out.force += force;
    out.torque += arm.cross(force);
  }
  void operator()(const physics::Gravity& law) const { out.force += mass * real(law.acceleration); }
  void operator()(const physics::ConstantForce& law) const { out.force += real(law.force); }
  void operator()(const physics::ConstantTorque& law) const { out.torque += real(law.torque); }
  void operator()(const physics::LinearDamping& law) const {
    out.force -= Real(law.coefficient) * body.velocity;
  }
  void operator()(const physics::AngularDamping& law) const {
    out.torque -= Real(law.coefficient) * body.angular_velocity;
  }
  void operator()(const physics::ForceAtPoint& law) const {
    if (piece < Real(law.start) || piece >= Real(law.end)) return;
    add_at_point(real(law.force), body.rotation * real(law.point));
  }
  void operator()(const physics::Spring& law) const {
    if (piece < Real(law.start) || piece >= Real(law.end)) return;
    const RealAnchorMotion anchor = anchor_motion(law, t, piece);
    const RealVec3 arm = body.rotation * real(law.attachment);
    const RealVec3 offset = body.position + arm - anchor.position;
    const Real length = offset.norm();
    if (length == 0) return;
    const RealVec3 direction = offset / length;
    // The attachment's velocity relative to the anchor, as in physics/forces.hpp.
    const RealVec3 relative_velocity =
        body.velocity + body.angular_velocity.cross(arm) - anchor.velocity;
    const Real magnitude = Real(law.stiffness) * (length - Real(law.rest_length)) +
                           Real(law.damping) * relative_velocity.dot(direction);
    add_at_point(-magnitude * direction, arm);
  }
  void operator()(const physics::PenaltyContact& law) const {
    for (const physics::Plane& plane : law.planes) {
      const RealVec3 normal = real(plane.normal);
      const Real friction = Real(physics::combine(law.material, plane.material).friction);
      const Real slip_speed = Real(law.slip_speed);
      for (int feature = 0; feature < 8; ++feature) {
        const RealVec3 arm = body.rotation * real(physics::corner(law.half_size, feature));
        const Real depth = Real(plane.offset) - normal.dot(body.position + arm);
        if (depth <= 0) continue;
        const RealVec3 velocity = body.velocity + body.angular_velocity.cross(arm);
        const Real normal_speed = normal.dot(velocity);
        const Real normal_force =
            std::max(Real(0), Real(law.stiffness) * depth - Real(law.damping) * normal_speed);
        const RealVec3 slip = velocity - normal_speed * normal;
        add_at_point(
            normal_force * normal - (friction * normal_force /
                                     std::sqrt(slip.squaredNorm() + slip_speed * slip_speed)) *
                                        slip,
            arm);
      }
    }
  }
};

struct RigidBodyOde {
  const physics::BodyModel& model;
  Real piece;  // s, strictly inside the piece being integrated

  Kinematics kinematics(const OdeState& y) const {
    const RealQuat unit = RealQuat(y[6], y[7], y[8], y[9]).normalized();
    const RealMat3 rotation = unit.toRotationMatrix();
    const RealVec3 momentum(y[3], y[4], y[5]);
    const RealVec3 angular_momentum(y[10], y[11], y[12]);
    const RealVec3 inverse_inertia = real(model.constants.inertia).cwiseInverse();
    return {.position = RealVec3(y[0], y[1], y[2]),
            .velocity = momentum / Real(model.constants.mass),
            .rotation = rotation,
            .angular_velocity =
                rotation * inverse_inertia.cwiseProduct(rotation.transpose() * angular_momentum)};
  }

  void operator()(const OdeState& y, OdeState& rate, Real t) const {
    const Kinematics body = kinematics(y);
    RealWrench wrench;
    const RealLawEvaluator evaluator{Real(model.constants.mass), body, t, piece, wrench};
    for (const physics::ForceLaw& law : model.forces) std::visit(evaluator, law);
    // dq/dt = ½ (0, ω) q: tangent to the unit sphere, so |q| is a constant of this ODE.
    const RealQuat q(y[6], y[7], y[8], y[9]);
    const RealVec3& w = body.angular_velocity;
    const RealQuat spin = RealQuat(0, w.x(), w.y(), w.z()) * q;
    rate = {body.velocity.x(), body.velocity.y(), body.velocity.z(), wrench.force.x(),
            wrench.force.y(),  wrench.force.z(),  spin.w() / 2,      spin.x() / 2,
            spin.y() / 2,      spin.z() / 2,      wrench.torque.x(), wrench.torque.y(),
            wrench.torque.z()};
  }
};

// The times in (0, duration) at which a law switches on or off or a moving anchor turns: the
// ODE is smooth between them, and an adaptive step across one would trust an error estimate
// that the jump makes meaningless (RKF 7(8)'s can miss it entirely). 0 and duration included.
std::vector<Real> piece_ends(const physics::BodyModel& model, Real duration) {
  std::vector<Real> ends = {0, duration};
  const auto add = [&](double time) {
    if (Real(time) > 0 && Real(time) < duration) ends.push_back(Real(time));
  };
  for (const physics::ForceLaw& law : model.forces) {
    if (const auto* push = std::get_if<physics::ForceAtPoint>(&law)) {
      add(push->start);
      add(push->end);
    } else if (const auto* spring = std::get_if<physics::Spring>(&law)) {
      add(spring->start);
      add(spring->end);
      for (const physics::AnchorKey& key : spring->anchor_keys) add(key.time);
    }
  }
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  return ends;
}

double relative(double difference, double scale) {
  return scale > 0.0 ? difference / scale : 0.0;
}

double relative_vector(const physics::Vec3& a, const physics::Vec3& b, const physics::Vec3& start) {
  return relative((a - b).norm(), std::max({a.norm(), b.norm(), start.norm()}));
}

}  // namespace

FinalState final_state_of(const physics::BodyState& state) {
  return {.position = state.position(),
          .momentum = state.momentum(),
          .orientation = state.orientation(),
          .angular_momentum = state.angular_momentum(),
          .energy = physics::kinetic_energy(state)};
}

FinalState solve_reference(const physics::BodyModel& model, const physics::BodyState& initial,
                           double duration, double tolerance) {
  namespace odeint = boost::numeric::odeint;
  const physics::PrimaryState& start = initial.primary();
  OdeState y = {start.position.x(),        start.position.y(),         start.position.z(),
                start.momentum.x(),        start.momentum.y(),         start.momentum.z(),
                start.orientation.w(),     start.orientation.x(),      start.orientation.y(),
                start.orientation.z(),     start.angular_momentum.x(), start.angular_momentum.y(),
                start.angular_momentum.z()};
  const std::vector<Real> ends = piece_ends(model, Real(duration));
  for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
    const RigidBodyOde ode{model, (ends[i] + ends[i + 1]) / 2};
    const Real first_step = std::min<Real>(ends[i + 1] - ends[i], 1e-4L);
    odeint::integrate_adaptive(
        odeint::make_controlled(Real(tolerance), Real(tolerance),
                                odeint::runge_kutta_fehlberg78<OdeState, Real>()),
        ode, y, ends[i], ends[i + 1], first_step);
  }

  const Kinematics end = RigidBodyOde{model, Real(duration)}.kinematics(y);
  const RealVec3 momentum(y[3], y[4], y[5]);
  const RealVec3 angular_momentum(y[10], y[11], y[12]);
  const Real energy = (momentum.dot(end.velocity) + angular_momentum.dot(end.angular_velocity)) / 2;
  const RealQuat orientation = RealQuat(y[6], y[7], y[8], y[9]).normalized();
  return {.position = end.position.cast<double>(),
          .momentum = momentum.cast<double>(),
          .orientation = orientation.cast<double>(),
          .angular_momentum = angular_momentum.cast<double>(),
          .energy = static_cast<double>(energy)};
}

double relative_difference(const FinalState& a, const FinalState& b, const FinalState& start) {
  return std::max(
      {physics::angle_between(a.orientation, b.orientation),
       relative_vector(a.position, b.position, start.position),
       relative_vector(a.momentum, b.momentum, start.momentum),
       relative_vector(a.angular_momentum, b.angular_momentum, start.angular_momentum),
       relative(std::abs(a.energy - b.energy),
                std::max({std::abs(a.energy), std::abs(b.energy), std::abs(start.energy)}))});
}

}  // namespace tumble::bench
