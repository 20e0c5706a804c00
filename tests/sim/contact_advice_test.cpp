// The impulse-contact advice matches what the contact does: a resting cube on a bouncy floor
// chatters when restitution_threshold is below the speed gravity adds in a step, and rests when
// the advice is taken.
#include "sim/contact_advice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "sim/simulation.hpp"
#include "sim/stability.hpp"

namespace tumble::sim {
namespace {

constexpr double kStep = 1.0 / 60.0;  // s; gravity adds 0.1635 m/s per step

physics::BodyModel cube(double restitution) {
  physics::BodyModel model{.constants = physics::cube_constants(1.0, 1.0),
                           .forces = {physics::Gravity{}},
                           .shape = physics::box_shape(physics::Vec3::Constant(0.5)),
                           .material = {.restitution = restitution, .friction = 0.5}};
  return model;
}

// The highest the resting cube's centre gets above 0.5 m in 3 s (m), stepped with euler (whose
// steps are not held to their energy, physics/contact_island.hpp) unless said.
double largest_hop(double threshold, physics::Integrator integrator = physics::Integrator::euler) {
  const physics::BodyModel model = cube(0.5);
  Simulation world(
      {model},
      {physics::make_state(model.constants, physics::Vec3(0, 0.5, 0), physics::Vec3::Zero(),
                           physics::Quat::Identity(), physics::Vec3::Zero())},
      integrator, kStep, {physics::Plane{}}, {.restitution_threshold = threshold});
  double highest = 0.0;
  while (world.time() < 3.0) {
    world.step();
    highest = std::max(highest, world.current().front().position().y() - 0.5);
  }
  return highest;
}

TEST(ContactAdvice, WarnsOfAThresholdBelowTheSpeedOfOneStepAndThatCubeChatters) {
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  EXPECT_EQ(check_contact(cube(0.5), floor, {.restitution_threshold = 0.05},
                          physics::Integrator::euler, kStep)
                .size(),
            1u);
  EXPECT_GT(largest_hop(0.05), 1e-4);  // it does chatter: hops of a tenth of a millimetre
}

TEST(ContactAdvice, IsQuietWhenTheThresholdIsTakenAndThatCubeRests) {
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  const double advised = 1.01 * kThresholdOverStepSpeed * 9.81 * kStep;  // just above
  EXPECT_TRUE(check_contact(cube(0.5), floor, {.restitution_threshold = advised},
                            physics::Integrator::euler, kStep)
                  .empty());
  EXPECT_LT(largest_hop(advised), 1e-9);
}

// A passive body's steps with rk4 are held to their energy: the bounce a low threshold gives a
// resting cube would raise it, so it rests, and nothing is said.
TEST(ContactAdvice, IsQuietWhenTheStepsAreHeldToTheirEnergyAndThatCubeRests) {
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  EXPECT_TRUE(check_contact(cube(0.5), floor, {.restitution_threshold = 0.05},
                            physics::Integrator::rk4, kStep)
                  .empty());
  EXPECT_LT(largest_hop(0.05, physics::Integrator::rk4), 1e-9);
}

TEST(ContactAdvice, IsQuietWithoutBounceOrForPenaltyContact) {
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  EXPECT_TRUE(check_contact(cube(0.0), floor, {.restitution_threshold = 0.01},
                            physics::Integrator::rk4, kStep)
                  .empty());
  EXPECT_TRUE(
      check_contact(cube(0.5), floor,
                    {.method = physics::ContactMethod::penalty, .restitution_threshold = 0.01},
                    physics::Integrator::rk4, kStep)
          .empty());
}

// A column of unit cubes of these masses (kg) on the floor, the first at the bottom; `push` (N)
// presses the top one down.
struct Column {
  std::vector<physics::BodyModel> models;
  std::vector<physics::BodyState> initial;
};

Column column(const std::vector<double>& masses, double push = 0.0) {
  Column out;
  for (std::size_t i = 0; i < masses.size(); ++i) {
    physics::BodyModel model{.constants = physics::cube_constants(masses[i], 1.0),
                             .forces = {physics::Gravity{}},
                             .shape = physics::box_shape(physics::Vec3::Constant(0.5)),
                             .material = {}};
    if (push > 0.0 && i + 1 == masses.size()) {
      model.forces.push_back(physics::ConstantForce{physics::Vec3(0.0, -push, 0.0)});
    }
    out.initial.push_back(physics::make_state(
        model.constants, physics::Vec3(0.0, 0.5 + static_cast<double>(i), 0.0),
        physics::Vec3::Zero(), physics::Quat::Identity(), physics::Vec3::Zero()));
    out.models.push_back(std::move(model));
  }
  return out;
}

std::vector<BodiesAdvice> advice_for(const Column& c, double dt,
                                     physics::ContactSettings settings = {}) {
  return check_contact_world(c.models, c.initial, {physics::Plane{}}, settings,
                             physics::Integrator::rk4, dt);
}

// Thirteen 1 kg cubes under one of `top` kg: 14 bodies on a floor, 56 contact points, beyond the
// block solve's 48.
std::vector<double> tall_column(double top) {
  std::vector<double> masses(13, 1.0);
  masses.push_back(top);
  return masses;
}

TEST(ContactWorldAdvice, NamesTouchingBodiesOfAMassRatioBeyondWhatTheSolverHoldsInAGroupThatLarge) {
  const std::vector<BodiesAdvice> advice = advice_for(column(tall_column(100.0)), kStep);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0].bodies, (std::vector<std::size_t>{12, 13}));
  EXPECT_NE(advice[0].message.find("mass ratio of 100"), std::string::npos) << advice[0].message;
  EXPECT_TRUE(advice_for(column(tall_column(5.0)), kStep).empty());
  // Two bodies are solved as one block, at any ratio (contact_hard: 1000:1 holds within 1e-13 m).
  EXPECT_TRUE(advice_for(column({1.0, 1000.0}), kStep).empty());
  // Apart, the same bodies do not touch and say nothing.
  Column apart = column(tall_column(100.0));
  apart.initial[13].set({.position = physics::Vec3(0.0, 20.0, 0.0)}, apart.models[13].constants);
  EXPECT_TRUE(advice_for(apart, kStep).empty());
}

TEST(ContactWorldAdvice, NamesALoadThatOneStepCannotCarryAndTheStepThatCan) {
  const std::vector<BodiesAdvice> advice = advice_for(column(tall_column(1.0), 1e4), kStep);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0].bodies, (std::vector<std::size_t>{13}));
  EXPECT_NE(advice[0].message.find("use dt <= 0.0141 s"), std::string::npos) << advice[0].message;
  EXPECT_TRUE(advice_for(column(tall_column(1.0), 5e3), kStep).empty());
  // A cube alone on the floor holds any load (contact_hard: 1e6 N within 3e-5 m).
  EXPECT_TRUE(advice_for(column({1.0}, 1e6), kStep).empty());
}

TEST(ContactWorldAdvice, NamesAStackStepTooCoarselyToSettle) {
  const std::vector<BodiesAdvice> advice = advice_for(column(tall_column(1.0)), 1.0 / 30.0);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0].bodies.size(), 14u);
  EXPECT_NE(advice[0].message.find("use dt <= 0.0286 s"), std::string::npos) << advice[0].message;
  EXPECT_TRUE(advice_for(column(tall_column(1.0)), kStep).empty());
  // A stack of three is one block and settles even at dt = 1/10 s (contact_hard).
  EXPECT_TRUE(advice_for(column({1.0, 1.0, 1.0}), 0.1).empty());
}

// With no gravity nothing rests: a bouncing cube is told that a threshold above zero takes the
// bounce of its slow impacts.
TEST(ContactAdvice, TellsABouncingBodyWithNoGravityToBounceAtAnySpeed) {
  physics::BodyModel weightless = cube(1.0);
  weightless.forces.clear();
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  const std::vector<std::string> advice =
      check_contact(weightless, floor, {}, physics::Integrator::rk4, kStep);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_NE(advice[0].find("restitution_threshold = 0"), std::string::npos) << advice[0];
  EXPECT_TRUE(check_contact(weightless, floor, {.restitution_threshold = 0.0},
                            physics::Integrator::rk4, kStep)
                  .empty());
  EXPECT_TRUE(check_contact(cube(1.0), floor, {}, physics::Integrator::rk4, kStep)
                  .empty());  // under gravity: quiet
}

// ---- Penalty contact between bodies (check_penalty_pairs) ----------------------------------

const physics::ContactSettings kPenalty = {.method = physics::ContactMethod::penalty};

// The column with penalty contact on the floor as well, as the scene builder gives it.
Column penalty_column(const std::vector<double>& masses, const physics::ContactSettings& springs) {
  Column out = column(masses);
  for (physics::BodyModel& model : out.models) {
    model = physics::with_penalty_contact(std::move(model), {physics::Plane{}}, springs.stiffness,
                                          springs.damping);
  }
  return out;
}

std::vector<BodiesAdvice> pair_advice(const Column& c, physics::Integrator integrator, double dt,
                                      const physics::ContactSettings& springs = kPenalty) {
  return check_contact_world(c.models, c.initial, {physics::Plane{}}, springs, integrator, dt);
}

// The smallest step any warning on the column suggests: each body's (check_step: its springs on
// the floor) and the pairs' (s).
double advised_step(const Column& c, physics::Integrator integrator, double dt) {
  double out = dt;
  for (std::size_t i = 0; i < c.models.size(); ++i) {
    for (const StepWarning& w : check_step(c.models[i], c.initial[i], integrator, dt, 10.0)) {
      if (w.suggested_dt) out = std::min(out, *w.suggested_dt);
    }
  }
  for (const BodiesAdvice& advice : pair_advice(c, integrator, dt)) {
    if (advice.suggested_dt) out = std::min(out, *advice.suggested_dt);
  }
  return out;
}

// The farthest the top body gets from where it started over 10 s (m).
double top_drift(const Column& c, physics::Integrator integrator, double dt,
                 const physics::ContactSettings& springs) {
  Simulation world(c.models, c.initial, integrator, dt, {}, springs);
  double farthest = 0.0;
  while (world.time() < 10.0 && !world.blow_up()) {
    world.step();
    farthest = std::max(farthest,
                        (world.current().back().position() - c.initial.back().position()).norm());
  }
  return world.blow_up() ? std::numeric_limits<double>::infinity() : farthest;
}

// At 1/60 s every integrator is far beyond the springs' limit (k = 1e5 N/m: ω_n up to 1265
// rad/s by Gershgorin's bound, 1140 exactly); at the step tumble check suggests, a column of
// three unit cubes stands 10 s with its top within 1 cm (it sinks 1.5 m g / k = 0.15 mm).
TEST(PenaltyPairAdvice, AColumnOfThreeStandsTenSecondsAtTheStepCheckSuggests) {
  const Column c = penalty_column({1.0, 1.0, 1.0}, kPenalty);
  for (const physics::Integrator integrator : physics::kAllIntegrators) {
    SCOPED_TRACE(std::string(physics::integrator_name(integrator)));
    const std::vector<BodiesAdvice> coarse = pair_advice(c, integrator, kStep);
    ASSERT_EQ(coarse.size(), 1u);
    EXPECT_EQ(coarse[0].bodies, (std::vector<std::size_t>{0, 1, 2}));
    ASSERT_TRUE(coarse[0].suggested_dt.has_value()) << coarse[0].message;
    const double dt = advised_step(c, integrator, kStep);
    EXPECT_TRUE(pair_advice(c, integrator, dt).empty());
    EXPECT_LT(top_drift(c, integrator, dt, kPenalty), 0.01);
  }
  // Beyond the limit the column does not stand: the warning is not idle.
  EXPECT_GT(top_drift(c, physics::Integrator::rk4, 1.0 / 240.0, kPenalty), 0.01);
}

// At 1/120 s, rk4: the stiffness and damping check suggests for this step (ζ kept) hold the
// column within 1 cm (it sinks 3.2 mm into the softer springs).
TEST(PenaltyPairAdvice, AColumnOfThreeStandsAtTheStiffnessCheckSuggestsForItsStep) {
  const double dt = 1.0 / 120.0;
  const std::vector<BodiesAdvice> advice =
      pair_advice(penalty_column({1.0, 1.0, 1.0}, kPenalty), physics::Integrator::rk4, dt);
  ASSERT_EQ(advice.size(), 1u);
  ASSERT_TRUE(advice[0].suggested_stiffness && advice[0].suggested_damping) << advice[0].message;
  const physics::ContactSettings softer = {.method = physics::ContactMethod::penalty,
                                           .stiffness = *advice[0].suggested_stiffness,
                                           .damping = *advice[0].suggested_damping};
  const Column c = penalty_column({1.0, 1.0, 1.0}, softer);
  EXPECT_TRUE(pair_advice(c, physics::Integrator::rk4, dt, softer).empty());
  EXPECT_LT(top_drift(c, physics::Integrator::rk4, dt, softer), 0.01);
}

// Soft springs hold a column stable but deep: 500 N/m per point sinks a column of three unit
// cubes 1.5 m g / k = 29 mm; the advice gives the stiffness that sinks it 1 cm.
TEST(PenaltyPairAdvice, NamesAColumnThatSinksIntoSoftSprings) {
  const physics::ContactSettings soft = {
      .method = physics::ContactMethod::penalty, .stiffness = 500.0, .damping = 10.0};
  const std::vector<BodiesAdvice> advice = pair_advice(
      penalty_column({1.0, 1.0, 1.0}, soft), physics::Integrator::rk4, 1.0 / 1000.0, soft);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_NE(advice[0].message.find("sink about 29.4 mm"), std::string::npos) << advice[0].message;
  ASSERT_TRUE(advice[0].suggested_stiffness.has_value());
  EXPECT_NEAR(*advice[0].suggested_stiffness, 1.5 * 9.81 / 0.01, 1e-9);
}

// Bodies apart at the start may meet: the two lightest are named, at 4k (1/m₁ + 1/m₂).
TEST(PenaltyPairAdvice, NamesTheTwoLightestBodiesThatMayMeet) {
  Column c = penalty_column({3.0, 1.0, 2.0}, kPenalty);
  for (std::size_t i = 0; i < c.initial.size(); ++i) {
    c.initial[i].set({.position = physics::Vec3(3.0 * static_cast<double>(i), 5.0, 0.0)},
                     c.models[i].constants);
  }
  const std::vector<BodiesAdvice> advice = pair_advice(c, physics::Integrator::rk4, kStep);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0].bodies, (std::vector<std::size_t>{1, 2}));
  EXPECT_NE(advice[0].message.find("ω_n = 774.6 rad/s"), std::string::npos) << advice[0].message;
  // Bodies that do not collide, or a step within the limit: nothing.
  physics::ContactSettings apart = kPenalty;
  apart.collide_bodies = false;
  EXPECT_TRUE(pair_advice(c, physics::Integrator::rk4, kStep, apart).empty());
  EXPECT_TRUE(pair_advice(c, physics::Integrator::rk4, 1e-4).empty());
}

// A unit cube at `height` (m) above the origin with the laws `forces`.
physics::BodyModel cube_with(std::vector<physics::ForceLaw> forces, bool is_static = false) {
  physics::BodyModel model = cube(0.0);
  model.forces = std::move(forces);
  model.is_static = is_static;
  return model;
}

physics::BodyState at_height(double height) {
  return physics::make_state(physics::cube_constants(1.0, 1.0), physics::Vec3(0.0, height, 0.0),
                             physics::Vec3::Zero(), physics::Quat::Identity(),
                             physics::Vec3::Zero());
}

TEST(WeightlessAboveFloor, NamesTheMovingBodiesWithNoGravityThatStartAboveAPlaneFacingUp) {
  const physics::Plane slope{.normal = physics::Vec3(0.6, 0.8, 0.0), .offset = 0.0};
  const std::vector<physics::BodyModel> models = {
      cube_with({}), cube_with({physics::Gravity{}}),
      cube_with({physics::ConstantForce{.force = physics::Vec3(0.0, -1.0, 0.0)}}),
      cube_with({physics::Gravity{.acceleration = physics::Vec3::Zero()}})};
  const std::vector<physics::BodyState> initial = {at_height(2.0), at_height(2.0), at_height(2.0),
                                                   at_height(2.0)};
  // A force that is not gravity is no gravity; nor is a gravity law of 0.
  const std::vector<std::size_t> expected = {0, 2, 3};
  EXPECT_EQ(weightless_above_floor(models, initial, {physics::Plane{}}), expected);
  EXPECT_EQ(weightless_above_floor(models, initial, {slope}), expected);
}

TEST(WeightlessAboveFloor, IsQuietWithGravityForStaticBodiesBelowAFloorOrBesideWalls) {
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  EXPECT_TRUE(
      weightless_above_floor({cube_with({physics::Gravity{}})}, {at_height(2.0)}, floor).empty());
  EXPECT_TRUE(weightless_above_floor({cube_with({}, true)}, {at_height(2.0)}, floor).empty());
  EXPECT_TRUE(weightless_above_floor({cube_with({})}, {at_height(-2.0)}, floor).empty());
  const std::vector<physics::Plane> walls = {
      {.normal = physics::Vec3::UnitX(), .offset = -3.0},
      {.normal = physics::Vec3(0.0, -1.0, 0.0), .offset = -5.0}};  // and a ceiling
  EXPECT_TRUE(weightless_above_floor({cube_with({})}, {at_height(2.0)}, walls).empty());
  EXPECT_TRUE(weightless_above_floor({cube_with({})}, {at_height(2.0)}, {}).empty());
}

}  // namespace
}  // namespace tumble::sim
