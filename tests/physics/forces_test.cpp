#include "physics/forces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "physics/integrators.hpp"
#include "support/closed_forms.hpp"

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

// Keys at 1 s and 3 s, from (0, 1, 0) to (4, 3, 0): 2 m/s along x and 1 m/s along y, then still
// from 3 s to 4 s, ending at (4, 3, 2) after 2 m/s along z.
const Spring kKeyedSpring{.anchor_keys = {{.time = 1.0, .anchor = Vec3(0, 1, 0)},
                                          {.time = 3.0, .anchor = Vec3(4, 3, 0)},
                                          {.time = 3.5, .anchor = Vec3(4, 3, 0)},
                                          {.time = 4.5, .anchor = Vec3(4, 3, 2)}},
                          .stiffness = 1.0};

TEST(Forces, AnchorRestsAtTheFirstKeyBeforeItAndAtTheLastAfterIt) {
  for (const double t : {-1e300, -5.0, 0.0, 0.999999}) {
    EXPECT_EQ(anchor_motion(kKeyedSpring, t).position, Vec3(0, 1, 0)) << t;
    EXPECT_EQ(anchor_motion(kKeyedSpring, t).velocity, Vec3::Zero()) << t;
  }
  for (const double t : {4.5, 4.500001, 100.0, 1e300}) {
    EXPECT_EQ(anchor_motion(kKeyedSpring, t).position, Vec3(4, 3, 2)) << t;
    EXPECT_EQ(anchor_motion(kKeyedSpring, t).velocity, Vec3::Zero()) << t;
  }
}

// At a key's own time the anchor is exactly there, moving as the segment after the key does.
TEST(Forces, AnchorIsAtEachKeyAtItsTime) {
  EXPECT_EQ(anchor_motion(kKeyedSpring, 1.0).position, Vec3(0, 1, 0));
  EXPECT_EQ(anchor_motion(kKeyedSpring, 1.0).velocity, Vec3(2, 1, 0));
  EXPECT_EQ(anchor_motion(kKeyedSpring, 3.0).position, Vec3(4, 3, 0));
  EXPECT_EQ(anchor_motion(kKeyedSpring, 3.0).velocity, Vec3::Zero());
  EXPECT_EQ(anchor_motion(kKeyedSpring, 3.5).position, Vec3(4, 3, 0));
  EXPECT_EQ(anchor_motion(kKeyedSpring, 3.5).velocity, Vec3(0, 0, 2));
}

TEST(Forces, AnchorMovesInAStraightLineAtConstantSpeedBetweenKeys) {
  EXPECT_LT((anchor_motion(kKeyedSpring, 1.5).position - Vec3(1, 1.5, 0)).norm(), kExact);
  EXPECT_LT((anchor_motion(kKeyedSpring, 2.0).position - Vec3(2, 2, 0)).norm(), kExact);
  EXPECT_LT((anchor_motion(kKeyedSpring, 2.999).position - Vec3(3.998, 2.999, 0)).norm(), kExact);
  EXPECT_LT((anchor_motion(kKeyedSpring, 2.0).velocity - Vec3(2, 1, 0)).norm(), kExact);
  EXPECT_EQ(anchor_motion(kKeyedSpring, 3.25).position, Vec3(4, 3, 0));
  EXPECT_EQ(anchor_motion(kKeyedSpring, 3.25).velocity, Vec3::Zero());
  EXPECT_LT((anchor_motion(kKeyedSpring, 4.0).position - Vec3(4, 3, 1)).norm(), kExact);
  EXPECT_LT((anchor_motion(kKeyedSpring, 4.0).velocity - Vec3(0, 0, 2)).norm(), kExact);
}

TEST(Forces, AnchorKeysAWholeDoubleRangeApartStayFinite) {
  const double big = std::numeric_limits<double>::max();
  const Spring spring{.anchor_keys = {{.time = -big, .anchor = Vec3(0, 0, 0)},
                                      {.time = big, .anchor = Vec3(2, 0, 0)}}};
  EXPECT_EQ(anchor_motion(spring, 0.0).position, Vec3(1, 0, 0));  // half way, in time
  EXPECT_EQ(anchor_motion(spring, 0.0).velocity, Vec3::Zero());   // 2 m over 3.6e308 s
  EXPECT_EQ(anchor_motion(spring, 0.5 * big).position, Vec3(1.5, 0, 0));
}

TEST(Forces, FixedAnchorAndASingleKeyAreTheSameAnchorAtRest) {
  const Spring fixed{.anchor = Vec3(1, 2, 3)};
  const Spring one_key{.anchor_keys = {{.time = 2.0, .anchor = Vec3(1, 2, 3)}}};
  for (const double t : {-1.0, 2.0, 7.0}) {
    EXPECT_EQ(anchor_motion(fixed, t).position, Vec3(1, 2, 3));
    EXPECT_EQ(anchor_motion(fixed, t).velocity, Vec3::Zero());
    EXPECT_EQ(anchor_motion(one_key, t).position, Vec3(1, 2, 3));
    EXPECT_EQ(anchor_motion(one_key, t).velocity, Vec3::Zero());
  }
}

TEST(Forces, SpringActsOnlyFromStartUntilEnd) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  const BodyState state = cube_at_rest(cube);
  const ForceLaw spring =
      Spring{.anchor = Vec3(0, 2, 0), .stiffness = 3.0, .start = 1.0, .end = 2.0};
  EXPECT_EQ(evaluate(spring, cube, state, 0.999).force, Vec3::Zero());
  EXPECT_EQ(evaluate(spring, cube, state, 1.0).force, Vec3(0, 6, 0));
  EXPECT_EQ(evaluate(spring, cube, state, 1.999).force, Vec3(0, 6, 0));
  EXPECT_EQ(evaluate(spring, cube, state, 2.0).force, Vec3::Zero());
  EXPECT_EQ(evaluate(spring, cube, state, 2.0).torque, Vec3::Zero());
}

// The damper sees the attachment's velocity relative to the moving anchor (forces.hpp says why).
TEST(Forces, SpringDampsTheVelocityRelativeToAMovingAnchor) {
  const BodyConstants cube = cube_constants(1.0, 1.0);
  // At t = 2 the anchor is at (2, 2, 0), 2 m above the centre, moving at (2, 1, 0).
  Spring spring = kKeyedSpring;
  spring.stiffness = 10.0;
  spring.damping = 3.0;
  const BodyState still =
      make_state(cube, Vec3(2, 0, 0), Vec3::Zero(), Quat::Identity(), Vec3::Zero());
  // Stretched 2 m: 20 N up; the anchor moves away (up) at 1 m/s: 3 N more.
  EXPECT_LT((evaluate(spring, cube, still, 2.0).force - Vec3(0, 23, 0)).norm(), kExact);
  // Moving with the anchor, the damper has nothing to resist: the stiffness alone.
  const BodyState along =
      make_state(cube, Vec3(2, 0, 0), Vec3(2, 1, 0), Quat::Identity(), Vec3::Zero());
  EXPECT_LT((evaluate(spring, cube, along, 2.0).force - Vec3(0, 20, 0)).norm(), kExact);
}

struct DragCase {
  Integrator integrator;
  double tolerance;  // m, on the position at every step
};

class Drag : public ::testing::TestWithParam<DragCase> {};

// Against the closed form of the driven critically damped oscillator (support/closed_forms.hpp) at
// dt = 1/1024 s (ω dt = 0.02); the lag peaks at V / (e ω) = 9.2 mm. The anchor's velocity jumps
// at the two keys, and a method that reads the law at the end of a step ending on a key reads it
// after the jump: a momentum error of w c V dt once per key (w the weight of that stage: 1/6 for
// rk4, 1/2 and 0.68 for the last half kick of splitting and splitting4), which the oscillator turns
// into a position error of at most w c V dt / (e m ω): 6.0e-5, 1.8e-4 and 2.4e-4 m, as measured.
// The tolerances are twice that; euler and symplectic_euler are first order in ω dt (measured
// 4.6e-4 and 3.5e-4 m).
TEST_P(Drag, BodyFollowsASlowlyMovingAnchorAsTheDrivenOscillatorDoes) {
  const testing::CriticallyDampedDrag drag;
  const BodyModel model = drag.model();
  BodyState state = drag.at_rest();
  const double dt = 1.0 / 1024.0;
  const double tolerance = GetParam().tolerance;
  for (int n = 0; n < 3 * 1024; ++n) {
    state = step(GetParam().integrator, model, state, n * dt, dt);
    const double t = (n + 1) * dt;
    ASSERT_NEAR(state.position().x(), drag.position_at(t), tolerance) << t;
    ASSERT_LT(state.position().tail<2>().norm(), kExact) << t;
    if (t == drag.stop - dt) {
      // Dragged at V for 2 s, the body has caught up with the anchor: the damper resists only
      // motion relative to it. Fiedler's damping of v_P alone would leave it 2V/ω = 50 mm behind.
      EXPECT_NEAR(state.position().x(), drag.anchor_at(t), tolerance);
      EXPECT_NEAR(state.velocity().x(), drag.speed, drag.frequency * tolerance);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, Drag,
                         ::testing::Values(DragCase{Integrator::euler, 1e-3},
                                           DragCase{Integrator::symplectic_euler, 1e-3},
                                           DragCase{Integrator::rk4, 1.2e-4},
                                           DragCase{Integrator::splitting, 3.6e-4},
                                           DragCase{Integrator::splitting4, 4.8e-4}),
                         [](const auto& info) {
                           return std::string(integrator_name(info.param.integrator));
                         });

// Until the last step before start (whose final stage, at t + dt = start, feels it) the stretched
// spring pulls nothing; from end on it has let go, and the body flies on with the momentum it
// had: exactly, since every force evaluation of those steps is at or past end.
TEST(Forces, SpringPullsOnlyFromStartAndLetsGoAtEnd) {
  const BodyConstants cube = cube_constants(2.0, 1.0);
  const BodyModel model{
      .constants = cube,
      .forces = {Spring{
          .anchor = Vec3(1, 0, 0), .stiffness = 50.0, .damping = 5.0, .start = 0.25, .end = 0.5}}};
  for (const Integrator integrator : {Integrator::rk4, Integrator::splitting}) {
    SCOPED_TRACE(std::string(integrator_name(integrator)));
    const double dt = 1.0 / 64.0;
    BodyState state = cube_at_rest(cube);
    Vec3 released = Vec3::Zero();
    for (int n = 0; n < 64; ++n) {
      const double t = n * dt;
      state = step(integrator, model, state, t, dt);
      if (t + dt < 0.25) {
        EXPECT_EQ(state.momentum(), Vec3::Zero()) << t;
      }
      if (t + dt == 0.5) released = state.momentum();
      if (t >= 0.5) {
        EXPECT_EQ(state.momentum(), released) << t;
      }
    }
    EXPECT_GT(released.x(), 0.1);  // it was pulled, and keeps going
  }
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
