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

// The highest the resting cube's centre gets above 0.5 m in 3 s (m).
double largest_hop(double threshold) {
  const physics::BodyModel model = cube(0.5);
  Simulation world(
      {model},
      {physics::make_state(model.constants, physics::Vec3(0, 0.5, 0), physics::Vec3::Zero(),
                           physics::Quat::Identity(), physics::Vec3::Zero())},
      physics::Integrator::rk4, kStep, {physics::Plane{}}, {.restitution_threshold = threshold});
  double highest = 0.0;
  while (world.time() < 3.0) {
    world.step();
    highest = std::max(highest, world.current().front().position().y() - 0.5);
  }
  return highest;
}

TEST(ContactAdvice, WarnsOfAThresholdBelowTheSpeedOfOneStepAndThatCubeChatters) {
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  EXPECT_EQ(check_contact(cube(0.5), floor, {.restitution_threshold = 0.05}, kStep).size(), 1u);
  EXPECT_GT(largest_hop(0.05), 1e-4);  // it does chatter: hops of a tenth of a millimetre
}

TEST(ContactAdvice, IsQuietWhenTheThresholdIsTakenAndThatCubeRests) {
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  const double advised = 1.01 * kThresholdOverStepSpeed * 9.81 * kStep;  // just above
  EXPECT_TRUE(check_contact(cube(0.5), floor, {.restitution_threshold = advised}, kStep).empty());
  EXPECT_LT(largest_hop(advised), 1e-9);
}

TEST(ContactAdvice, IsQuietWithoutBounceOrForPenaltyContact) {
  const std::vector<physics::Plane> floor = {physics::Plane{}};
  EXPECT_TRUE(check_contact(cube(0.0), floor, {.restitution_threshold = 0.01}, kStep).empty());
  EXPECT_TRUE(check_contact(
                  cube(0.5), floor,
                  {.method = physics::ContactMethod::penalty, .restitution_threshold = 0.01}, kStep)
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

TEST(ContactWorldAdvice, NamesTwoTouchingBodiesOfAMassRatioBeyondWhatTheSolverHolds) {
  const std::vector<BodiesAdvice> advice = advice_for(column({1.0, 100.0}), kStep);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0].bodies, (std::vector<std::size_t>{0, 1}));
  EXPECT_NE(advice[0].message.find("mass ratio of 100"), std::string::npos) << advice[0].message;
  EXPECT_TRUE(advice_for(column({1.0, 40.0}), kStep).empty());
  // Apart, the same bodies do not touch and say nothing.
  Column apart = column({1.0, 100.0});
  apart.initial[1].set({.position = physics::Vec3(0.0, 3.0, 0.0)}, apart.models[1].constants);
  EXPECT_TRUE(advice_for(apart, kStep).empty());
}

TEST(ContactWorldAdvice, NamesALoadThatOneStepCannotCarryAndTheStepThatCan) {
  const std::vector<BodiesAdvice> advice = advice_for(column({1.0}, 1e4), kStep);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0].bodies, (std::vector<std::size_t>{0}));
  EXPECT_NE(advice[0].message.find("use dt <= 0.0141 s"), std::string::npos) << advice[0].message;
  EXPECT_TRUE(advice_for(column({1.0}, 5e3), kStep).empty());
}

TEST(ContactWorldAdvice, NamesAStackStepTooCoarselyToSettle) {
  const std::vector<BodiesAdvice> advice = advice_for(column({1.0, 1.0, 1.0}), 1.0 / 30.0);
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0].bodies, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_NE(advice[0].message.find("use dt <= 0.0286 s"), std::string::npos) << advice[0].message;
  EXPECT_TRUE(advice_for(column({1.0, 1.0, 1.0}), kStep).empty());
  EXPECT_TRUE(advice_for(column({1.0, 1.0}), 1.0 / 30.0).empty());  // two bodies settle
}

TEST(ContactWorldAdvice, SaysNothingForPenaltyContact) {
  EXPECT_TRUE(advice_for(column({1.0, 100.0, 1.0}, 1e4), 1.0 / 30.0,
                         {.method = physics::ContactMethod::penalty})
                  .empty());
}

}  // namespace
}  // namespace tumble::sim
