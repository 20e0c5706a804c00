// The impulse-contact advice matches what the contact does: a resting cube on a bouncy floor
// chatters when restitution_threshold is below the speed gravity adds in a step, and rests when
// the advice is taken.
#include "sim/contact_advice.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "sim/simulation.hpp"

namespace tumble::sim {
namespace {

constexpr double kStep = 1.0 / 60.0;  // s; gravity adds 0.1635 m/s per step

physics::BodyModel cube(double restitution) {
  physics::BodyModel model{.constants = physics::cube_constants(1.0, 1.0),
                           .forces = {physics::Gravity{}},
                           .half_size = physics::Vec3::Constant(0.5),
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
                             .half_size = physics::Vec3::Constant(0.5),
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
  return check_contact_world(c.models, c.initial, {physics::Plane{}}, settings, dt);
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

TEST(ContactWorldAdvice, SaysNothingForPenaltyContact) {
  EXPECT_TRUE(advice_for(column({1.0, 100.0, 1.0}, 1e4), 1.0 / 30.0,
                         {.method = physics::ContactMethod::penalty})
                  .empty());
}

}  // namespace
}  // namespace tumble::sim
