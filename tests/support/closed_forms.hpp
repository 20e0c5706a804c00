// Exact solutions that the physics tests compare against.
#pragma once

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

}  // namespace tumble::testing
