// The twist lever arm of a flat patch against the closed forms of uniform pressure
// (../shared/research/contact-hard.md §5).
#include "physics/patch_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace tumble::physics {
namespace {

// The rectangle of half-extents a, b: r̄ = [d + (a²/2b) ln((b+d)/a) + (b²/2a) ln((a+d)/b)] / 3.
double rectangle_arm(double a, double b) {
  const double d = std::hypot(a, b);
  return (d + a * a / (2 * b) * std::log((b + d) / a) + b * b / (2 * a) * std::log((a + d) / b)) /
         3.0;
}

std::vector<Vec3> rectangle(double a, double b, const Vec3& centre) {
  return {centre + Vec3(a, 0, b), centre + Vec3(-a, 0, -b), centre + Vec3(-a, 0, b),
          centre + Vec3(a, 0, -b)};
}

TEST(PatchTwistArm, ASquareFaceHasTheMeanDistanceOfItsArea) {
  const std::vector<Vec3> face = rectangle(0.5, 0.5, Vec3(2, 0, -1));
  const double expected = (std::sqrt(2.0) + std::log(1.0 + std::sqrt(2.0))) / 6.0;  // 0.3826
  EXPECT_NEAR(patch_twist_arm(face, Vec3::UnitY(), Vec3(2, 0, -1)), expected, 1e-14);
  EXPECT_NEAR(expected, 0.3826, 1e-4);
}

TEST(PatchTwistArm, RectanglesMatchTheClosedForm) {
  for (const auto& [a, b] : {std::pair{1.0, 0.25}, std::pair{2.0, 0.3}, std::pair{0.025, 1.5}}) {
    EXPECT_NEAR(patch_twist_arm(rectangle(a, b, Vec3::Zero()), Vec3::UnitY(), Vec3::Zero()),
                rectangle_arm(a, b), 1e-13 * std::hypot(a, b))
        << a << " x " << b;
  }
}

TEST(PatchTwistArm, AnOctagonIsWithinItsInscribedAndCircumscribedDisks) {
  std::vector<Vec3> octagon;
  for (int k = 0; k < 8; ++k) {
    const double angle = 2 * std::numbers::pi * k / 8 + 0.1;
    octagon.push_back(Vec3(std::cos(angle), 0.0, std::sin(angle)));
  }
  const double arm = patch_twist_arm(octagon, Vec3::UnitY(), Vec3::Zero());
  EXPECT_LT(arm, 2.0 / 3.0);                                   // the circumscribed disk's
  EXPECT_GT(arm, 2.0 / 3.0 * std::cos(std::numbers::pi / 8));  // the inscribed disk's
}

TEST(PatchTwistArm, PointsAlongALineHaveAQuarterOfItsLength) {
  const std::vector<Vec3> edge = {Vec3(-0.5, 0, 0.5), Vec3(0.5, 0, 0.5)};
  EXPECT_NEAR(patch_twist_arm(edge, Vec3::UnitY(), Vec3(0, 0, 0.5)), 0.25, 1e-15);
}

TEST(PatchTwistArm, OnePointHasNone) {
  const std::vector<Vec3> corner = {Vec3(1, 2, 3)};
  EXPECT_EQ(patch_twist_arm(corner, Vec3::UnitY(), Vec3(1, 2, 3)), 0.0);
}

TEST(PatchTwistArm, TheOrderOfThePointsAndATiltedNormalDoNotMatter) {
  const Quat tilt(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  std::vector<Vec3> face;
  for (const Vec3& p : rectangle(0.4, 0.1, Vec3::Zero())) face.push_back(tilt * p);
  const double arm = patch_twist_arm(face, tilt * Vec3::UnitY(), Vec3::Zero());
  EXPECT_NEAR(arm, rectangle_arm(0.4, 0.1), 1e-14);
  std::swap(face[0], face[3]);
  EXPECT_NEAR(patch_twist_arm(face, tilt * Vec3::UnitY(), Vec3::Zero()), arm, 1e-15);
}

}  // namespace
}  // namespace tumble::physics
