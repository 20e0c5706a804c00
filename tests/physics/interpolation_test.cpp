#include "physics/interpolation.hpp"

#include <gtest/gtest.h>

namespace tumble::physics {
namespace {

struct Bracket {
  BodyConstants constants = box_constants(2.0, Vec3(0.5, 1.0, 2.0));
  BodyState previous = make_state(constants, Vec3(1, 2, 3), Vec3(1, 0, 0),
                                  Quat(Eigen::AngleAxisd(0.2, Vec3::UnitY())), Vec3(0, 1, 0));
  BodyState current = make_state(constants, Vec3(2, 2, 2), Vec3(3, 0, -1),
                                 Quat(Eigen::AngleAxisd(0.6, Vec3::UnitY())), Vec3(0, 2, 1));
};

void expect_same_state(const BodyState& a, const BodyState& b) {
  EXPECT_EQ(a.position(), b.position());
  EXPECT_EQ(a.momentum(), b.momentum());
  EXPECT_EQ(a.orientation().coeffs(), b.orientation().coeffs());
  EXPECT_EQ(a.angular_momentum(), b.angular_momentum());
  EXPECT_EQ(a.angular_velocity(), b.angular_velocity());
}

TEST(Interpolation, AtAlphaZeroAndOneGivesTheBracketingStates) {
  const Bracket s;
  expect_same_state(interpolate(s.previous, s.current, 0.0, s.constants), s.previous);
  expect_same_state(interpolate(s.previous, s.current, 1.0, s.constants), s.current);
}

TEST(Interpolation, LerpsPositionAndMomentaAndRecomputesDerivedState) {
  const Bracket s;
  const BodyState mid = interpolate(s.previous, s.current, 0.25, s.constants);
  EXPECT_LT((mid.position() - Vec3(1.25, 2, 2.75)).norm(), 1e-15);
  EXPECT_LT((mid.velocity() - Vec3(1.5, 0, -0.25)).norm(), 1e-15);
  // Derived from the interpolated primary state, not lerped: ω = I_world⁻¹ L at the new q.
  EXPECT_LT((mid.angular_velocity() -
             apply_inverse_inertia_world(s.constants, mid.orientation(), mid.angular_momentum()))
                .norm(),
            1e-15);
}

TEST(Interpolation, SlerpMovesAtConstantAngularRate) {
  const Quat a(Eigen::AngleAxisd(0.1, Vec3(1, 2, 3).normalized()));
  const Quat b = Quat(Eigen::AngleAxisd(1.2, Vec3(0, 1, 0))) * a;
  for (const double alpha : {0.1, 0.5, 0.9}) {
    const Quat q = slerp_shortest(a, b, alpha);
    EXPECT_NEAR(angle_between(a, q), 1.2 * alpha, 1e-14);
    EXPECT_NEAR(angle_between(q, b), 1.2 * (1.0 - alpha), 1e-14);
  }
}

TEST(Interpolation, SlerpTakesTheShortestPathWhenTheDotProductIsNegative) {
  const Quat a = Quat::Identity();
  Quat b(Eigen::AngleAxisd(0.2, Vec3::UnitZ()));
  b.coeffs() = -b.coeffs();  // the same rotation, on the far side of the 4-sphere
  ASSERT_LT(a.dot(b), 0.0);
  const Quat mid = slerp_shortest(a, b, 0.5);
  EXPECT_NEAR(angle_between(mid, Quat(Eigen::AngleAxisd(0.1, Vec3::UnitZ()))), 0.0, 1e-15);
  EXPECT_NEAR(angle_between(a, mid), 0.1, 1e-15);  // not (2π - 0.2) / 2
}

TEST(Interpolation, SlerpOfNearlyEqualRotationsStaysFinite) {
  const Quat a(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
  const Quat b(Eigen::AngleAxisd(0.3 + 1e-12, Vec3::UnitX()));
  const Quat q = slerp_shortest(a, b, 0.5);
  EXPECT_TRUE(q.coeffs().allFinite());
  EXPECT_NEAR(angle_between(a, q), 0.5e-12, 1e-15);
}

}  // namespace
}  // namespace tumble::physics
