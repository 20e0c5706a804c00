// The shipped scenes of issue "Joints" where joints meet contact: Newton's cradle on strings and a
// cart driven by motors on its axles, run through the world step as `tumble simulate` runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "physics/joints.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"

namespace tumble::scene {
namespace {

Scene shipped(const std::string& name) {
  Result<Scene> loaded = load_scene_file(
      (std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes" / (name + ".toml")).string());
  EXPECT_TRUE(loaded) << loaded.error();
  return loaded ? std::move(loaded).value() : Scene{};
}

// The first ball, pulled back 30° on its 1 m string, strikes the row; over the first swing (the
// 1.3 s until the last ball has risen and come back) the last rises to within 5 % of the height
// the first fell from, and the three between stay within 1 cm of where they hung.
TEST(NewtonsCradle, TheLastBallRisesAsHighAsTheFirstFell) {
  const Scene scene = shipped("newtons_cradle");
  ASSERT_EQ(scene.bodies.size(), 5u);
  ASSERT_EQ(scene.joints.size(), 5u);
  sim::Simulation simulation = build_simulation(scene);
  const double rest = scene.bodies[4].position.y();  // the row's height (m)
  const double drop = scene.bodies[0].position.y() - rest;
  double highest = 0.0, farthest = 0.0;
  while (simulation.time() < 1.3) {
    simulation.step();
    ASSERT_FALSE(simulation.blow_up());
    const auto& now = simulation.current();
    highest = std::max(highest, now[4].position().y() - rest);
    for (std::size_t k = 1; k <= 3; ++k) {
      farthest = std::max(farthest, (now[k].position() - scene.bodies[k].position).norm());
    }
  }
  EXPECT_NEAR(highest, drop, 0.05 * drop);
  EXPECT_LT(farthest, 0.01);
}

// The cart's motors turn its wheels at 4 rad/s relative to the chassis; once up to speed (1 s) it
// rolls at 4 × 0.3 = 1.2 m/s within 1 %, every wheel's contact with the floor still (no slip), and
// the chassis level at its height.
TEST(MotorWheel, RollsAtTheMotorsSpeedTimesTheRadius) {
  const Scene scene = shipped("motor_wheel");
  sim::Simulation simulation = build_simulation(scene);
  double slowest = 1e300, fastest = 0.0, worst_slip = 0.0, worst_height = 0.0;
  while (simulation.time() < 5.0) {
    simulation.step();
    ASSERT_FALSE(simulation.blow_up());
    if (simulation.time() < 1.0) continue;
    const auto& now = simulation.current();
    slowest = std::min(slowest, now[0].velocity().x());
    fastest = std::max(fastest, now[0].velocity().x());
    worst_height = std::max(worst_height, std::abs(now[0].position().y() - 0.3));
    for (std::size_t k = 1; k <= 4; ++k) {
      const physics::Vec3 contact = now[k].position() - physics::Vec3(0.0, 0.3, 0.0);
      worst_slip = std::max(worst_slip, physics::point_velocity(now[k], contact).norm());
    }
  }
  EXPECT_NEAR(slowest, 1.2, 0.012);
  EXPECT_NEAR(fastest, 1.2, 0.012);
  EXPECT_LT(worst_slip, 0.012);
  EXPECT_LT(worst_height, 1e-3);
}

// Penalty contact scenes may hold bodies by joints too: two cubes on a hinge along their shared
// edge, dropped onto a penalty floor at 2000 steps a second, land with the hinge closed and
// nothing through the floor. They do not come to rest: the cube left on its edge slides to and
// fro at up to 0.1 m/s for as long as it is run (at dt = 0.0002 s too), where impulse contact lays
// both flat and still; a fault of penalty contact with joints not yet found, so their rest is not
// asserted here (docs/physics-and-contact.md, "Joints").
TEST(PenaltyContact, HoldsJointedBodies) {
  Result<Scene> loaded = parse_scene(R"(duration = 2.0
[physics]
dt = 0.0005
contact = "penalty"
[[planes]]
point = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
[[bodies]]
name = "left"
shape = "cube"
size = 0.2
mass = 1.0
position = [-0.1, 0.5, 0.0]
[[bodies.forces]]
kind = "gravity"
[[bodies]]
name = "right"
shape = "cube"
size = 0.2
mass = 1.0
position = [0.1, 0.6, 0.0]
orientation = [0.9961946980917455, 0.0, 0.0, 0.08715574274765817]
[[bodies.forces]]
kind = "gravity"
[[joints]]
kind = "hinge"
body_a = "right"
body_b = "left"
anchor = [0.0, 0.5, 0.0]
axis = [0.0, 0.0, 1.0]
)",
                                     "penalty_hinge.toml");
  ASSERT_TRUE(loaded) << loaded.error();
  sim::Simulation simulation = build_simulation(*loaded);
  const physics::Joint& hinge = simulation.joints().joints[0];
  double widest = 0.0;
  while (simulation.time() < 2.0) {
    simulation.step();
    ASSERT_FALSE(simulation.blow_up());
    const auto& now = simulation.current();
    widest = std::max(widest, physics::joint_opening(hinge, now));
  }
  EXPECT_LT(widest, 1e-9);
  for (const physics::BodyState& body : simulation.current()) {
    EXPECT_GT(body.position().y(), 0.09);  // a cube's half side less the springs' few mm
  }
}

}  // namespace
}  // namespace tumble::scene
