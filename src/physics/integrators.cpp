#include "physics/integrators.hpp"

namespace tumble::physics {
namespace {

// Time derivative of the primary state: (dx/dt, dp/dt, dq/dt, dL/dt).
struct Derivative {
  Vec3 velocity = Vec3::Zero();  // m/s
  Vec3 force = Vec3::Zero();     // N
  Quat spin = Quat(0, 0, 0, 0);  // 1/s
  Vec3 torque = Vec3::Zero();    // N m
};

// primary + derivative * h, as a raw (not yet normalised) primary state.
PrimaryState advanced(const PrimaryState& in, const Derivative& rate, double h) {
  PrimaryState out = in;
  out.position += h * rate.velocity;
  out.momentum += h * rate.force;
  out.orientation.coeffs() += h * rate.spin.coeffs();
  out.angular_momentum += h * rate.torque;
  return out;
}

Derivative derivative_at(const BodyModel& model, const BodyState& state, double t) {
  const Wrench wrench = total_wrench(model.forces, model.constants, state, t);
  return {.velocity = state.velocity(),
          .force = wrench.force,
          .spin = state.spin(),
          .torque = wrench.torque};
}

BodyState euler_step(const BodyModel& model, const BodyState& in, double t, double dt) {
  return BodyState(advanced(in.primary(), derivative_at(model, in, t), dt), model.constants);
}

// Kick the momenta with forces from the start of the step, then drift the pose with the new
// velocities (semi-implicit Euler).
BodyState symplectic_euler_step(const BodyModel& model, const BodyState& in, double t, double dt) {
  const Wrench wrench = total_wrench(model.forces, model.constants, in, t);
  PrimaryState kicked = in.primary();
  kicked.momentum += dt * wrench.force;
  kicked.angular_momentum += dt * wrench.torque;
  const BodyState mid(kicked, model.constants);
  return BodyState(advanced(kicked, {.velocity = mid.velocity(), .spin = mid.spin()}, dt),
                   model.constants);
}

// Fiedler's RK4: each stage state is recalculated (and so its quaternion normalised) before
// its derivative is taken; measured still fourth order (tests/physics/integrators_test.cpp).
BodyState rk4_step(const BodyModel& model, const BodyState& in, double t, double dt) {
  const auto stage = [&](const Derivative& rate, double h) {
    const BodyState state(advanced(in.primary(), rate, h), model.constants);
    return derivative_at(model, state, t + h);
  };
  const Derivative a = derivative_at(model, in, t);
  const Derivative b = stage(a, 0.5 * dt);
  const Derivative c = stage(b, 0.5 * dt);
  const Derivative d = stage(c, dt);
  Derivative combined;
  combined.velocity = (a.velocity + 2.0 * (b.velocity + c.velocity) + d.velocity) / 6.0;
  combined.force = (a.force + 2.0 * (b.force + c.force) + d.force) / 6.0;
  combined.spin.coeffs() =
      (a.spin.coeffs() + 2.0 * (b.spin.coeffs() + c.spin.coeffs()) + d.spin.coeffs()) / 6.0;
  combined.torque = (a.torque + 2.0 * (b.torque + c.torque) + d.torque) / 6.0;
  return BodyState(advanced(in.primary(), combined, dt), model.constants);
}

}  // namespace

std::string_view integrator_name(Integrator integrator) {
  switch (integrator) {
    case Integrator::euler:
      return "euler";
    case Integrator::symplectic_euler:
      return "symplectic_euler";
    case Integrator::rk4:
      return "rk4";
  }
  return "unknown";
}

std::optional<Integrator> integrator_from_name(std::string_view name) {
  for (const Integrator integrator : kAllIntegrators) {
    if (integrator_name(integrator) == name) return integrator;
  }
  return std::nullopt;
}

BodyState step(Integrator integrator, const BodyModel& model, const BodyState& state, double t,
               double dt) {
  switch (integrator) {
    case Integrator::euler:
      return euler_step(model, state, t, dt);
    case Integrator::symplectic_euler:
      return symplectic_euler_step(model, state, t, dt);
    case Integrator::rk4:
      return rk4_step(model, state, t, dt);
  }
  return state;
}

}  // namespace tumble::physics
