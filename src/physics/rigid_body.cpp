#include "physics/rigid_body.hpp"

#include <cmath>

namespace tumble::physics {
namespace {

// R D Rᵀ a for a diagonal body-frame tensor D: a world vector through a body-frame tensor.
Vec3 through_body_tensor(const Mat3& rotation, const Vec3& diagonal, const Vec3& world_vector) {
  return rotation * diagonal.cwiseProduct(rotation.transpose() * world_vector);
}

}  // namespace

BodyConstants cube_constants(double mass, double side) {
  return constants_from_moments(mass, Vec3::Constant(mass * side * side / 6.0));
}

BodyConstants box_constants(double mass, const Vec3& size) {
  const Vec3 squared = size.cwiseProduct(size);
  const Vec3 inertia =
      mass / 12.0 *
      Vec3(squared.y() + squared.z(), squared.x() + squared.z(), squared.x() + squared.y());
  return constants_from_moments(mass, inertia);
}

BodyConstants static_constants() {
  return BodyConstants{.mass = 0.0,
                       .inverse_mass = 0.0,
                       .inertia = Vec3::Zero(),
                       .inverse_inertia = Vec3::Zero(),
                       .isotropic = true};
}

BodyConstants constants_from_moments(double mass, const Vec3& moments) {
  return BodyConstants{.mass = mass,
                       .inverse_mass = 1.0 / mass,
                       .inertia = moments,
                       .inverse_inertia = moments.cwiseInverse(),
                       .isotropic = moments.x() == moments.y() && moments.y() == moments.z()};
}

Vec3 apply_inverse_inertia_world(const BodyConstants& constants, const Quat& orientation,
                                 const Vec3& world_vector) {
  if (constants.isotropic) return constants.inverse_inertia.x() * world_vector;
  return through_body_tensor(orientation.toRotationMatrix(), constants.inverse_inertia,
                             world_vector);
}

Vec3 apply_inertia_world(const BodyConstants& constants, const Quat& orientation,
                         const Vec3& world_vector) {
  if (constants.isotropic) return constants.inertia.x() * world_vector;
  return through_body_tensor(orientation.toRotationMatrix(), constants.inertia, world_vector);
}

void BodyState::recalculate(const BodyConstants& constants) {
  primary_.orientation.normalize();

  derived_.velocity = primary_.momentum * constants.inverse_mass;
  if (constants.isotropic) {
    derived_.angular_velocity = constants.inverse_inertia.x() * primary_.angular_momentum;
  } else {
    derived_.angular_velocity =
        through_body_tensor(rotation(), constants.inverse_inertia, primary_.angular_momentum);
  }
  const Vec3& w = derived_.angular_velocity;
  derived_.spin.coeffs() = 0.5 * (Quat(0.0, w.x(), w.y(), w.z()) * primary_.orientation).coeffs();

  // A non-finite state is not asserted against: a step too large for the forces produces one,
  // and sim::Simulation reports it as a blow-up, naming the body and the time.
}

Mat4 BodyState::body_to_world() const {
  Mat4 out = Mat4::Identity();
  out.topLeftCorner<3, 3>() = rotation();
  out.topRightCorner<3, 1>() = primary_.position;
  return out;
}

Mat4 BodyState::world_to_body() const {
  const Mat3 inverse = rotation().transpose();
  Mat4 out = Mat4::Identity();
  out.topLeftCorner<3, 3>() = inverse;
  out.topRightCorner<3, 1>() = -(inverse * primary_.position);
  return out;
}

BodyState make_state(const BodyConstants& constants, const Vec3& position, const Vec3& velocity,
                     const Quat& orientation, const Vec3& angular_velocity) {
  const Quat unit = orientation.normalized();
  return BodyState(
      PrimaryState{.position = position,
                   .momentum = constants.mass * velocity,
                   .orientation = unit,
                   .angular_momentum = apply_inertia_world(constants, unit, angular_velocity)},
      constants);
}

double angle_between(const Quat& a, const Quat& b) {
  const Quat relative = a.conjugate() * b;
  // atan2 stays accurate for tiny angles, where acos(|w|) loses half the digits.
  return 2.0 * std::atan2(relative.vec().norm(), std::abs(relative.w()));
}

double kinetic_energy(const BodyState& state) {
  return 0.5 * state.momentum().dot(state.velocity()) +
         0.5 * state.angular_momentum().dot(state.angular_velocity());
}

Vec3 body_point_to_world(const BodyState& state, const Vec3& body_point) {
  return state.position() + state.orientation() * body_point;
}

Vec3 point_velocity(const BodyState& state, const Vec3& world_point) {
  return state.velocity() + state.angular_velocity().cross(world_point - state.position());
}

}  // namespace tumble::physics
