// The block solve of normal rows (physics/normal_block.hpp): its LCP against hand-solved cases,
// and a cube's face against what symmetry says.
#include "physics/normal_block.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "physics/rigid_body.hpp"

namespace tumble::physics {
namespace {

// w = A λ + q with A = [[2, 1], [1, 2]]: q = (-1, -1) pushes both rows (λ = 1/3 each, w = 0);
// q = (-1, 1) pushes the first alone (λ = (1/2, 0), w = (0, 3/2)); q >= 0 pushes none.
TEST(BlockLcp, SolvesSmallProblemsExactly) {
  Eigen::MatrixXd a(2, 2);
  a << 2.0, 1.0, 1.0, 2.0;
  BlockLcp lcp;
  lcp.set_matrix(a);
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(2);
  ASSERT_TRUE(lcp.solve(Eigen::Vector2d(-1.0, -1.0), 1e-14, solution));
  EXPECT_NEAR(solution(0), 1.0 / 3.0, 1e-9);
  EXPECT_NEAR(solution(1), 1.0 / 3.0, 1e-9);
  solution.setZero();
  ASSERT_TRUE(lcp.solve(Eigen::Vector2d(-1.0, 1.0), 1e-14, solution));
  EXPECT_NEAR(solution(0), 0.5, 1e-9);
  EXPECT_EQ(solution(1), 0.0);
  // A wrong first guess (both pushing) is corrected by the pivoting.
  solution = Eigen::Vector2d(1.0, 1.0);
  ASSERT_TRUE(lcp.solve(Eigen::Vector2d(-1.0, 1.0), 1e-14, solution));
  EXPECT_NEAR(solution(0), 0.5, 1e-9);
  EXPECT_EQ(solution(1), 0.0);
  solution.setZero();
  ASSERT_TRUE(lcp.solve(Eigen::Vector2d(1.0, 0.5), 1e-14, solution));
  EXPECT_EQ(solution(0), 0.0);
  EXPECT_EQ(solution(1), 0.0);
}

// A falling unit cube (1 kg) landing flat on a static floor at 3 m/s, its four bottom corners
// as rows: the four are one singular block (a face has three degrees of freedom). Solved to stop,
// the cube stops without a turn, each corner taking a quarter of the 3 N s; solved to bounce at
// e = 1 (least speed 3 m/s) it leaves at 3 m/s, a quarter of 6 N s each.
TEST(NormalBlock, AFaceLandingFlatSharesTheImpulseEqually) {
  const BodyConstants constants = box_constants(1.0, Vec3::Ones());
  for (const double leave : {0.0, 3.0}) {
    std::vector<SolverBody> bodies(1);
    bodies[0].velocity = Vec3(0.0, -3.0, 0.0);
    bodies[0].inverse_mass = 1.0;
    bodies[0].isotropic = true;
    bodies[0].inverse_inertia = Mat3::Identity() * constants.inverse_inertia.x();
    bodies[0].inertia = Mat3::Identity() * constants.inertia.x();
    std::vector<ContactConstraint> points;
    for (const double x : {-0.5, 0.5}) {
      for (const double z : {-0.5, 0.5}) {
        const Vec3 arm(x, -0.5, z);
        ContactConstraint c;
        c.normal.linear = Vec3::UnitY();
        c.normal.moment_a = arm.cross(Vec3::UnitY());
        c.normal.turn_a = bodies[0].turn(c.normal.moment_a);
        c.normal.moment_b = c.normal.turn_b = Vec3::Zero();
        c.normal.mass = 0.0;
        points.push_back(c);
      }
    }
    NormalBlock block;
    const std::vector<std::uint32_t> rows = {0, 1, 2, 3};
    block.build(bodies, points, rows);
    std::vector<double> least(4, leave), impulses(4, 0.0);
    ASSERT_TRUE(block.solve(bodies, points, least, impulses));
    for (const double impulse : impulses) EXPECT_NEAR(impulse, (3.0 + leave) / 4.0, 1e-8);
    EXPECT_NEAR(bodies[0].velocity.y(), leave, 1e-8);
    EXPECT_LT(bodies[0].angular_velocity.norm(), 1e-12);
  }
}

}  // namespace
}  // namespace tumble::physics
