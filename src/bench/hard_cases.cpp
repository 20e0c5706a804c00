#include "bench/hard_cases.hpp"

#include <cmath>

namespace tumble::bench {
namespace {

using physics::Quat;
using physics::Vec3;

Quat about(double angle /* rad */, const Vec3& axis) {
  return Quat(Eigen::AngleAxisd(angle, axis.normalized()));
}

// Fiedler's example cube: 1 kg, 1 m, from rest, torque τ = 1 N m about x against angular damping
// c = 0.1 N m s. With k = c / I, I dω/dt = τ - c ω gives ω(t) = (τ / c)(1 - e^{-k t}) and the
// angle turned θ(t) = (τ / c)(t - (1 - e^{-k t}) / k) (tests/support/closed_forms.hpp).
HardCase article_cube() {
  const double torque = 1.0, coefficient = 0.1, duration = 20.0;
  const physics::BodyConstants constants = physics::cube_constants(1.0, 1.0);
  const double inertia = constants.inertia.x();
  return {
      .name = "article_cube",
      .summary =
          "Fiedler's unit cube spun up from rest by 1 N m about x against angular damping "
          "0.1 N m s, 20 s (183 rad turned)",
      .model = {.constants = constants,
                .forces = {physics::ConstantTorque{.torque = Vec3(torque, 0, 0)},
                           physics::AngularDamping{.coefficient = coefficient}}},
      .initial = physics::make_state(constants, Vec3::Zero(), Vec3::Zero(), Quat::Identity(),
                                     Vec3::Zero()),
      .duration = duration,
      .closed_form =
          [=] {
            const double rate = coefficient / inertia;
            const double decayed = 1.0 - std::exp(-rate * duration);
            const double spin = torque / coefficient * decayed;                       // rad/s
            const double angle = torque / coefficient * (duration - decayed / rate);  // rad
            return FinalState{.orientation = about(angle, Vec3::UnitX()),
                              .angular_momentum = Vec3(inertia * spin, 0, 0),
                              .energy = 0.5 * inertia * spin * spin};
          },
  };
}

// A spinning cube thrown under gravity: a parabola for the centre and, the inertia being
// isotropic and there being no torque, a constant angular velocity, so q(t) = exp(ω t / 2) q0.
HardCase spinning_projectile() {
  const Vec3 position(0.0, 1.0, 0.0), velocity(3.0, 8.0, -1.0), gravity(0.0, -9.81, 0.0);
  const Vec3 spin(2.0, -5.0, 7.0);  // rad/s, world
  const Quat orientation = about(0.4, Vec3(1, 1, 0));
  const double duration = 5.0;
  const physics::BodyConstants constants = physics::cube_constants(1.0, 1.0);
  return {
      .name = "spinning_projectile",
      .summary = "A unit cube thrown at 8.6 m/s under gravity, spinning at 8.8 rad/s, 5 s",
      .model = {.constants = constants, .forces = {physics::Gravity{.acceleration = gravity}}},
      .initial = physics::make_state(constants, position, velocity, orientation, spin),
      .duration = duration,
      .conserves_angular_momentum = true,
      .headline = HeadlineError::position,
      .closed_form =
          [=] {
            const double t = duration;
            const Vec3 end_velocity = velocity + gravity * t;
            const double inertia = constants.inertia.x();
            return FinalState{.position = position + velocity * t + 0.5 * gravity * t * t,
                              .momentum = constants.mass * end_velocity,
                              .orientation = about(spin.norm() * t, spin) * orientation,
                              .angular_momentum = inertia * spin,
                              .energy = 0.5 * constants.mass * end_velocity.squaredNorm() +
                                        0.5 * inertia * spin.squaredNorm()};
          },
  };
}

// The tennis-racket (Dzhanibekov) flip. Box 0.3 × 1 × 2 m, 1 kg: I = (0.417, 0.341, 0.091) kg m²,
// y intermediate. Spin 3 rad/s about body y, perturbed by 0.3 rad/s (10%) about body x. That puts
// the motion clearly off the separatrix: L²/(2E) exceeds I_y by 0.27% and the elliptic modulus
// has 1 - k² = 0.016 (a perturbation of 0.01 rad/s would give 5e-6), so the flip period, 6.5 s,
// depends only mildly on the energy and a reference error does not grow into a phase error.
// 120 s is about 18 periods, each with two flips.
HardCase dzhanibekov() {
  const physics::BodyConstants constants = physics::box_constants(1.0, Vec3(0.3, 1.0, 2.0));
  const Quat orientation = about(0.5, Vec3(1, 2, 3));
  const Vec3 spin_body(0.3, 3.0, 0.0);  // rad/s, body frame
  return {
      .name = "dzhanibekov",
      .summary =
          "A 0.3 x 1 x 2 m box spun at 3 rad/s about its intermediate axis with a 10% "
          "perturbation, torque-free, flipping every 3.2 s, 120 s",
      .model = {.constants = constants, .forces = {}},
      .initial = physics::make_state(constants, Vec3::Zero(), Vec3::Zero(), orientation,
                                     orientation * spin_body),
      .duration = 120.0,
      .conserves_angular_momentum = true,
      .conserves_energy = true,
  };
}

// A box tumbling fast: 250 rad/s about the body direction (1, 2, 3), which is no principal axis,
// so the angular velocity precesses and nutates. 10 s is 2500 rad.
HardCase fast_spin() {
  const physics::BodyConstants constants = physics::box_constants(1.5, Vec3(0.4, 0.7, 1.0));
  const Quat orientation = about(1.0, Vec3(-1, 0, 2));
  const Vec3 spin_body = 250.0 * Vec3(1, 2, 3).normalized();  // rad/s, body frame
  return {
      .name = "fast_spin",
      .summary =
          "A 0.4 x 0.7 x 1 m box tumbling at 250 rad/s about a non-principal axis, "
          "torque-free, 10 s",
      .model = {.constants = constants, .forces = {}},
      .initial = physics::make_state(constants, Vec3::Zero(), Vec3::Zero(), orientation,
                                     orientation * spin_body),
      .duration = 10.0,
      .conserves_angular_momentum = true,
      .conserves_energy = true,
  };
}

// Viscous drag much faster than any benchmarked step: k = c / m = 600 / 2 = 300 /s, so
// p(t) = p0 e^{-k t} and x(t) = x0 + v0 (1 - e^{-k t}) / k. Explicit Euler needs k dt <= 2,
// RK4 k dt <= 2.785.
HardCase stiff_linear_damping() {
  const Vec3 position(0.0, 0.5, 0.0), velocity(2.0, 1.0, -1.0);
  const double coefficient = 600.0, duration = 1.0;
  const physics::BodyConstants constants = physics::cube_constants(2.0, 1.0);
  return {
      .name = "stiff_linear_damping",
      .summary = "A 2 kg cube coasting at 2.4 m/s into linear damping 600 N s/m (k = 300 /s), 1 s",
      .model = {.constants = constants,
                .forces = {physics::LinearDamping{.coefficient = coefficient}}},
      .initial = physics::make_state(constants, position, velocity, Quat::Identity(), Vec3::Zero()),
      .duration = duration,
      .conserves_angular_momentum = true,
      .headline = HeadlineError::position,
      .closed_form =
          [=] {
            const double rate = coefficient / constants.mass;
            const double remaining = std::exp(-rate * duration);
            const Vec3 end_velocity = velocity * remaining;
            return FinalState{.position = position + velocity * (1.0 - remaining) / rate,
                              .momentum = constants.mass * end_velocity,
                              .energy = 0.5 * constants.mass * end_velocity.squaredNorm()};
          },
  };
}

// Rotational drag much faster than any benchmarked step: a unit cube (I = 1/6 kg m²) with
// c = 50 N m s, so k = c / I = 300 /s, L(t) = L0 e^{-k t}, and the cube turns about the fixed
// axis of ω0 through |ω0| (1 - e^{-k t}) / k.
HardCase stiff_angular_damping() {
  const Vec3 spin(3.0, -4.0, 12.0);  // rad/s, world
  const Quat orientation = about(0.7, Vec3(0, 1, 1));
  const double coefficient = 50.0, duration = 1.0;
  const physics::BodyConstants constants = physics::cube_constants(1.0, 1.0);
  return {
      .name = "stiff_angular_damping",
      .summary = "A unit cube spinning at 13 rad/s into angular damping 50 N m s (k = 300 /s), 1 s",
      .model = {.constants = constants,
                .forces = {physics::AngularDamping{.coefficient = coefficient}}},
      .initial = physics::make_state(constants, Vec3::Zero(), Vec3::Zero(), orientation, spin),
      .duration = duration,
      .closed_form =
          [=] {
            const double inertia = constants.inertia.x();
            const double rate = coefficient / inertia;
            const double remaining = std::exp(-rate * duration);
            const Vec3 end_spin = spin * remaining;
            return FinalState{
                .orientation = about(spin.norm() * (1.0 - remaining) / rate, spin) * orientation,
                .angular_momentum = inertia * end_spin,
                .energy = 0.5 * inertia * end_spin.squaredNorm()};
          },
  };
}

// A constant world force at a body corner, off the centre: the torque turns with the body, which
// swings like a pendulum about the force's direction while it spins (an asymmetric heavy top
// about its centre) and the centre accelerates uniformly.
HardCase pushed_corner() {
  const physics::BodyConstants constants = physics::box_constants(2.0, Vec3(0.6, 0.4, 0.2));
  return {
      .name = "pushed_corner",
      .summary =
          "A 0.6 x 0.4 x 0.2 m box pushed by 1 N at a corner while spinning at 2 rad/s, "
          "10 s",
      .model = {.constants = constants,
                .forces = {physics::ForceAtPoint{.force = Vec3(0.0, 1.0, 0.0),
                                                 .point = Vec3(0.3, 0.2, 0.1)}}},
      .initial = physics::make_state(constants, Vec3::Zero(), Vec3(0.2, 0.0, 0.0),
                                     about(0.3, Vec3(1, 0, 1)), Vec3(0.5, 0.0, 2.0)),
      .duration = 10.0,
  };
}

// A long torque-free run: a 1 × 0.5 × 0.25 m box tumbling at 1.6 rad/s for 1000 s. Errors in the
// rotation period accumulate linearly into the phase.
HardCase long_torque_free() {
  const physics::BodyConstants constants = physics::box_constants(1.0, Vec3(1.0, 0.5, 0.25));
  const Quat orientation = about(1.0, Vec3(0, 1, 1));
  const Vec3 spin_body(0.6, -0.9, 1.2);  // rad/s, body frame
  return {
      .name = "long_torque_free",
      .summary =
          "A 1 x 0.5 x 0.25 m box tumbling freely at 1.6 rad/s, drifting at 0.2 m/s, "
          "1000 s",
      .model = {.constants = constants, .forces = {}},
      .initial = physics::make_state(constants, Vec3::Zero(), Vec3(0.2, 0.0, 0.0), orientation,
                                     orientation * spin_body),
      .duration = 1000.0,
      .conserves_angular_momentum = true,
      .conserves_energy = true,
  };
}

// A box hanging by one corner from a damped spring under gravity: the corner is released 1.14 m
// from the anchor (the spring at rest would be 1 m, and 1.1 m under the box's weight) and 0.5 m to
// the side, with the box twisted and turning, so it bounces, swings like a pendulum and wobbles
// about the corner at once: every translation-rotation coupling is active.
HardCase box_on_spring() {
  const physics::BodyConstants constants = physics::box_constants(1.0, Vec3(0.5, 1.0, 1.5));
  const physics::Spring spring{.anchor = Vec3(0, 2, 0),
                               .attachment = Vec3(0.25, 0.5, 0.75),  // a corner
                               .stiffness = 100.0,
                               .damping = 0.5,
                               .rest_length = 1.0};
  const Quat orientation = about(0.3, Vec3::UnitZ());
  const Vec3 corner(0.5, 1.0, 0.2);  // m, world
  return {
      .name = "box_on_spring",
      .summary =
          "A 0.5 x 1 x 1.5 m box hanging by a corner from a 100 N/m damped spring under "
          "gravity, released swinging and twisting, 10 s",
      .model = {.constants = constants, .forces = {physics::Gravity{}, spring}},
      .initial = physics::make_state(constants, corner - orientation * spring.attachment,
                                     Vec3(0.0, 0.0, 0.5), orientation, Vec3(0.5, 1.0, -0.3)),
      .duration = 10.0,
      .headline = HeadlineError::position,
  };
}

}  // namespace

const Reference& HardCase::reference() const {
  std::call_once(cache->once, [this] {
    Reference& out = cache->value;
    const FinalState start = final_state_of(initial);
    const FinalState tight = solve_reference(model, initial, duration, kReferenceTolerance);
    const FinalState loose = solve_reference(model, initial, duration, kCrossCheckTolerance);
    out.tolerance_difference = relative_difference(loose, tight, start);
    if (closed_form) {
      out.state = closed_form();
      out.closed_form = true;
      out.closed_form_difference = relative_difference(out.state, tight, start);
    } else {
      out.state = tight;
    }
  });
  return cache->value;
}

const std::vector<HardCase>& hard_cases() {
  static const std::vector<HardCase> cases = {
      article_cube(),  spinning_projectile(),  dzhanibekov(),
      fast_spin(),     stiff_linear_damping(), stiff_angular_damping(),
      pushed_corner(), long_torque_free(),     box_on_spring(),
  };
  return cases;
}

const HardCase* find_hard_case(const std::string& name) {
  for (const HardCase& c : hard_cases()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

}  // namespace tumble::bench
