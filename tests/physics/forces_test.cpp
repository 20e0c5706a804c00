#include "physics/forces.hpp"

#include <gtest/gtest.h>

#include "physics/integrators.hpp"

namespace tumble::physics {
namespace {

constexpr double kExact = 1e-14;  // round-off only: these are closed forms evaluated directly

BodyState cube_at_rest(const BodyConstants& constants, const Vec3& position = Vec3::Zero(),
                       const Quat& orientation = Quat::Identity()) {
  return make_state(constants, position, Vec3::Zero(), orientation, Vec3::Zero());
}

TEST(Forces, TorqueOfAForceAtAPointIsOffsetCrossForce) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  const BodyState state = cube_at_rest(cube);
  const Wrench w = evaluate(ForceAtPoint{.force = Vec3(0, 0, 1), .point = Vec3(0.5, 0.5, 0.5)},
                            cube, state, 0.0);
  EXPECT_LT((w.force - Vec3(0, 0, 1)).norm(), kExact);
  // (p - x) × F, not the article's F × (p - x): pushing +z at a +x,+y corner tips it about +x.
  EXPECT_LT((w.torque - Vec3(0.5, -0.5, 0)).norm(), kExact);
}

TEST(Forces, ForceAtPointFollowsTheBodyPointAsTheBodyMovesAndTurns) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  // Turned 90° about z and moved: the body point (0.5, 0, 0) sits at world (1, 2.5, 3).
  const BodyState state =
      cube_at_rest(cube, Vec3(1, 2, 3), Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())));
  const Wrench w =
      evaluate(ForceAtPoint{.force = Vec3(1, 0, 0), .point = Vec3(0.5, 0, 0)}, cube, state, 0.0);
  EXPECT_LT((w.torque - Vec3(0, 0, -0.5)).norm(), kExact);  // (0, 0.5, 0) × (1, 0, 0)
}

TEST(Forces, ForceAtPointActsOnlyFromStartUntilEnd) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  const BodyState state = cube_at_rest(cube);
  const ForceLaw push =
      ForceAtPoint{.force = Vec3(1, 0, 0), .point = Vec3(0, 0.5, 0), .start = 1.0, .end = 2.0};
  EXPECT_EQ(evaluate(push, cube, state, 0.999).force, Vec3::Zero());
  EXPECT_EQ(evaluate(push, cube, state, 1.0).force, Vec3(1, 0, 0));
  EXPECT_EQ(evaluate(push, cube, state, 1.999).force, Vec3(1, 0, 0));
  EXPECT_EQ(evaluate(push, cube, state, 2.0).force, Vec3::Zero());
}

// A symmetric body at rest, pushed off-centre: at the first instant the linear acceleration is
// F/m, the angular acceleration I⁻¹ (r × F), and the pushed point accelerates at F/m + α × r.
TEST(Forces, OffCentrePushOnASymmetricBodyAtTheFirstInstant) {
  const BodyConstants cube = cube_constants(2.0, 1.0);  // I = 1/3 kg m²
  const BodyModel model{
      .constants = cube,
      .forces = {ForceAtPoint{.force = Vec3(0, 0, 3), .point = Vec3(0.5, 0.5, 0.5)}}};
  const BodyState start = cube_at_rest(cube);
  const Wrench w = total_wrench(model.forces, cube, start, 0.0);
  EXPECT_LT((w.torque - Vec3(1.5, -1.5, 0)).norm(), kExact);

  const double dt = 1e-6;
  const BodyState after = step(Integrator::rk4, model, start, 0.0, dt);
  const Vec3 angular_acceleration(4.5, -4.5, 0);
  const Vec3 point_acceleration(-2.25, -2.25, 6.0);  // (0, 0, 1.5) + α × (0.5, 0.5, 0.5)
  const Vec3 point = body_point_to_world(after, Vec3(0.5, 0.5, 0.5));
  // The body turns by O(dt) in the step, so the finite differences match to O(dt) relative.
  EXPECT_LT((after.angular_velocity() / dt - angular_acceleration).norm(), 1e-5);
  EXPECT_LT((after.velocity() / dt - Vec3(0, 0, 1.5)).norm(), 1e-9);
  EXPECT_LT((point_velocity(after, point) / dt - point_acceleration).norm(), 1e-5);
}

TEST(Forces, GravityIsMassTimesAcceleration) {
  const BodyConstants cube = cube_constants(3.0, 1.0);
  const Wrench w =
      evaluate(Gravity{.acceleration = Vec3(0, -9.81, 0)}, cube, cube_at_rest(cube), 0);
  EXPECT_LT((w.force - Vec3(0, -29.43, 0)).norm(), kExact);
  EXPECT_EQ(w.torque, Vec3::Zero());
}

TEST(Forces, DampingOpposesVelocityAndAngularVelocity) {
  const BodyConstants cube = cube_constants(2.0, 1.0);
  const BodyState state =
      make_state(cube, Vec3::Zero(), Vec3(1, 2, 0), Quat::Identity(), Vec3(0, 0, 3));
  EXPECT_LT((evaluate(LinearDamping{.coefficient = 0.5}, cube, state, 0).force - Vec3(-0.5, -1, 0))
                .norm(),
            kExact);
  EXPECT_LT((evaluate(AngularDamping{.coefficient = 0.1}, cube, state, 0).torque - Vec3(0, 0, -0.3))
                .norm(),
            kExact);
}

TEST(Forces, SpringPullsTheAttachmentTowardsTheAnchor) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  const Spring spring{.anchor = Vec3(0, 3, 0),
                      .attachment = Vec3(0, 0.5, 0),
                      .stiffness = 10.0,
                      .damping = 2.0,
                      .rest_length = 1.0};
  // Length 2.5, stretched by 1.5: 15 N up; no torque, the line passes through the centre.
  const Wrench at_rest = evaluate(spring, cube, cube_at_rest(cube), 0);
  EXPECT_LT((at_rest.force - Vec3(0, 15, 0)).norm(), kExact);
  EXPECT_LT(at_rest.torque.norm(), kExact);
  // Moving towards the anchor at 1 m/s: damping takes 2 N off. Spinning about z moves the
  // attachment sideways only, which the damper does not see.
  const BodyState moving =
      make_state(cube, Vec3::Zero(), Vec3(0, 1, 0), Quat::Identity(), Vec3(0, 0, 2));
  EXPECT_LT((evaluate(spring, cube, moving, 0).force - Vec3(0, 13, 0)).norm(), kExact);
}

TEST(Forces, SpringAtAnOffCentreAttachmentTurnsTheBody) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  const Spring spring{.anchor = Vec3(0.5, 3, 0),
                      .attachment = Vec3(0.5, 0, 0),
                      .stiffness = 10.0,
                      .rest_length = 1.0};
  const Wrench w = evaluate(spring, cube, cube_at_rest(cube), 0);
  EXPECT_LT((w.force - Vec3(0, 20, 0)).norm(), kExact);
  EXPECT_LT((w.torque - Vec3(0, 0, 10)).norm(), kExact);  // (0.5, 0, 0) × (0, 20, 0)
}

TEST(Forces, TotalWrenchSumsOnlyTheListedLaws) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  const BodyState state = cube_at_rest(cube);
  EXPECT_EQ(total_wrench({}, cube, state, 0).force, Vec3::Zero());
  EXPECT_EQ(total_wrench({}, cube, state, 0).torque, Vec3::Zero());
  const Wrench sum =
      total_wrench({ConstantForce{.force = Vec3(1, 0, 0)}, ConstantTorque{.torque = Vec3(0, 2, 0)},
                    ConstantForce{.force = Vec3(0, 0, 3)}},
                   cube, state, 0);
  EXPECT_EQ(sum.force, Vec3(1, 0, 3));
  EXPECT_EQ(sum.torque, Vec3(0, 2, 0));
}

}  // namespace
}  // namespace tumble::physics
