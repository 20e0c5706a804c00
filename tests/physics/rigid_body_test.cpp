#include "physics/rigid_body.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::physics {
namespace {

// A box with three different edges, tilted about a generic axis: no symmetry hides a bug.
struct TiltedBox {
  BodyConstants constants = box_constants(2.0, Vec3(0.4, 1.0, 2.5));
  Quat orientation = Quat(Eigen::AngleAxisd(0.9, Vec3(1.0, -2.0, 0.5).normalized()));
};

Mat3 inertia_world_matrix(const BodyConstants& constants, const Quat& orientation) {
  const Mat3 rotation = orientation.toRotationMatrix();
  return rotation * constants.inertia.asDiagonal() * rotation.transpose();
}

TEST(RigidBody, CubeInertiaIsMassTimesSideSquaredOverSix) {
  const BodyConstants cube = cube_constants(3.0, 2.0);
  EXPECT_DOUBLE_EQ(cube.inertia.x(), 3.0 * 4.0 / 6.0);
  EXPECT_EQ(cube.inertia, Vec3::Constant(cube.inertia.x()));
  EXPECT_DOUBLE_EQ(cube.inverse_inertia.x() * cube.inertia.x(), 1.0);
  EXPECT_DOUBLE_EQ(cube.inverse_mass, 1.0 / 3.0);
  EXPECT_TRUE(cube.isotropic);
}

TEST(RigidBody, BoxInertiaIsTheUniformBoxFormula) {
  const BodyConstants box = box_constants(12.0, Vec3(1.0, 2.0, 3.0));
  EXPECT_DOUBLE_EQ(box.inertia.x(), 4.0 + 9.0);  // m (b² + c²) / 12 with m = 12
  EXPECT_DOUBLE_EQ(box.inertia.y(), 1.0 + 9.0);
  EXPECT_DOUBLE_EQ(box.inertia.z(), 1.0 + 4.0);
  EXPECT_DOUBLE_EQ(box.inverse_inertia.z(), 0.2);
  EXPECT_FALSE(box.isotropic);
}

TEST(RigidBody, BoxWithEqualEdgesMatchesTheCube) {
  const BodyConstants box = box_constants(1.5, Vec3::Constant(0.7));
  const BodyConstants cube = cube_constants(1.5, 0.7);
  EXPECT_TRUE(box.isotropic);
  EXPECT_NEAR(box.inertia.x(), cube.inertia.x(), 1e-15);
}

TEST(RigidBody, RecalculateNormalisesTheOrientation) {
  const BodyConstants constants = cube_constants(1.0, 1.0);
  const BodyState state(PrimaryState{.orientation = Quat(2.0, 0.4, -1.0, 0.2)}, constants);
  EXPECT_NEAR(state.orientation().norm(), 1.0, 1e-15);
  EXPECT_NEAR(state.orientation().w(), 2.0 / std::sqrt(4.0 + 0.16 + 1.0 + 0.04), 1e-15);
}

TEST(RigidBody, MatricesAreInversesOfEachOther) {
  const TiltedBox box;
  const BodyState state(
      PrimaryState{.position = Vec3(1.0, -2.0, 3.0), .orientation = box.orientation},
      box.constants);
  const Mat4 product = state.body_to_world() * state.world_to_body();
  EXPECT_LT((product - Mat4::Identity()).cwiseAbs().maxCoeff(), 1e-14);
  // And they place a body point where the quaternion does.
  const Vec3 body_point(0.2, 0.5, -1.0);
  const Eigen::Vector4d world = state.body_to_world() * body_point.homogeneous();
  EXPECT_LT((world.head<3>() - body_point_to_world(state, body_point)).norm(), 1e-14);
}

TEST(RigidBody, AngularVelocityIsWorldInverseInertiaTimesAngularMomentum) {
  const TiltedBox box;
  const Vec3 angular_momentum(0.3, -1.2, 2.0);
  const BodyState state(
      PrimaryState{.orientation = box.orientation, .angular_momentum = angular_momentum},
      box.constants);
  const Mat3 inertia_world = inertia_world_matrix(box.constants, box.orientation);
  EXPECT_LT((inertia_world * state.angular_velocity() - angular_momentum).norm(), 1e-14);
}

TEST(RigidBody, CubeAngularVelocityIsAngularMomentumOverScalarInertia) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  const BodyState state(
      PrimaryState{.orientation = TiltedBox().orientation, .angular_momentum = Vec3(1.0, 2.0, 3.0)},
      cube);
  EXPECT_LT((state.angular_velocity() - 6.0 * Vec3(1.0, 2.0, 3.0)).norm(), 1e-14);
}

TEST(RigidBody, VelocityIsMomentumOverMass) {
  const BodyState state(PrimaryState{.momentum = Vec3(4.0, -2.0, 1.0)}, cube_constants(2.0, 1.0));
  EXPECT_EQ(state.velocity(), Vec3(2.0, -1.0, 0.5));
}

TEST(RigidBody, SpinIsHalfAngularVelocityTimesOrientation) {
  const TiltedBox box;
  const BodyState state(
      PrimaryState{.orientation = box.orientation, .angular_momentum = Vec3(0.5, 0.1, -0.7)},
      box.constants);
  // dq/dt for a small step: (exp(ω h / 2) q - q) / h → 0.5 (0, ω) q as h → 0.
  const double h = 1e-7;
  const Vec3 w = state.angular_velocity();
  const Quat turned = Quat(Eigen::AngleAxisd(w.norm() * h, w.normalized())) * state.orientation();
  const Eigen::Vector4d difference = (turned.coeffs() - state.orientation().coeffs()) / h;
  EXPECT_LT((difference - state.spin().coeffs()).norm(), 1e-6);
  // The spin of a unit quaternion is tangent to the unit sphere.
  EXPECT_NEAR(state.spin().coeffs().dot(state.orientation().coeffs()), 0.0, 1e-15);
}

TEST(RigidBody, MakeStateTurnsVelocitiesIntoMomenta) {
  const TiltedBox box;
  const Vec3 angular_velocity(1.0, 2.0, -0.5);
  const BodyState state =
      make_state(box.constants, Vec3(1, 2, 3), Vec3(0.5, 0, 0), box.orientation, angular_velocity);
  EXPECT_EQ(state.momentum(), Vec3(1.0, 0.0, 0.0));
  EXPECT_LT((state.angular_velocity() - angular_velocity).norm(), 1e-14);
  EXPECT_LT((state.angular_momentum() -
             inertia_world_matrix(box.constants, box.orientation) * angular_velocity)
                .norm(),
            1e-14);
}

TEST(RigidBody, KineticEnergyIsTranslationalPlusRotational) {
  const TiltedBox box;
  const Vec3 v(1.0, -1.0, 2.0);
  const Vec3 w(0.3, 0.2, -0.1);
  const BodyState state = make_state(box.constants, Vec3::Zero(), v, box.orientation, w);
  const double expected = 0.5 * box.constants.mass * v.squaredNorm() +
                          0.5 * w.dot(inertia_world_matrix(box.constants, box.orientation) * w);
  EXPECT_NEAR(kinetic_energy(state), expected, 1e-14 * expected);
}

TEST(RigidBody, PointVelocityIsVelocityPlusOmegaCrossOffset) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  // Spinning about z at 2 rad/s while moving along x at 1 m/s.
  const BodyState state =
      make_state(cube, Vec3(5, 0, 0), Vec3(1, 0, 0), Quat::Identity(), Vec3(0, 0, 2));
  // The point 0.5 m above the centre along y moves at v + (0,0,2) × (0,0.5,0) = (1 - 1, 0, 0).
  EXPECT_LT((point_velocity(state, Vec3(5, 0.5, 0)) - Vec3(0, 0, 0)).norm(), 1e-15);
  EXPECT_LT((point_velocity(state, Vec3(5.5, 0, 0)) - Vec3(1, 1, 0)).norm(), 1e-15);
}

TEST(RigidBody, AngleBetweenMeasuresTheRelativeRotation) {
  const Quat a(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
  const Quat b(Eigen::AngleAxisd(0.3 + 1e-9, Vec3::UnitZ()));
  EXPECT_NEAR(angle_between(a, b), 1e-9, 1e-15);
  // q and -q are the same rotation.
  Quat negated;
  negated.coeffs() = -a.coeffs();
  EXPECT_NEAR(angle_between(a, negated), 0.0, 1e-15);
  EXPECT_NEAR(angle_between(Quat::Identity(), Quat(Eigen::AngleAxisd(2.5, Vec3::UnitX()))), 2.5,
              1e-14);
}

}  // namespace
}  // namespace tumble::physics
