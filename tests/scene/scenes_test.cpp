// The example scenes shipped in scenes/: each must load, build and run.
#include <gtest/gtest.h>
#include <cstdio>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"

namespace tumble::scene {
namespace {

namespace fs = std::filesystem;
using physics::Vec3;

// The source tree's scenes/ (TUMBLE_SOURCE_DIR is compiled in by tests/CMakeLists.txt).
fs::path scenes_dir() {
  return fs::path(TUMBLE_SOURCE_DIR) / "scenes";
}

// Every *.toml in scenes/, sorted so that failures list in a stable order.
std::vector<fs::path> scene_files() {
  std::vector<fs::path> files;
  const fs::path dir = scenes_dir();
  if (dir.empty() || !fs::is_directory(dir)) return files;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".toml") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The scene in `path`, or a test failure carrying the loader's message.
Scene load(const fs::path& path) {
  Result<Scene> result = load_scene_file(path.string());
  if (!result) {
    ADD_FAILURE() << result.error();
    return {};
  }
  return std::move(result).value();
}

bool is_finite(const physics::BodyState& state) {
  return state.position().allFinite() && state.momentum().allFinite() &&
         state.orientation().coeffs().allFinite() && state.angular_momentum().allFinite() &&
         state.velocity().allFinite() && state.angular_velocity().allFinite() &&
         state.spin().coeffs().allFinite();
}

TEST(Scenes, SourceDirectoryIsKnown) {
  EXPECT_TRUE(fs::is_directory(scenes_dir())) << scenes_dir();
}

TEST(Scenes, TheDocumentedExamplesAreAllThere) {
  std::vector<std::string> stems;
  for (const fs::path& file : scene_files()) stems.push_back(file.stem().string());
  for (const char* expected :
       {"spinning_cube", "thrown_cube", "pushed_cube", "intermediate_axis", "cube_on_spring"}) {
    EXPECT_TRUE(std::find(stems.begin(), stems.end(), expected) != stems.end())
        << "scenes/" << expected << ".toml is missing";
  }
  EXPECT_GE(stems.size(), 5u);
}

TEST(Scenes, EverySceneLoadsAndIsNamedAfterItsFile) {
  const std::vector<fs::path> files = scene_files();
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const Scene scene = load(file);
    // The name picks the output folder; matching the file keeps outputs easy to find.
    EXPECT_EQ(scene.name, file.stem().string());
    EXPECT_FALSE(scene.bodies.empty());
  }
}

// Glenn Fiedler, "Physics in 3D": a unit cube spun up by a constant torque about x against
// angular damping, stepped with RK4 at 100 Hz.
TEST(Scenes, SpinningCubeIsTheArticleExample) {
  const Scene scene = load(scenes_dir() / "spinning_cube.toml");
  EXPECT_EQ(scene.name, "spinning_cube");
  EXPECT_EQ(scene.duration, 20.0);
  EXPECT_EQ(scene.physics.dt, 0.01);
  EXPECT_EQ(scene.physics.integrator, physics::Integrator::rk4);
  ASSERT_EQ(scene.bodies.size(), 1u);

  const BodySpec& cube = scene.bodies[0];
  EXPECT_EQ(cube.shape, Shape::cube);
  EXPECT_EQ(cube.size, Vec3::Ones());
  EXPECT_EQ(cube.mass, 1.0);
  EXPECT_EQ(cube.position, Vec3::Zero());
  EXPECT_EQ(cube.velocity, Vec3::Zero());
  EXPECT_EQ(cube.orientation.coeffs(), physics::Quat::Identity().coeffs());
  EXPECT_EQ(cube.angular_velocity, Vec3::Zero());

  ASSERT_EQ(cube.forces.size(), 2u);
  const auto* torque = std::get_if<physics::ConstantTorque>(&cube.forces[0]);
  ASSERT_NE(torque, nullptr) << "the first force is not a torque";
  EXPECT_EQ(torque->torque, Vec3(1.0, 0.0, 0.0));
  const auto* damping = std::get_if<physics::AngularDamping>(&cube.forces[1]);
  ASSERT_NE(damping, nullptr) << "the second force is not angular damping";
  EXPECT_EQ(damping->coefficient, 0.1);
}

TEST(Scenes, EverySceneRunsAHundredStepsWithFiniteStates) {
  const std::vector<fs::path> files = scene_files();
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const Scene scene = load(file);
    if (scene.bodies.empty()) continue;  // load() has already failed the test
    EXPECT_GE(step_count(scene), 100) << "the scene is shorter than the 100 steps run here";
    sim::Simulation simulation = build_simulation(scene);
    ASSERT_EQ(simulation.current().size(), scene.bodies.size());
    for (int n = 0; n < 100; ++n) simulation.step();
    EXPECT_EQ(simulation.step_count(), 100);
    for (std::size_t i = 0; i < simulation.current().size(); ++i) {
      EXPECT_TRUE(is_finite(simulation.current()[i])) << "body " << scene.bodies[i].name;
    }
  }
}

// scenes/strike.toml does what its comment says: the struck cube takes 0.9 of the striker's
// speed (restitution 0.8) and stops near x = 0.97 m, the striker within 2 cm of where it hit
// (its centre 1 m before the resting cube's), and neither tilts or turns.
TEST(Scenes, StrikeHandsOnNearlyAllTheStrikersSpeed) {
  const Scene scene = load(scenes_dir() / "strike.toml");
  ASSERT_EQ(scene.bodies.size(), 2u);
  sim::Simulation simulation = build_simulation(scene);
  while (simulation.step_count() < step_count(scene)) simulation.step();
  const physics::BodyState& striker = simulation.current()[0];
  const physics::BodyState& target = simulation.current()[1];
  EXPECT_NEAR(target.position().x(), 0.97, 0.03);   // m
  EXPECT_NEAR(striker.position().x(), -1.0, 0.02);  // m: touching the target's start
  for (const physics::BodyState* body : {&striker, &target}) {
    const double turned = 2.0 * std::acos(std::min(1.0, std::abs(body->orientation().w())));
    std::printf("[ measured ] strike: x %.4f m, y %.6f m, |v| %.2e m/s, turned %.2e rad\n",
                body->position().x(), body->position().y(), body->velocity().norm(), turned);
    EXPECT_NEAR(body->position().y(), 0.5, 1e-4);  // m: on the floor
    EXPECT_LT(body->velocity().norm(), 1e-3);      // m/s: at rest
    EXPECT_LT(turned, 1e-3);                       // rad (0.06°): not turned
  }
}

}  // namespace
}  // namespace tumble::scene
