// The exact torque-free motion of a rigid body: with no torque the world angular momentum L is
// constant and only the orientation moves. Used as the drift of the splitting integrators.
#pragma once

#include "physics/rigid_body.hpp"

namespace tumble::physics {

// The torque-free rotation from one start state, ready to be evaluated at any elapsed time.
// Everything that depends only on the start state (energy, |L|, moments: the elliptic modulus,
// frequency and amplitudes, and sn, cn, dn at the start) is computed once by the constructor;
// orientation_after() costs the rest.
//
// Cost of a construction and one evaluation (measured in tests/physics/free_rigid_body_test.cpp):
// isotropic and symmetric bodies a few sines and cosines; three different moments one Jacobi
// amplitude (about six arithmetic-geometric-mean steps) and one Π (Carlson's R_F and R_J), about
// a microsecond; steps longer than a half-period also need the complete Π.
class FreeRigidBodyFlow {
 public:
  FreeRigidBodyFlow(const BodyConstants& constants, const Quat& orientation /* body to world */,
                    const Vec3& angular_momentum /* kg m²/s, world frame */);

  // Orientation after `elapsed` seconds (any sign, any length) of torque-free motion, exact to
  // round-off: the body-frame L follows Euler's equations, the world L stays put.
  Quat orientation_after(double elapsed /* s */) const;

  // Three different moments: the motion in the "elliptic frame", a signed permutation of the
  // principal axes (a, b, c) in which b is the intermediate axis, c the axis the angular momentum
  // circulates about, and L_c > 0; there L / |L| = (A_a cn τ, ±A_b sn τ, A_c dn τ).
  struct Elliptic {
    Mat3 to_elliptic = Mat3::Identity();  // body principal frame → elliptic frame (a rotation)
    Vec3 inertia = Vec3::Ones();          // (I_a, I_b, I_c) (kg m²)
    Vec3 amplitude = Vec3::Zero();        // (A_a, A_b, A_c): largest |L_a|, |L_b|, |L_c|, over |L|
    double norm = 0.0;                    // |L| (kg m²/s)
    double sign_b = 1.0;                  // L_b = sign_b A_b sn τ: the sense of circulation
    double modulus = 0.0;                 // k
    double complement_squared = 1.0;      // k'² = 1 − k², computed without cancellation
    double frequency = 0.0;               // dτ/dt (1/s)
    double characteristic = 0.0;          // n < 0 of Π(n; φ | k), a function of the moments only
    Vec3 start = Vec3(0, 1, 1);  // (sn τ₀, cn τ₀, dn τ₀), from L itself, not from τ₀
    double start_offset = 0.0;   // azimuth of (L_a, L_b) minus am τ₀ (rad)
    Quat start_alignment = Quat::Identity();  // minimal rotation taking L̂ (elliptic frame) to +c
  };

 private:
  enum class Kind { still, steady, symmetric, elliptic };

  Kind kind_ = Kind::still;
  Quat start_ = Quat::Identity();  // body to world at elapsed = 0
  Vec3 axis_ = Vec3::UnitZ();      // L / |L|, world frame
  // steady: rate of rotation about L (rad/s); symmetric: the same for the equal moments I₁.
  double rate_about_momentum_ = 0.0;
  // symmetric only: the symmetry axis (body frame) and the rate of rotation about it (rad/s).
  Vec3 symmetry_axis_ = Vec3::UnitZ();
  double rate_about_symmetry_axis_ = 0.0;
  Elliptic elliptic_;
};

// The orientation after time h (s) of torque-free motion from `orientation` with world angular
// momentum L; L, position and momentum do not change. Builds a FreeRigidBodyFlow and evaluates it.
Quat free_rigid_body(const BodyConstants& constants, const Quat& orientation,
                     const Vec3& angular_momentum /* kg m²/s, world frame */, double h /* s */);

}  // namespace tumble::physics
