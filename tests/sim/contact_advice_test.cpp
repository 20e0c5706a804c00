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

}  // namespace
}  // namespace tumble::sim
