#include "scene/scene_loader.hpp"
#include "support/scene_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <variant>

namespace tumble::scene {
namespace {

using physics::Vec3;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using testing::parse_valid;

// The force law at `index` as kind T; a test failure (and a default T) if it is another kind.
template <typename T>
T force_as(const BodySpec& body, std::size_t index) {
  if (index >= body.forces.size()) {
    ADD_FAILURE() << "body " << body.name << " has no force " << index;
    return {};
  }
  const T* law = std::get_if<T>(&body.forces[index]);
  if (!law) {
    ADD_FAILURE() << "force " << index << " of body " << body.name << " is another kind (index "
                  << body.forces[index].index() << ")";
    return {};
  }
  return *law;
}

// Every key of the schema, every force kind, integers where numbers are expected, and a
// quaternion that is only nearly unit.
constexpr const char* kFullScene = R"(name = "full_scene"
duration = 5

[physics]
dt = 0.002
integrator = "symplectic_euler"

[[bodies]]
name = "lid"
shape = "box"
size = [0.5, 1, 2.0]
mass = 3
position = [1.0, 2.0, -3.0]
velocity = [0.5, -0.25, 4]
orientation = [0.7071, 0.7071, 0.0, 0.0]
angular_velocity = [0.1, 0.2, 0.3]
color = "#ff8000"

[[bodies.forces]]
kind = "gravity"

[[bodies.forces]]
kind = "gravity"
acceleration = [0.0, -1.62, 0.0]

[[bodies.forces]]
kind = "force"
force = [1.0, 2.0, 3.0]

[[bodies.forces]]
kind = "torque"
torque = [0.0, 0.0, -1.5]

[[bodies.forces]]
kind = "linear_damping"
coefficient = 0.3

[[bodies.forces]]
kind = "angular_damping"
coefficient = 0

[[bodies.forces]]
kind = "force_at_point"
force = [0.0, 10.0, 0.0]
point = [0.25, -0.5, 1.0]
start = 1
end = 1.5

[[bodies.forces]]
kind = "force_at_point"
force = [1.0, 0.0, 0.0]
point = [0.0, 0.0, 0.5]

[[bodies.forces]]
kind = "spring"
anchor = [0.0, 5.0, 0.0]
attachment = [0.25, 0.5, 1.0]
stiffness = 40
damping = 1.5
rest_length = 2.0

[[bodies.forces]]
kind = "spring"
anchor = [1.0, 1.0, 1.0]
stiffness = 10.0

[[bodies]]
shape = "cube"
size = 2
mass = 0.5

[render]
width = 640
height = 360
fps = 30
msaa = 8
background = [0.1, 0.2, 0.3]
shadows = false
backend = "egl"
egl_device = 1

[camera]
position = [6.0, 4.0, 8.0]
look_at = [0.0, 1.0, 0.0]
up = [0, 0, 1]
fov_degrees = 55
follow = "lid"

[light]
direction = [1.0, -2.0, 0.5]
color = [1.0, 0.9, 0.8]
ambient = 0.25

[ground]
enabled = false
height = -2.5
color = "#808080"
grid_spacing = 0.5

[output]
directory = "renders/full"
frames = true
video = false
crf = 0
preset = "slow"
)";

TEST(SceneLoader, FullSceneGivesExactlyTheWrittenValues) {
  const Scene scene = parse_valid(kFullScene);
  EXPECT_EQ(scene.name, "full_scene");
  EXPECT_EQ(scene.source_path, "test.toml");
  EXPECT_EQ(scene.duration, 5.0);
  EXPECT_EQ(scene.physics.dt, 0.002);
  EXPECT_EQ(scene.physics.integrator, physics::Integrator::symplectic_euler);
  ASSERT_EQ(scene.bodies.size(), 2u);

  const BodySpec& lid = scene.bodies[0];
  EXPECT_EQ(lid.name, "lid");
  EXPECT_EQ(lid.shape, Shape::box);
  EXPECT_EQ(lid.size, Vec3(0.5, 1.0, 2.0));
  EXPECT_EQ(lid.mass, 3.0);
  EXPECT_EQ(lid.position, Vec3(1.0, 2.0, -3.0));
  EXPECT_EQ(lid.velocity, Vec3(0.5, -0.25, 4.0));
  EXPECT_EQ(lid.angular_velocity, Vec3(0.1, 0.2, 0.3));
  ASSERT_EQ(lid.forces.size(), 10u);

  EXPECT_EQ(force_as<physics::Gravity>(lid, 0).acceleration, Vec3(0.0, -9.81, 0.0));
  EXPECT_EQ(force_as<physics::Gravity>(lid, 1).acceleration, Vec3(0.0, -1.62, 0.0));
  EXPECT_EQ(force_as<physics::ConstantForce>(lid, 2).force, Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(force_as<physics::ConstantTorque>(lid, 3).torque, Vec3(0.0, 0.0, -1.5));
  EXPECT_EQ(force_as<physics::LinearDamping>(lid, 4).coefficient, 0.3);
  EXPECT_EQ(force_as<physics::AngularDamping>(lid, 5).coefficient, 0.0);

  const auto timed_push = force_as<physics::ForceAtPoint>(lid, 6);
  EXPECT_EQ(timed_push.force, Vec3(0.0, 10.0, 0.0));
  EXPECT_EQ(timed_push.point, Vec3(0.25, -0.5, 1.0));
  EXPECT_EQ(timed_push.start, 1.0);
  EXPECT_EQ(timed_push.end, 1.5);

  const auto endless_push = force_as<physics::ForceAtPoint>(lid, 7);
  EXPECT_EQ(endless_push.force, Vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(endless_push.point, Vec3(0.0, 0.0, 0.5));
  EXPECT_EQ(endless_push.start, -kInfinity);
  EXPECT_EQ(endless_push.end, kInfinity);

  const auto spring = force_as<physics::Spring>(lid, 8);
  EXPECT_EQ(spring.anchor, Vec3(0.0, 5.0, 0.0));
  EXPECT_EQ(spring.attachment, Vec3(0.25, 0.5, 1.0));
  EXPECT_EQ(spring.stiffness, 40.0);
  EXPECT_EQ(spring.damping, 1.5);
  EXPECT_EQ(spring.rest_length, 2.0);

  EXPECT_TRUE(spring.anchor_keys.empty());
  EXPECT_EQ(spring.start, -kInfinity);
  EXPECT_EQ(spring.end, kInfinity);

  const auto bare_spring = force_as<physics::Spring>(lid, 9);
  EXPECT_EQ(bare_spring.anchor, Vec3(1.0, 1.0, 1.0));
  EXPECT_EQ(bare_spring.attachment, Vec3::Zero());
  EXPECT_EQ(bare_spring.stiffness, 10.0);
  EXPECT_EQ(bare_spring.damping, 0.0);
  EXPECT_EQ(bare_spring.rest_length, 0.0);

  const BodySpec& second = scene.bodies[1];
  EXPECT_EQ(second.name, "body1");  // bodies are named by their index unless named
  EXPECT_EQ(second.shape, Shape::cube);
  EXPECT_EQ(second.size, Vec3(2.0, 2.0, 2.0));  // a cube's one side, on every axis
  EXPECT_EQ(second.mass, 0.5);
  EXPECT_EQ(second.position, Vec3::Zero());
  EXPECT_EQ(second.velocity, Vec3::Zero());
  EXPECT_EQ(second.orientation.coeffs(), physics::Quat::Identity().coeffs());
  EXPECT_EQ(second.angular_velocity, Vec3::Zero());
  EXPECT_TRUE(second.forces.empty());
}

// Anchor keys as an inline array and as [[bodies.forces.anchor_keys]] tables, and a spring's
// start and end.
TEST(SceneLoader, SpringReadsAnchorKeysStartAndEnd) {
  const Scene scene = parse_valid(R"(duration = 2.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
anchor_keys = [{ time = 0.0, anchor = [0, 1, 0] }, { time = 1.5, anchor = [3, 2, 0] }]
stiffness = 400
damping = 40
start = 0.25
end = 1.75
[[bodies.forces]]
kind = "spring"
stiffness = 1
end = 1
[[bodies.forces.anchor_keys]]
time = -1
anchor = [1, 2, 3]
)");
  ASSERT_EQ(scene.bodies.size(), 1u);
  const auto dragged = force_as<physics::Spring>(scene.bodies[0], 0);
  ASSERT_EQ(dragged.anchor_keys.size(), 2u);
  EXPECT_EQ(dragged.anchor_keys[0].time, 0.0);
  EXPECT_EQ(dragged.anchor_keys[0].anchor, Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(dragged.anchor_keys[1].time, 1.5);
  EXPECT_EQ(dragged.anchor_keys[1].anchor, Vec3(3.0, 2.0, 0.0));
  EXPECT_EQ(dragged.anchor, Vec3::Zero());  // unused with keys
  EXPECT_EQ(dragged.stiffness, 400.0);
  EXPECT_EQ(dragged.damping, 40.0);
  EXPECT_EQ(dragged.start, 0.25);
  EXPECT_EQ(dragged.end, 1.75);

  const auto held = force_as<physics::Spring>(scene.bodies[0], 1);
  ASSERT_EQ(held.anchor_keys.size(), 1u);
  EXPECT_EQ(held.anchor_keys[0].time, -1.0);
  EXPECT_EQ(held.anchor_keys[0].anchor, Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(held.start, -kInfinity);
  EXPECT_EQ(held.end, 1.0);
}

TEST(SceneLoader, NearlyUnitOrientationIsNormalised) {
  const Scene scene = parse_valid(kFullScene);
  ASSERT_FALSE(scene.bodies.empty());
  const physics::Quat& q = scene.bodies[0].orientation;
  // Written as [0.7071, 0.7071, 0, 0], whose length is 0.99999; stored as exactly unit.
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  EXPECT_NEAR(q.w(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(q.x(), std::sqrt(0.5), 1e-15);
  EXPECT_EQ(q.y(), 0.0);
  EXPECT_EQ(q.z(), 0.0);
}

TEST(SceneLoader, FullSceneGivesExactlyTheWrittenRenderingValues) {
  const Scene scene = parse_valid(kFullScene);
  EXPECT_EQ(scene.render.width, 640);
  EXPECT_EQ(scene.render.height, 360);
  EXPECT_EQ(scene.fps, 30);
  EXPECT_EQ(scene.render.msaa, 8);
  EXPECT_EQ(scene.render.background, common::Color(0.1, 0.2, 0.3));
  EXPECT_FALSE(scene.render.shadows);
  EXPECT_EQ(scene.render.backend, common::Backend::egl);
  EXPECT_EQ(scene.render.egl_device, 1);

  ASSERT_TRUE(scene.camera.position.has_value());
  EXPECT_EQ(*scene.camera.position, Vec3(6.0, 4.0, 8.0));
  ASSERT_TRUE(scene.camera.look_at.has_value());
  EXPECT_EQ(*scene.camera.look_at, Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(scene.camera.up, Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(scene.camera.fov_degrees, 55.0);
  EXPECT_EQ(scene.camera.follow, "lid");

  EXPECT_EQ(scene.render.light.direction, Vec3(1.0, -2.0, 0.5));
  EXPECT_EQ(scene.render.light.color, common::Color(1.0, 0.9, 0.8));
  EXPECT_EQ(scene.render.light.ambient, 0.25);

  EXPECT_FALSE(scene.render.ground.enabled);
  ASSERT_TRUE(scene.ground_height.has_value());
  EXPECT_EQ(*scene.ground_height, -2.5);
  EXPECT_EQ(scene.render.ground.color, common::Color(128 / 255.0, 128 / 255.0, 128 / 255.0));
  EXPECT_EQ(scene.render.ground.grid_spacing, 0.5);

  EXPECT_EQ(scene.output.directory, "renders/full");
  EXPECT_TRUE(scene.output.frames);
  EXPECT_FALSE(scene.output.video);
  EXPECT_EQ(scene.output.crf, 0);
  EXPECT_EQ(scene.output.preset, "slow");

  ASSERT_FALSE(scene.bodies.empty());
  // "#ff8000": each pair of hex digits is a component out of 255.
  EXPECT_EQ(scene.bodies[0].color, common::Color(1.0, 128 / 255.0, 0.0));
}

TEST(SceneLoader, MinimalSceneTakesEveryDefault) {
  const Scene scene = parse_valid(R"(duration = 2.5
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)");
  EXPECT_EQ(scene.name, "test");  // the stem of "test.toml"
  EXPECT_EQ(scene.duration, 2.5);
  EXPECT_EQ(scene.physics.dt, 0.01);
  EXPECT_EQ(scene.physics.integrator, physics::Integrator::rk4);
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.bodies[0].name, "body0");
  EXPECT_EQ(scene.bodies[0].size, Vec3::Ones());
  EXPECT_EQ(scene.bodies[0].orientation.coeffs(), physics::Quat::Identity().coeffs());
}

TEST(SceneLoader, SceneWithoutRenderingTablesTakesEveryRenderingDefault) {
  const Scene scene = parse_valid(R"(name = "quiet"
duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
position = [2.0, 0.0, 0.0]
)");
  EXPECT_EQ(scene.render.width, 1280);
  EXPECT_EQ(scene.render.height, 720);
  EXPECT_EQ(scene.fps, 60);
  EXPECT_EQ(scene.render.msaa, common::kEdgeFilter);  // no msaa given: one sample, filtered
  EXPECT_TRUE(scene.render.shadows);
  EXPECT_EQ(scene.render.backend, common::Backend::automatic);
  EXPECT_EQ(scene.render.egl_device, common::kAutomaticEglDevice);

  // Left out, the camera is placed later to frame the whole motion.
  EXPECT_FALSE(scene.camera.position.has_value());
  EXPECT_FALSE(scene.camera.look_at.has_value());
  EXPECT_EQ(scene.camera.up, Vec3::UnitY());
  EXPECT_EQ(scene.camera.fov_degrees, 40.0);
  EXPECT_TRUE(scene.camera.follow.empty());

  // Left out, the ground is placed later below the whole motion.
  EXPECT_FALSE(scene.ground_height.has_value());
  EXPECT_TRUE(scene.render.ground.enabled);

  EXPECT_EQ(scene.output.directory, "quiet");  // the scene's name
  EXPECT_TRUE(scene.output.frames);
  EXPECT_TRUE(scene.output.video);
  EXPECT_EQ(scene.output.crf, 20);
  EXPECT_EQ(scene.output.preset, "veryfast");

  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_NE(scene.bodies[0].color, scene.bodies[1].color);  // from a palette, by index
}

TEST(SceneLoader, RenderingLimitsIncludeTheirEnds) {
  const Scene low = parse_valid(R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
width = 16
height = 16
fps = 1
msaa = 1
[light]
ambient = 0
[ground]
grid_spacing = 0
[output]
crf = 0
)");
  EXPECT_EQ(low.render.width, 16);
  EXPECT_EQ(low.render.height, 16);
  EXPECT_EQ(low.fps, 1);
  EXPECT_EQ(low.render.msaa, 1);
  EXPECT_EQ(low.render.light.ambient, 0.0);
  EXPECT_EQ(low.render.ground.grid_spacing, 0.0);  // no grid
  EXPECT_EQ(low.output.crf, 0);

  const Scene high = parse_valid(R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
width = 8192
height = 4320
fps = 240
msaa = 16
[light]
ambient = 1
[output]
crf = 51
)");
  EXPECT_EQ(high.render.width, 8192);
  EXPECT_EQ(high.render.height, 4320);  // exactly kMaxPixels
  EXPECT_EQ(high.fps, 240);
  EXPECT_EQ(high.render.msaa, 16);
  EXPECT_EQ(high.render.light.ambient, 1.0);
  EXPECT_EQ(high.output.crf, 51);
}

TEST(SceneLoader, PhysicsTableMayOmitEitherSetting) {
  const Scene only_integrator = parse_valid(R"(duration = 1.0
[physics]
integrator = "euler"
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)");
  EXPECT_EQ(only_integrator.physics.dt, 0.01);
  EXPECT_EQ(only_integrator.physics.integrator, physics::Integrator::euler);

  const Scene only_dt = parse_valid(R"(duration = 1.0
[physics]
dt = 0.001
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)");
  EXPECT_EQ(only_dt.physics.dt, 0.001);
  EXPECT_EQ(only_dt.physics.integrator, physics::Integrator::rk4);
}

// Bodies collide by default; collide_bodies = false (or a body's collide = false) lets bodies
// pass through each other as before contact between bodies existed, so overlapping is allowed.
TEST(SceneLoader, CollideKeysTurnContactBetweenBodiesOff) {
  const std::string two_cubes = R"(
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
position = [0.5, 0.0, 0.0]
)";
  const Scene off = parse_valid("duration = 1.0\n[physics]\ncollide_bodies = false\n" + two_cubes);
  EXPECT_FALSE(off.physics.contact.collide_bodies);
  const Scene one = parse_valid("duration = 1.0\n" + two_cubes + "collide = false\n");
  EXPECT_TRUE(one.physics.contact.collide_bodies);
  EXPECT_TRUE(one.bodies[0].collide);
  EXPECT_FALSE(one.bodies[1].collide);
  EXPECT_TRUE(
      std::holds_alternative<SceneError>(parse_scene("duration = 1.0\n" + two_cubes, "t.toml")));
}

// Still islands sleep unless the scene says sleep = false.
TEST(SceneLoader, SleepIsOnUnlessTheSceneTurnsItOff) {
  const std::string cube = "[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n";
  EXPECT_TRUE(parse_valid("duration = 1.0\n" + cube).physics.contact.sleep);
  EXPECT_FALSE(
      parse_valid("duration = 1.0\n[physics]\nsleep = false\n" + cube).physics.contact.sleep);
}

TEST(SceneLoader, LargeIntegersAreReadAsTheNearestDouble) {
  const SceneOrError result = parse_scene(R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1
mass = 9007199254740993
)",
                                          "test.toml");
  ASSERT_TRUE(std::holds_alternative<Scene>(result)) << std::get<SceneError>(result).message;
  EXPECT_EQ(std::get<Scene>(result).bodies[0].mass, 9007199254740992.0);
}

// Odd sizes are fine without a video (H.264 yuv420p needs even ones); frames can be turned off.
TEST(SceneLoader, OutputSwitchesAreReadAndOddSizesNeedNoVideo) {
  const std::string body = "duration = 1.0\n[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n";
  const Scene odd = parse_valid(body + "[render]\nwidth = 65\n[output]\nvideo = false\n");
  EXPECT_EQ(odd.render.width, 65);
  EXPECT_FALSE(odd.output.video);
  const Scene video_only = parse_valid(body + "[output]\nframes = false\n");
  EXPECT_FALSE(video_only.output.frames);
  EXPECT_TRUE(video_only.output.video);
}

TEST(SceneLoader, DefaultNameIsTheStemOfTheGivenPath) {
  SceneOrError result = parse_scene(R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
                                    "some/folder/falling_lid.toml");
  ASSERT_TRUE(std::holds_alternative<Scene>(result));
  EXPECT_EQ(std::get<Scene>(result).name, "falling_lid");
  EXPECT_EQ(std::get<Scene>(result).source_path, "some/folder/falling_lid.toml");
}

// Every key of [[planes]], the body materials and the penalty settings, as written.
TEST(SceneLoader, PlanesMaterialsAndContactSettingsAreReadAsWritten) {
  const Scene scene = parse_valid(R"(duration = 1.0
[physics]
contact = "penalty"
contact_stiffness = 2e4
contact_damping = 0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
position = [0.0, 0.5, 0.0]
restitution = 1
friction = 0
[[planes]]
name = "floor"
point = [1, 0, -2]
normal = [0, 2, 0]
restitution = 0.25
friction = 1.5
visible = false
size = [4, 6.5]
)");
  EXPECT_EQ(scene.physics.contact.method, physics::ContactMethod::penalty);
  EXPECT_EQ(scene.physics.contact.stiffness, 2e4);
  EXPECT_EQ(scene.physics.contact.damping, 0.0);
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.bodies[0].material.restitution, 1.0);
  EXPECT_EQ(scene.bodies[0].material.friction, 0.0);
  ASSERT_EQ(scene.planes.size(), 1u);
  const PlaneSpec& floor = scene.planes[0];
  EXPECT_EQ(floor.name, "floor");
  EXPECT_EQ(floor.point, Vec3(1.0, 0.0, -2.0));
  EXPECT_EQ(floor.normal, Vec3::UnitY());  // [0, 2, 0] made unit
  EXPECT_EQ(floor.material.restitution, 0.25);
  EXPECT_EQ(floor.material.friction, 1.5);
  EXPECT_FALSE(floor.visible);
  EXPECT_EQ(floor.size[0], 4.0);
  EXPECT_EQ(floor.size[1], 6.5);
}

TEST(SceneLoader, PlanesMaterialsAndContactTakeTheirDefaults) {
  const Scene scene = parse_valid(R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
position = [0.0, 3.0, 0.0]
[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
[[planes]]
point = [-5, 0, 0]
normal = [1, 0, 0]
)");
  const physics::ContactSettings defaults;
  EXPECT_EQ(scene.physics.contact.method, physics::ContactMethod::impulse);
  EXPECT_EQ(scene.physics.contact.restitution_threshold, defaults.restitution_threshold);
  EXPECT_EQ(scene.physics.contact.stiffness, defaults.stiffness);
  EXPECT_EQ(scene.physics.contact.damping, defaults.damping);
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.bodies[0].material.restitution, 0.0);
  EXPECT_EQ(scene.bodies[0].material.friction, 0.5);
  ASSERT_EQ(scene.planes.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const PlaneSpec& plane = scene.planes[i];
    EXPECT_EQ(plane.name, "plane" + std::to_string(i));  // named by index, like bodies
    EXPECT_EQ(plane.material.restitution, 0.0);
    EXPECT_EQ(plane.material.friction, 0.5);
    EXPECT_TRUE(plane.visible);
    EXPECT_EQ(plane.size[0], 20.0);
    EXPECT_EQ(plane.size[1], 20.0);
  }
  EXPECT_EQ(scene.planes[1].normal, Vec3::UnitX());
}

TEST(SceneLoader, ImpulseContactReadsItsRestitutionThreshold) {
  const Scene scene = parse_valid(R"(duration = 1.0
[physics]
contact = "impulse"
restitution_threshold = 0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)");
  EXPECT_EQ(scene.physics.contact.method, physics::ContactMethod::impulse);
  EXPECT_EQ(scene.physics.contact.restitution_threshold, 0.0);
  EXPECT_TRUE(scene.planes.empty());
}

// Unit length whatever the written length, from denormal to near the largest double.
TEST(SceneLoader, PlaneNormalIsStoredAsUnit) {
  const auto normal_of = [](const std::string& written) {
    const Scene scene = parse_valid(
        "duration = 1.0\n[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\nposition = [9, "
        "9, 9]\n[[planes]]\npoint = [0, 0, 0]\nnormal = " +
        written + "\n");
    return scene.planes.empty() ? Vec3(Vec3::Zero()) : scene.planes[0].normal;
  };
  const Vec3 slope = normal_of("[0, 3, 4]");
  EXPECT_NEAR(slope.x(), 0.0, 1e-16);
  EXPECT_NEAR(slope.y(), 0.6, 1e-15);
  EXPECT_NEAR(slope.z(), 0.8, 1e-15);
  EXPECT_EQ(normal_of("[1e-310, 0, 0]"), Vec3::UnitX());
  const Vec3 huge = normal_of("[1.7e308, 1.7e308, 0]");
  EXPECT_NEAR(huge.x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(huge.y(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(huge.norm(), 1.0, 1e-15);
}

// Resting on a plane is the usual start: a face on the floor, an edge on a slope within the
// 1e-9 m written decimals can miss by, and a corner just touching a wall all load.
TEST(SceneLoader, ABodyMayStartTouchingAPlane) {
  const Scene scene = parse_valid(R"(duration = 1.0
[[bodies]]
name = "resting"
shape = "cube"
size = 1.0
mass = 1.0
position = [0.0, 0.5, 0.0]
[[bodies]]
name = "on_edge"
shape = "cube"
size = 1.0
mass = 1.0
position = [3.0, 0.7071067811, 0.0]
orientation = [0.9238795325112867, 0.0, 0.0, 0.3826834323650898]
[[planes]]
name = "floor"
point = [0, 0, 0]
normal = [0, 1, 0]
[[planes]]
name = "wall"
point = [-0.5, 0, 0]
normal = [1, 0, 0]
)");
  EXPECT_EQ(scene.planes.size(), 2u);
}

// The error message for `text`, or a test failure if it loads.
std::string message_of(const std::string& text, const std::string& path = "test.toml") {
  SceneOrError result = parse_scene(text, path);
  if (std::holds_alternative<Scene>(result)) {
    ADD_FAILURE() << "loaded, but should not have";
    return {};
  }
  return std::get<SceneError>(result).message;
}

TEST(SceneLoader, AFileNameThatCannotBeTheSceneNameIsExplained) {
  const std::string message = message_of(R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
                                         "renders/my scene.toml");
  EXPECT_EQ(
      message.rfind("renders/my scene.toml:1:1: name: missing, and the file name \"my scene\" "
                    "cannot stand in for it: must be 1-100 letters",
                    0),
      0u)
      << message;
}

// A key of 100 000 characters: the message names it in 80 bytes and says it was cut.
TEST(SceneLoader, AHugeUnknownKeyIsCutShortInTheMessage) {
  const std::string message =
      message_of("duration = 1.0\n" + std::string(100000, 'k') +
                 " = 1\n[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n");
  EXPECT_EQ(message.rfind("test.toml:2:1: " + std::string(80, 'k') + "...: unknown key", 0), 0u)
      << message.substr(0, 200);
  EXPECT_LT(message.size(), 400u);
}

TEST(SceneLoader, ControlCharactersFromTheFileAreEscapedInMessages) {
  const std::string message = message_of(R"(duration = 1.0
[[bodies]]
shape = "cu\u001b[2Jbe\n"
size = 1.0
mass = 1.0
)");
  EXPECT_NE(message.find("unknown shape \"cu\\x1b[2Jbe\\n\""), std::string::npos) << message;
}

// toml++ recurses once per part of a dotted key or table header and has no limit of its own
// there: 40 000 parts overflowed the stack. Refused before parsing, with the key's position.
TEST(SceneLoader, DeeplyDottedKeysAreRefusedBeforeParsing) {
  std::string parts = "a";
  for (int i = 1; i < 40000; ++i) parts += ".a";
  for (const std::string& text :
       {"duration = 1.0\n[" + parts + "]\n", "duration = 1.0\n  " + parts + " = 1\n",
        "duration = 1.0\n[[" + parts + "]]\n"}) {
    const std::string message = message_of(text);
    EXPECT_EQ(message.rfind("test.toml:2:", 0), 0u) << message.substr(0, 200);
    EXPECT_NE(message.find("a dotted key of more than 32 parts"), std::string::npos)
        << message.substr(0, 200);
  }
}

// A scene the loader must reject, and what its message must say. Lines and columns are
// 1-based and were counted by hand from `text`; a value's column is where the value starts.
struct BadScene {
  const char* name;      // the test's name
  const char* text;      // the whole file
  const char* location;  // "test.toml:LINE:COL"
  const char* key;       // the qualified key the message names
  const char* reason;    // a phrase of the explanation
};

std::ostream& operator<<(std::ostream& out, const BadScene& bad) {
  return out << bad.name;
}

class SceneLoaderRejects : public ::testing::TestWithParam<BadScene> {};

TEST_P(SceneLoaderRejects, WithLocationKeyAndReason) {
  const BadScene& bad = GetParam();
  const SceneOrError result = parse_scene(bad.text, "test.toml");
  ASSERT_TRUE(std::holds_alternative<SceneError>(result)) << "accepted:\n" << bad.text;
  const std::string& message = std::get<SceneError>(result).message;
  // "path:line:column: key: what is wrong"
  const std::string prefix = std::string(bad.location) + ": " + bad.key + ": ";
  EXPECT_EQ(message.substr(0, prefix.size()), prefix) << message;
  EXPECT_NE(message.find(bad.reason, prefix.size()), std::string::npos)
      << "expected \"" << bad.reason << "\" in: " << message;
}

const BadScene kBadScenes[] = {
    {"TomlSyntaxError", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = = 1.0
)",
     "test.toml:5:8", "TOML syntax error", "value"},
    {"UnterminatedString", R"(duration = 1.0
[[bodies]]
shape = "cube
size = 1.0
mass = 1.0
)",
     "test.toml:3:14", "TOML syntax error", "string"},
    {"UnknownTopLevelKey", R"(duration = 1.0
colour = "red"
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:2:1", "colour", "unknown key"},
    {"UnknownBodyKeyTypoBesideTheRealKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
mas = 1.0
)",
     "test.toml:6:1", "bodies[0].mas", "unknown key"},
    {"UnknownBodyKeyTypoOfAnOptionalKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
postion = [0.0, 0.0, 0.0]
)",
     "test.toml:6:1", "bodies[0].postion", "allowed here"},
    {"UnknownBodyKeyInInlineTable", R"(duration = 1.0
bodies = [{shape = "cube", size = 1.0, mass = 1.0, mas = 2}]
)",
     "test.toml:2:52", "bodies[0].mas", "unknown key"},
    {"UnknownForceKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "torque"
torque = [1.0, 0.0, 0.0]
strength = 2.0
)",
     "test.toml:9:1", "bodies[0].forces[0].strength", "unknown key"},
    {"UnknownPhysicsKey", R"(duration = 1.0
[physics]
step = 0.01
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:1", "physics.step", "unknown key"},
    {"MissingDuration", R"([[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:1:1", "duration", "missing"},
    {"MissingBodyMass", R"(duration = 1.0

[[bodies]]
shape = "cube"
size = 1.0
)",
     "test.toml:3:1", "bodies[0].mass", "missing"},
    {"MissingShape", R"(duration = 1.0
[[bodies]]
size = 1.0
mass = 1.0
)",
     "test.toml:2:1", "bodies[0].shape", "missing"},
    {"MissingSize", R"(duration = 1.0
[[bodies]]
shape = "cube"
mass = 1.0
)",
     "test.toml:2:1", "bodies[0].size", "missing"},
    {"MissingForceKind", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
torque = [1.0, 0.0, 0.0]
)",
     "test.toml:6:1", "bodies[0].forces[0].kind", "missing"},
    {"MissingForceParameter", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "torque"
)",
     "test.toml:6:1", "bodies[0].forces[0].torque", "missing"},
    {"NoBodiesKey", R"(duration = 1.0
)",
     "test.toml:1:1", "bodies", "missing"},
    {"EmptyBodies", R"(duration = 1.0
bodies = []
)",
     "test.toml:2:10", "bodies", "at least one"},
    {"BodiesIsATable", R"(duration = 1.0
[bodies]
shape = "cube"
)",
     "test.toml:2:1", "bodies", "at least one"},
    {"BodyIsNotATable", R"(duration = 1.0
bodies = [1]
)",
     "test.toml:2:11", "bodies[0]", "expected a [[bodies]] table"},
    {"StringForNumber", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = "1.0"
)",
     "test.toml:5:8", "bodies[0].mass", "expected a number, found a string"},
    {"BooleanForNumber", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = true
)",
     "test.toml:5:8", "bodies[0].mass", "found a boolean"},
    {"NumberForString", R"(duration = 1.0
[physics]
integrator = 4
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:14", "physics.integrator", "expected a string, found a number"},
    {"NumberForVector", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
velocity = 2.0
)",
     "test.toml:6:12", "bodies[0].velocity", "found a number"},
    {"VectorOfTwo", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
velocity = [2.0, 0.0]
)",
     "test.toml:6:12", "bodies[0].velocity", "found an array of 2"},
    {"StringInVector", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
angular_velocity = [2.0, "0", 0.0]
)",
     "test.toml:6:20", "bodies[0].angular_velocity", "expected a number, found a string"},
    {"PhysicsIsNotATable", R"(duration = 1.0
physics = 3
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:2:11", "physics", "expected a [physics] table"},
    {"ForcesIsNotAnArray", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
forces = 3
)",
     "test.toml:6:10", "bodies[0].forces", "expected [[bodies.forces]]"},
    {"NanDuration", R"(duration = nan
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:1:12", "duration", "finite"},
    {"InfInVector", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
position = [0.0, inf, 0.0]
)",
     "test.toml:6:12", "bodies[0].position", "finite"},
    {"NegativeInfMass", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = -inf
)",
     "test.toml:5:8", "bodies[0].mass", "finite"},
    {"NanForceParameter", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "linear_damping"
coefficient = nan
)",
     "test.toml:8:15", "bodies[0].forces[0].coefficient", "finite"},
    {"ZeroMass", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 0
)",
     "test.toml:5:8", "bodies[0].mass", "greater than 0 (got 0)"},
    {"NegativeMass", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = -2.5
)",
     "test.toml:5:8", "bodies[0].mass", "greater than 0 (got -2.5)"},
    {"ZeroCubeSize", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 0.0
mass = 1.0
)",
     "test.toml:4:8", "bodies[0].size", "greater than 0"},
    {"NegativeCubeSize", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = -1.0
mass = 1.0
)",
     "test.toml:4:8", "bodies[0].size", "greater than 0"},
    {"BoxWithAZeroEdge", R"(duration = 1.0
[[bodies]]
shape = "box"
size = [1.0, 0.0, 2.0]
mass = 1.0
)",
     "test.toml:4:8", "bodies[0].size", "every edge"},
    {"CubeSizeGivenAsArray", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = [1.0, 1.0, 1.0]
mass = 1.0
)",
     "test.toml:4:8", "bodies[0].size", "one number"},
    {"BoxSizeGivenAsNumber", R"(duration = 1.0
[[bodies]]
shape = "box"
size = 1.0
mass = 1.0
)",
     "test.toml:4:8", "bodies[0].size", "array of 3 numbers"},
    {"ZeroDt", R"(duration = 1.0
[physics]
dt = 0.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:6", "physics.dt", "greater than 0 (got 0)"},
    {"NegativeDt", R"(duration = 1.0
[physics]
dt = -0.01
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:6", "physics.dt", "greater than 0 (got -0.01)"},
    {"DtLongerThanDuration", R"(duration = 1.0
[physics]
dt = 2.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:6", "physics.dt", "longer than duration"},
    {"ZeroDuration", R"(duration = 0.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:1:12", "duration", "greater than 0 (got 0)"},
    {"NegativeDuration", R"(duration = -1
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:1:12", "duration", "greater than 0 (got -1)"},
    {"ZeroQuaternion", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
orientation = [0, 0, 0, 0]
)",
     "test.toml:6:15", "bodies[0].orientation", "length is 0"},
    {"QuaternionOfLengthTwo", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
orientation = [2.0, 0.0, 0.0, 0.0]
)",
     "test.toml:6:15", "bodies[0].orientation", "length is 2"},
    {"QuaternionOfThreeNumbers", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
orientation = [1.0, 0.0, 0.0]
)",
     "test.toml:6:15", "bodies[0].orientation", "[w, x, y, z]"},
    {"UnknownIntegrator", R"(duration = 1.0
[physics]
integrator = "verlet"
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:14", "physics.integrator", "unknown integrator \"verlet\""},
    {"UnknownShape", R"(duration = 1.0
[[bodies]]
shape = "sphere"
size = 1.0
mass = 1.0
)",
     "test.toml:3:9", "bodies[0].shape", "unknown shape \"sphere\""},
    {"UnknownForceKind", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "magnetism"
)",
     "test.toml:7:8", "bodies[0].forces[0].kind", "unknown force kind \"magnetism\""},
    {"PushStartsAfterItEnds", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "force_at_point"
force = [1.0, 0.0, 0.0]
point = [0.5, 0.5, 0.5]
start = 2.0
end = 1.0
)",
     "test.toml:10:9", "bodies[0].forces[0].start", "after end"},
    {"SpringWithNegativeStiffness", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
anchor = [0.0, 1.0, 0.0]
stiffness = -5.0
)",
     "test.toml:9:13", "bodies[0].forces[0].stiffness", "must not be negative"},
    {"SpringWithNegativeDamping", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
anchor = [0.0, 1.0, 0.0]
stiffness = 5.0
damping = -1.0
)",
     "test.toml:10:11", "bodies[0].forces[0].damping", "must not be negative"},
    {"SpringWithNegativeRestLength", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
anchor = [0.0, 1.0, 0.0]
stiffness = 5.0
rest_length = -0.5
)",
     "test.toml:10:15", "bodies[0].forces[0].rest_length", "must not be negative"},
    {"SpringAnchorKeysEmpty", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor_keys = []
)",
     "test.toml:9:15", "bodies[0].forces[0].anchor_keys",
     "expected at least one key [{ time = t, anchor = [x, y, z] }, ...]"},
    {"SpringAnchorKeysNotAnArray", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor_keys = 3
)",
     "test.toml:9:15", "bodies[0].forces[0].anchor_keys", "expected an array of keys"},
    {"SpringAnchorKeyNotATable", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor_keys = [{ time = 0, anchor = [0, 0, 0] }, 1.0]
)",
     "test.toml:9:50", "bodies[0].forces[0].anchor_keys[1]",
     "expected a key { time = t, anchor = [x, y, z] }"},
    {"SpringAnchorKeyTimesNotIncreasing", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor_keys = [{ time = 1, anchor = [0, 0, 0] }, { time = 0.5, anchor = [1, 0, 0] }]
)",
     "test.toml:9:59", "bodies[0].forces[0].anchor_keys[1].time",
     "must be after the previous key's time 1 s (got 0.5 s)"},
    {"SpringBothAnchorAndAnchorKeys", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor = [0, 1, 0]
anchor_keys = [{ time = 0, anchor = [0, 0, 0] }]
)",
     "test.toml:10:15", "bodies[0].forces[0].anchor_keys", "not both"},
    {"SpringWithoutAnchor", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
damping = 1.0
)",
     "test.toml:6:1", "bodies[0].forces[0].anchor",
     "missing required key: a spring needs anchor = [x, y, z] (fixed) or anchor_keys (moving)"},
    {"SpringMisspeltAnchorIsAnUnknownKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchr = [0, 1, 0]
)",
     "test.toml:9:1", "bodies[0].forces[0].anchr",
     "unknown key (allowed here: anchor, anchor_keys, attachment, damping, end, kind, rest_length, "
     "start, stiffness)"},
    {"SpringAnchorKeyWithoutAnchor", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor_keys = [{ time = 0 }]
)",
     "test.toml:9:16", "bodies[0].forces[0].anchor_keys[0].anchor", "missing required key"},
    {"SpringAnchorKeyWithUnknownKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor_keys = [{ time = 0, anchor = [0, 0, 0], at = 1 }]
)",
     "test.toml:9:48", "bodies[0].forces[0].anchor_keys[0].at",
     "unknown key (allowed here: anchor, time)"},
    {"SpringAnchorKeyTooFar", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor_keys = [{ time = 0, anchor = [0, 2e9, 0] }]
)",
     "test.toml:9:37", "bodies[0].forces[0].anchor_keys[0].anchor",
     "its length 2e+09 m is past the 1e+09 m tumble can simulate"},
    {"SpringAnchorKeysMoveTooFast", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor_keys = [{ time = 0, anchor = [0, 0, 0] }, { time = 1e-9, anchor = [1, 0, 0] }]
)",
     "test.toml:9:74", "bodies[0].forces[0].anchor_keys[1].anchor",
     "it moves at 1e+09 m/s from the previous key, past the 1e+08 m/s"},
    {"SpringStartsAfterItEnds", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "spring"
stiffness = 5.0
anchor = [0, 1, 0]
start = 2
end = 1
)",
     "test.toml:10:9", "bodies[0].forces[0].start", "start (2) is after end (1)"},
    {"NegativeAngularDamping", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "angular_damping"
coefficient = -0.1
)",
     "test.toml:8:15", "bodies[0].forces[0].coefficient", "must not be negative (got -0.1)"},
    {"NegativeLinearDampingInALaterForceOfALaterBody", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "gravity"
[[bodies.forces]]
kind = "linear_damping"
coefficient = -3
)",
     "test.toml:14:15", "bodies[1].forces[1].coefficient", "must not be negative (got -3)"},
    {"DuplicateBodyNames", R"(duration = 1.0
[[bodies]]
name = "a"
shape = "cube"
size = 1.0
mass = 1.0
[[bodies]]
name = "a"
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:8:8", "bodies[1].name", "duplicate body name \"a\""},
    {"UnsafeSceneName", R"(name = "../x"
duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:1:8", "name", "output folder"},
    {"EmptySceneName", R"(name = ""
duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:1:8", "name", "letters, digits"},
    {"UnsafeBodyName", R"(duration = 1.0
[[bodies]]
name = "lid/handle"
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:8", "bodies[0].name", "letters, digits"},
    {"MisspeltRequiredKeyIsNamedNotReportedMissing", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mas = 1.0
)",
     "test.toml:5:1", "bodies[0].mas", "did you mean \"mass\""},
    {"IntegerBeyondDoublePrecisionIsStillRangeChecked", R"(duration = 1.0
[physics]
dt = 9007199254740993
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:6", "physics.dt", "longer than duration"},
    {"DefaultDtLongerThanDuration", R"(duration = 0.005
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:1:12", "duration", "dt defaults to 0.01"},
    {"TooManySteps", R"(duration = 1e300
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:1:12", "duration", "more than 100000000 steps"},
    {"TooManyStepsBlamesAWrittenDt", R"(duration = 100.0
[physics]
dt = 1e-7
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:6", "physics.dt", "more than 100000000 steps"},
    {"InertiaUnderflows", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1e-200
mass = 1e-200
)",
     "test.toml:5:8", "bodies[0].mass", "beyond double precision"},
    {"OrientationOfThreeSaysWhatWasFound", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
orientation = [1.0, 0.0, 0.0]
)",
     "test.toml:6:15", "bodies[0].orientation", "found an array of 3"},
    {"RenderWidthZero", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
width = 0
)",
     "test.toml:7:9", "render.width", "must be from 16 to 8192 (got 0)"},
    {"RenderWidthBelowMinimum", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
width = 10
)",
     "test.toml:7:9", "render.width", "must be from 16 to 8192 (got 10)"},
    {"RenderWidthBeyond8K", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
width = 9000
)",
     "test.toml:7:9", "render.width", "must be from 16 to 8192 (got 9000)"},
    {"RenderWidthAsString", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
width = "wide"
)",
     "test.toml:7:9", "render.width", "expected a whole number, found a string"},
    {"RenderHeightBelowMinimum", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
height = 15
)",
     "test.toml:7:10", "render.height", "must be from 16 to 8192 (got 15)"},
    {"ZeroFps", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
fps = 0
)",
     "test.toml:7:7", "render.fps", "must be from 1 to 240 (got 0)"},
    {"FpsAbove240", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
fps = 241
)",
     "test.toml:7:7", "render.fps", "must be from 1 to 240 (got 241)"},
    {"MsaaNotAPowerOfTwo", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
msaa = 3
)",
     "test.toml:7:8", "render.msaa", "must be 1, 2, 4, 8 or 16"},
    {"MsaaAbove16", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
msaa = 32
)",
     "test.toml:7:8", "render.msaa", "must be from 1 to 16 (got 32)"},
    {"BackgroundComponentAboveOne", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
background = [1.2, 0, 0]
)",
     "test.toml:7:14", "render.background", "colour components must be from 0 to 1"},
    {"BackgroundHexOfFiveDigits", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
background = "#12345"
)",
     "test.toml:7:14", "render.background",
     "expected a colour \"#rrggbb\" or [r, g, b], found \"#12345\""},
    {"BackgroundColourName", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
background = "red"
)",
     "test.toml:7:14", "render.background", "found \"red\""},
    {"ShadowsAsNumber", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
shadows = 1
)",
     "test.toml:7:11", "render.shadows", "expected true or false, found a number"},
    {"RenderIsNotATable", R"(duration = 1.0
render = 3
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:2:10", "render", "expected a [render] table"},
    {"UnknownRenderKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
samples = 4
)",
     "test.toml:7:1", "render.samples",
     "unknown key (allowed here: backend, background, egl_device, font, fps, height, msaa, "
     "shadows, "
     "width)"},
    {"NegativeEglDevice", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
egl_device = -1
)",
     "test.toml:7:14", "render.egl_device", "must be from 0 to 255 (got -1)"},
    {"EglDeviceForOsmesa", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
backend = "osmesa"
egl_device = 0
)",
     "test.toml:8:14", "render.egl_device", "names an EGL device, but backend is \"osmesa\""},
    {"ZeroFieldOfView", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[camera]
fov_degrees = 0
)",
     "test.toml:7:15", "camera.fov_degrees", "less than 170 degrees (got 0)"},
    {"FieldOfView180", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[camera]
fov_degrees = 180
)",
     "test.toml:7:15", "camera.fov_degrees", "less than 170 degrees (got 180)"},
    {"ZeroCameraUp", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[camera]
up = [0, 0, 0]
)",
     "test.toml:7:6", "camera.up", "must not be the zero vector"},
    {"CameraFollowsNoBody", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[camera]
follow = "lid"
)",
     "test.toml:7:10", "camera.follow", "no body is named \"lid\""},
    {"CameraLooksAtItsOwnPosition", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[camera]
position = [1, 2, 3]
look_at = [1, 2, 3]
)",
     "test.toml:8:11", "camera.look_at", "cannot look at its own position"},
    {"UnknownCameraKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[camera]
target = [0, 0, 0]
)",
     "test.toml:7:1", "camera.target",
     "unknown key (allowed here: follow, fov_degrees, keys, look_at, orbit_period, position, up)"},
    {"ZeroLightDirection", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[light]
direction = [0, 0, 0]
)",
     "test.toml:7:13", "light.direction", "must not be the zero vector"},
    {"AmbientAboveOne", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[light]
ambient = 1.5
)",
     "test.toml:7:11", "light.ambient", "must be from 0 to 1"},
    {"UnknownLightKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[light]
intensity = 2.0
)",
     "test.toml:7:1", "light.intensity", "unknown key (allowed here: ambient, color, direction)"},
    {"NegativeGridSpacing", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[ground]
grid_spacing = -1
)",
     "test.toml:7:16", "ground.grid_spacing", "must not be negative (got -1)"},
    {"GroundEnabledAsString", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[ground]
enabled = "yes"
)",
     "test.toml:7:11", "ground.enabled", "expected true or false, found a string"},
    {"UnknownGroundKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[ground]
colour = "#808080"
)",
     "test.toml:7:1", "ground.colour",
     "unknown key (allowed here: color, enabled, grid_spacing, height)"},
    {"OutputDirectoryClimbsOut", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[output]
directory = "../up"
)",
     "test.toml:7:13", "output.directory", "relative folder inside the output folder"},
    {"OutputDirectoryIsAbsolute", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[output]
directory = "/abs"
)",
     "test.toml:7:13", "output.directory", "relative folder inside the output folder"},
    {"OutputDirectoryIsEmpty", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[output]
directory = ""
)",
     "test.toml:7:13", "output.directory", "relative folder inside the output folder"},
    {"CrfAbove51", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[output]
crf = 52
)",
     "test.toml:7:7", "output.crf", "must be from 0 to 51 (got 52)"},
    {"UnknownPreset", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[output]
preset = "fastest"
)",
     "test.toml:7:10", "output.preset", "unknown x264 preset \"fastest\""},
    {"UnknownOutputKey", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[output]
format = "gif"
)",
     "test.toml:7:1", "output.format",
     "unknown key (allowed here: crf, directory, formats, frames, gif_loop, poster_time, preset, "
     "video)"},
    {"BodyColourNotHex", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
color = "#gg0000"
)",
     "test.toml:6:9", "bodies[0].color",
     "expected a colour \"#rrggbb\" or [r, g, b], found \"#gg0000\""},
    {"RenderWidthWrittenAsADecimal", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
width = 1.5
)",
     "test.toml:7:9", "render.width", "expected a whole number, found 1.5"},
    {"BodyColorOfTwoComponents", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
color = [0.5, 0.5]
)",
     "test.toml:6:9", "bodies[0].color", "colour \"#rrggbb\" or [r, g, b], found an array of 2"},
    {"BodyInsideAPlaneIsBlamedOnItsPosition", R"(duration = 1.0
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 1.0
position = [0.0, 0.38, 0.0]
[[planes]]
name = "floor"
point = [0, 0, 0]
normal = [0, 1, 0]
)",
     "test.toml:7:12", "bodies[0].position", "body \"cube\" starts 0.12 m inside plane \"floor\""},
    {"BodyAtTheDefaultPositionInsideAPlaneIsBlamedOnThePlanesPoint", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
[[planes]]
name = "wall"
point = [0, 0, 0.25]
normal = [0, 0, -1]
)",
     "test.toml:7:9", "planes[0].point", "body \"body0\" starts 0.5 m inside plane \"plane0\""},
    {"ContactStiffnessWithTheDefaultImpulseContact", R"(duration = 1.0
[physics]
contact_stiffness = 1e5
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:3:21", "physics.contact_stiffness",
     "is for contact = \"penalty\" only, and this scene's contact is \"impulse\" (the default)"},
    {"ContactStiffnessZero", R"(duration = 1.0
[physics]
contact = "penalty"
contact_stiffness = 0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:4:21", "physics.contact_stiffness", "must be greater than 0 (got 0)"},
    {"PlanesNotTables", R"(duration = 1.0
planes = 3
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
     "test.toml:2:10", "planes", "expected [[planes]] tables"},
    {"PlaneNormalOfTwoNumbers", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[planes]]
point = [0, -1, 0]
normal = [0, 1]
)",
     "test.toml:8:10", "planes[0].normal", "expected an array of 3 numbers [x, y, z]"},
    {"PlaneWithoutPoint", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[planes]]
normal = [0, 1, 0]
)",
     "test.toml:6:1", "planes[0].point", "missing required key in planes[0]"},
    {"PlaneSizeOfOneNumber", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[planes]]
point = [0, -1, 0]
normal = [0, 1, 0]
size = 10
)",
     "test.toml:9:8", "planes[0].size", "expected an array of 2 numbers [across, up the slope]"},
    {"GroundEnabledWithPlanes", R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[[planes]]
point = [0, -1, 0]
normal = [0, 1, 0]
[ground]
enabled = false
)",
     "test.toml:10:11", "ground.enabled", "not used in a scene with [[planes]]"},
};

INSTANTIATE_TEST_SUITE_P(BadScenes, SceneLoaderRejects, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace tumble::scene
