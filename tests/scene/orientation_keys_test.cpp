// A body's `rotation` and `euler_degrees` give the quaternion they name (docs/scene-reference.md
// says the convention: euler_degrees turns about the world's x, then y, then z).
#include "scene/orientation_keys.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "support/scene_text.hpp"

namespace tumble::scene {
namespace {

using physics::Quat;
using physics::Vec3;
using testing::parse_valid;

constexpr double kDegree = std::numbers::pi / 180.0;  // rad

// The orientation the loader gives a unit cube whose table adds `keys`.
Quat orientation_of(const std::string& keys) {
  const Scene scene = parse_valid(testing::cube_scene(1.0) + keys);
  return scene.bodies.empty() ? Quat(0.0, 0.0, 0.0, 0.0) : scene.bodies.front().orientation;
}

void expect_within(const Quat& got, const Quat& want, double tolerance) {
  EXPECT_NEAR(got.w(), want.w(), tolerance);
  EXPECT_NEAR(got.x(), want.x(), tolerance);
  EXPECT_NEAR(got.y(), want.y(), tolerance);
  EXPECT_NEAR(got.z(), want.z(), tolerance);
}

TEST(OrientationKeys, RotationOf45DegreesAboutYIsCosAndSinOfHalfTheAngle) {
  const Quat want(std::cos(22.5 * kDegree), 0.0, std::sin(22.5 * kDegree), 0.0);
  expect_within(orientation_of("rotation = { axis = [0, 1, 0], degrees = 45 }\n"), want, 1e-15);
  // The axis is made unit: its length says nothing.
  expect_within(orientation_of("rotation = { axis = [0.0, 2.5, 0.0], degrees = 45.0 }\n"), want,
                1e-15);
}

TEST(OrientationKeys, RotationAboutATiltedAxisIsItsHandComputedQuaternion) {
  // 120° about (1, 1, 1)/√3: (cos 60°, sin 60° / √3 each) = (1/2, 1/2, 1/2, 1/2).
  expect_within(orientation_of("rotation = { axis = [1, 1, 1], degrees = 120 }\n"),
                Quat(0.5, 0.5, 0.5, 0.5), 1e-15);
}

TEST(OrientationKeys, EulerDegreesAreTheProductOfTurnsAboutZThenYThenXFromTheLeft) {
  const double x = 30.0, y = -50.0, z = 110.0;  // degrees
  const Quat qx(std::cos(x / 2 * kDegree), std::sin(x / 2 * kDegree), 0.0, 0.0);
  const Quat qy(std::cos(y / 2 * kDegree), 0.0, std::sin(y / 2 * kDegree), 0.0);
  const Quat qz(std::cos(z / 2 * kDegree), 0.0, 0.0, std::sin(z / 2 * kDegree));
  expect_within(orientation_of("euler_degrees = [30, -50, 110]\n"), qz * qy * qx, 1e-15);
}

TEST(OrientationKeys, EulerDegreesTurnAboutTheWorldsXFirstThenItsY) {
  // 90° about x takes body y to world z, then 90° about world y takes it to world x; body x
  // stays on x through the first turn and goes to -z in the second.
  const Quat q = orientation_of("euler_degrees = [90, 90, 0]\n");
  EXPECT_LT((q * Vec3::UnitY() - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_LT((q * Vec3::UnitX() + Vec3::UnitZ()).norm(), 1e-15);
}

TEST(OrientationKeys, EachOfTheThreeKeysAloneOrNoneIsAccepted) {
  EXPECT_EQ(orientation_of("").coeffs(), Quat::Identity().coeffs());
  EXPECT_EQ(orientation_of("orientation = [0.0, 1.0, 0.0, 0.0]\n").coeffs(),
            Quat(0.0, 1.0, 0.0, 0.0).coeffs());
  EXPECT_EQ(orientation_of("euler_degrees = [0, 0, 0]\n").coeffs(), Quat::Identity().coeffs());
}

TEST(OrientationKeys, TwoOfTheKeysAreRefusedNamingBoth) {
  EXPECT_EQ(testing::error_of(testing::cube_scene(1.0) +
                              "euler_degrees = [1, 2, 3]\norientation = [1, 0, 0, 0]\n"),
            "test.toml:6:17: bodies[0].euler_degrees: give one of orientation, rotation and "
            "euler_degrees (orientation is given too)");
}

}  // namespace
}  // namespace tumble::scene
