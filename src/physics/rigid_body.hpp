// Rigid-body state after Glenn Fiedler, "Physics in 3D": primary state that the integrators
// advance, derived state recomputed from it in exactly one place, and per-body constants.
#pragma once

#include <Eigen/Geometry>

namespace tumble::physics {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;  // constructed as (w, x, y, z)
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;

// Mass properties of one body: immutable while it moves.
struct BodyConstants {
  double mass = 1.0;                           // kg
  double inverse_mass = 1.0;                   // 1/kg
  Vec3 inertia = Vec3::Constant(1.0);          // principal moments, body frame (kg m²)
  Vec3 inverse_inertia = Vec3::Constant(1.0);  // their reciprocals (1/(kg m²))
  // All three moments equal (a uniform cube): I⁻¹ is a scalar in every frame, so the
  // angular velocity needs no rotation of the inertia tensor.
  bool isotropic = true;
};

// The constants of a body of `mass` (kg) with principal `moments` (kg m², body frame).
BodyConstants constants_from_moments(double mass, const Vec3& moments);
// A static body's: no inverse mass or inertia, so that no impulse moves it (mass and moments 0:
// it has no momentum to speak of).
BodyConstants static_constants();
// A uniform-density cube: I = m s² / 6 about every axis through the centre.
BodyConstants cube_constants(double mass /* kg */, double side /* m */);
// A uniform-density box with edge lengths `size` along the body axes:
// I_x = m (b² + c²) / 12 and cyclically.
BodyConstants box_constants(double mass /* kg */, const Vec3& size /* m, body frame */);

// What the integrators advance.
struct PrimaryState {
  Vec3 position = Vec3::Zero();          // centre of mass, world frame (m)
  Vec3 momentum = Vec3::Zero();          // linear momentum, world frame (kg m/s)
  Quat orientation = Quat::Identity();   // body-to-world rotation; normalised by recalculate
  Vec3 angular_momentum = Vec3::Zero();  // about the centre of mass, world frame (kg m²/s)
};

// What follows from the primary state and the constants and is read at every integrator stage.
// The article's body<->world matrices are derived too, but only drawing and tests read them: they
// are computed on demand (BodyState::body_to_world) so that a step carries 80 bytes here, not 336.
struct DerivedState {
  Vec3 velocity = Vec3::Zero();          // p / m, world frame (m/s)
  Vec3 angular_velocity = Vec3::Zero();  // I_world⁻¹ L, world frame (rad/s)
  Quat spin = Quat(0, 0, 0, 0);          // dq/dt = 0.5 (0, ω) q (1/s)
};

// A body's state. The derived part has one writer, recalculate(), which runs whenever the
// primary part is set; nothing else can assign velocity, angular velocity or spin.
class BodyState {
 public:
  BodyState() = default;
  BodyState(const PrimaryState& primary, const BodyConstants& constants) {
    set(primary, constants);
  }

  // Replaces the primary state and recalculates (which also normalises the orientation).
  void set(const PrimaryState& primary, const BodyConstants& constants) {
    primary_ = primary;
    recalculate(constants);
  }

  const PrimaryState& primary() const { return primary_; }
  const DerivedState& derived() const { return derived_; }

  const Vec3& position() const { return primary_.position; }
  const Vec3& momentum() const { return primary_.momentum; }
  const Quat& orientation() const { return primary_.orientation; }
  const Vec3& angular_momentum() const { return primary_.angular_momentum; }
  const Vec3& velocity() const { return derived_.velocity; }
  const Vec3& angular_velocity() const { return derived_.angular_velocity; }
  const Quat& spin() const { return derived_.spin; }

  // The derived matrices, from the primary state when asked for.
  Mat3 rotation() const { return primary_.orientation.toRotationMatrix(); }  // body to world
  Mat4 body_to_world() const;  // homogeneous: rotate by q, then translate by x
  Mat4 world_to_body() const;  // its inverse

 private:
  void recalculate(const BodyConstants& constants);

  PrimaryState primary_;
  DerivedState derived_;
};

// A state from the quantities a scene gives: velocity and angular velocity in the world frame.
BodyState make_state(const BodyConstants& constants, const Vec3& position /* m */,
                     const Vec3& velocity /* m/s */, const Quat& orientation,
                     const Vec3& angular_velocity /* rad/s, world frame */);

// Inverse inertia in the world frame applied to a world vector: I_world⁻¹ a = R I_body⁻¹ Rᵀ a.
Vec3 apply_inverse_inertia_world(const BodyConstants& constants, const Quat& orientation,
                                 const Vec3& world_vector);
// Inertia in the world frame applied to a world vector: I_world a = R I_body Rᵀ a.
Vec3 apply_inertia_world(const BodyConstants& constants, const Quat& orientation,
                         const Vec3& world_vector);

// Angle of the rotation that takes orientation a to orientation b, in [0, π] (rad).
double angle_between(const Quat& a, const Quat& b);

// Kinetic energy, translational plus rotational: ½ p·v + ½ L·ω (J).
double kinetic_energy(const BodyState& state);

// World position of a point fixed in the body, given relative to the centre of mass (m).
Vec3 body_point_to_world(const BodyState& state, const Vec3& body_point);
// Velocity of a world point moving with the body: v + ω × (p - x) (m/s).
Vec3 point_velocity(const BodyState& state, const Vec3& world_point);

}  // namespace tumble::physics
