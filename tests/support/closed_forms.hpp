// Exact solutions that the physics tests compare against.
#pragma once

#include <algorithm>
#include <cmath>

#include "physics/integrators.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::testing {

using physics::Quat;
using physics::Vec3;

// Fiedler's example: a cube from rest under a constant torque τ about x and angular damping c.
// With k = c / I, I dω/dt = τ - c ω gives ω(t) = (τ / c)(1 - e^{-k t}) about x, and the angle
// turned is θ(t) = (τ / c)(t - (1 - e^{-k t}) / k).
struct DampedSpinUp {
  double torque = 1.0;         // N m, about world x
  double coefficient = 0.1;    // N m s
  double inertia = 1.0 / 6.0;  // kg m² (unit cube, 1 kg)

  double rate() const { return coefficient / inertia; }  // k (1/s)
  double angular_velocity(double t) const {
    return torque / coefficient * (1.0 - std::exp(-rate() * t));
  }
  double angle(double t) const {
    return torque / coefficient * (t - (1.0 - std::exp(-rate() * t)) / rate());
  }
  Quat orientation(double t) const { return Quat(Eigen::AngleAxisd(angle(t), Vec3::UnitX())); }
};

// Fiedler's example as a body: a unit cube from rest under the torque and damping above.
struct ArticleCube {
  DampedSpinUp exact;
  physics::BodyModel model{.constants = physics::cube_constants(1.0, 1.0),
                           .forces = {physics::ConstantTorque{.torque = Vec3(exact.torque, 0, 0)},
                                      physics::AngularDamping{.coefficient = exact.coefficient}}};
  physics::BodyState start = physics::make_state(model.constants, Vec3::Zero(), Vec3::Zero(),
                                                 Quat::Identity(), Vec3::Zero());
};

// A torque-free body with isotropic inertia under uniform gravity: a parabola for the centre,
// a constant angular velocity, so q(t) = exp(ω t / 2) q0.
struct SpinningProjectile {
  Vec3 position = Vec3(0.0, 1.0, 0.0);           // m
  Vec3 velocity = Vec3(3.0, 8.0, -1.0);          // m/s
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);          // m/s²
  Vec3 angular_velocity = Vec3(2.0, -5.0, 7.0);  // rad/s, world frame
  Quat orientation = Quat(Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized()));

  Vec3 position_at(double t) const { return position + velocity * t + 0.5 * gravity * t * t; }
  Vec3 velocity_at(double t) const { return velocity + gravity * t; }
  Quat orientation_at(double t) const {
    return Quat(Eigen::AngleAxisd(angular_velocity.norm() * t, angular_velocity.normalized())) *
           orientation;
  }
};

// Fiedler's mouse drag, scripted: a body pulled along x by a zero-length, critically damped
// spring at its centre (k = m ω², c = 2 m ω), no other force. The anchor rests at the origin
// until `start`, moves at V until `stop`, and rests there after. The lag y = x − a obeys
// y'' + 2ω y' + ω² y = −a''(t) = −V δ(t − start) + V δ(t − stop) (the damper acting on the
// velocity relative to the anchor), so from rest at the anchor y(t) = −V g(t − start) +
// V g(t − stop) with the impulse response g(τ) = τ e^{−ωτ} for τ >= 0, and 0 before (rates
// taken from the right at the two kinks, as the anchor's velocity is).
struct CriticallyDampedDrag {
  double mass = 1.0;        // kg
  double frequency = 20.0;  // ω (rad/s)
  double speed = 0.5;       // V (m/s)
  double start = 0.25;      // s
  double stop = 2.25;       // s

  double stiffness() const { return mass * frequency * frequency; }  // N/m
  double damping() const { return 2.0 * mass * frequency; }          // N s/m
  double anchor_at(double t) const { return speed * std::clamp(t - start, 0.0, stop - start); }
  double position_at(double t) const {
    return anchor_at(t) - speed * response(t - start) + speed * response(t - stop);
  }
  double velocity_at(double t) const {
    const double anchor_velocity = t >= start && t < stop ? speed : 0.0;
    return anchor_velocity - speed * response_rate(t - start) + speed * response_rate(t - stop);
  }

  physics::BodyModel model() const {
    return {.constants = physics::cube_constants(mass, 1.0),
            .forces = {physics::Spring{
                .anchor_keys = {{.time = start, .anchor = Vec3::Zero()},
                                {.time = stop, .anchor = Vec3(anchor_at(stop), 0, 0)}},
                .stiffness = stiffness(),
                .damping = damping()}}};
  }
  physics::BodyState at_rest() const {
    return physics::make_state(model().constants, Vec3::Zero(), Vec3::Zero(), Quat::Identity(),
                               Vec3::Zero());
  }

 private:
  double response(double tau) const { return tau > 0.0 ? tau * std::exp(-frequency * tau) : 0.0; }
  double response_rate(double tau) const {
    return tau >= 0.0 ? (1.0 - frequency * tau) * std::exp(-frequency * tau) : 0.0;
  }
};

}  // namespace tumble::testing
