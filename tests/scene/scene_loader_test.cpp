#include "scene/scene_loader.hpp"
#include "scene/scene_builder.hpp"
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

// A sphere is its radius (its box the cube around it, for bounds and framing) with the inertia of
// a uniform ball; a static body needs no mass (0 is taken, as other engines write a static body)
// and gets no inverse mass or inertia.
TEST(SceneLoader, SpheresAndStaticBodiesBecomeTheirShapesAndConstants) {
  const Scene scene = parse_valid(R"(
duration = 1.0
[[bodies]]
name = "ball"
shape = "sphere"
radius = 0.25
mass = 2.0
[[bodies]]
name = "peg"
shape = "sphere"
radius = 0.1
static = true
mass = 0.0
position = [0.0, 2.0, 0.0]
[[bodies]]
name = "table"
shape = "box"
size = [2.0, 0.1, 1.0]
static = true
position = [3.0, 0.0, 0.0]
)");
  ASSERT_EQ(scene.bodies.size(), 3u);
  const BodySpec& ball = scene.bodies[0];
  EXPECT_EQ(ball.shape, Shape::sphere);
  EXPECT_EQ(ball.radius, 0.25);
  EXPECT_EQ(ball.size, Vec3::Constant(0.5));
  EXPECT_FALSE(ball.is_static);
  const physics::BodyModel ball_model = body_model(scene, ball);
  EXPECT_EQ(ball_model.shape.kind, physics::ShapeKind::sphere);
  EXPECT_EQ(ball_model.shape.radius, 0.25);
  EXPECT_NEAR(ball_model.constants.inertia.x(), 0.4 * 2.0 * 0.25 * 0.25, 1e-15);
  EXPECT_TRUE(ball_model.constants.isotropic);
  for (const std::size_t i : {1u, 2u}) {
    const physics::BodyModel fixed = body_model(scene, scene.bodies[i]);
    EXPECT_TRUE(fixed.is_static) << scene.bodies[i].name;
    EXPECT_EQ(fixed.constants.inverse_mass, 0.0);
    EXPECT_EQ(fixed.constants.inverse_inertia, Vec3::Zero());
  }
  EXPECT_EQ(body_model(scene, scene.bodies[2]).shape.half_size, Vec3(1.0, 0.05, 0.5));
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
  EXPECT_FALSE(parse_scene("duration = 1.0\n" + two_cubes, "t.toml").ok());
  // Penalty contact acts between bodies too: overlapping bodies are refused there as well.
  const Result<Scene> penalty =
      parse_scene("duration = 1.0\n[physics]\ncontact = \"penalty\"\n" + two_cubes, "t.toml");
  ASSERT_FALSE(penalty.ok());
  EXPECT_NE(penalty.error().find("start overlapping by 0.5 m"), std::string::npos)
      << penalty.error();
}

// Still islands sleep unless the scene says sleep = false.
TEST(SceneLoader, SleepIsOnUnlessTheSceneTurnsItOff) {
  const std::string cube = "[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n";
  EXPECT_TRUE(parse_valid("duration = 1.0\n" + cube).physics.contact.sleep);
  EXPECT_FALSE(
      parse_valid("duration = 1.0\n[physics]\nsleep = false\n" + cube).physics.contact.sleep);
}

TEST(SceneLoader, LargeIntegersAreReadAsTheNearestDouble) {
  const Result<Scene> result = parse_scene(R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1
mass = 9007199254740993
)",
                                           "test.toml");
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_EQ(result->bodies[0].mass, 9007199254740992.0);
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
  Result<Scene> result = parse_scene(R"(duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)",
                                     "some/folder/falling_lid.toml");
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result->name, "falling_lid");
  EXPECT_EQ(result->source_path, "some/folder/falling_lid.toml");
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

// A scene refused with a message and nothing more to check is a file in tests/scene/bad/ (one a
// case, its line, column, key and message on its second line; scene/bad_scenes_test.cpp). The
// refusals here need a path or a text built in code.

// The error message for `text`, or a test failure if it loads.
std::string message_of(const std::string& text, const std::string& path = "test.toml") {
  Result<Scene> result = parse_scene(text, path);
  if (result.ok()) {
    ADD_FAILURE() << "loaded, but should not have";
    return {};
  }
  return result.error();
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

// Every joint key is read as written, in the world frame at t = 0, and a distance's lengths
// default as the reference says: a rod of the anchors' distance with neither, a rope (slack from
// 0) with max_length alone, a spring with no stops.
TEST(SceneLoader, ReadsJointsAndTheirDefaults) {
  const Scene scene = parse_valid(R"(duration = 1.0
[[bodies]]
name = "door"
shape = "box"
size = [1.0, 2.0, 0.05]
mass = 20.0
position = [0.5, 1.0, 0.0]
[[bodies]]
name = "bob"
shape = "sphere"
radius = 0.1
mass = 1.0
position = [3.0, 0.0, 0.0]
[[joints]]
name = "pivot"
kind = "hinge"
body_a = "door"
anchor = [0.0, 1.0, 0.0]
axis = [0.0, 2.0, 0.0]
lower = -0.5
upper = 0.5
motor_speed = 2.0
max_motor_torque = 10.0
collide_connected = true
visible = false
[[joints]]
name = "rod"
kind = "distance"
body_a = "bob"
anchor_a = [3.0, 0.0, 0.0]
anchor_b = [3.0, 2.0, 0.0]
[[joints]]
name = "rope"
kind = "distance"
body_a = "bob"
body_b = "door"
anchor_a = [3.0, 0.0, 0.0]
anchor_b = [1.0, 0.0, 0.0]
max_length = 2.5
[[joints]]
name = "spring"
kind = "distance"
body_a = "bob"
anchor_a = [3.0, 0.0, 0.0]
anchor_b = [3.0, 1.0, 0.0]
stiffness = 100.0
damping = 2.0
)");
  ASSERT_EQ(scene.joints.size(), 4u);
  const JointSpec& hinge = scene.joints[0];
  EXPECT_EQ(hinge.kind, physics::JointKind::hinge);
  EXPECT_EQ(hinge.body_a, 0u);
  EXPECT_EQ(hinge.body_b, physics::kWorldBody);
  EXPECT_EQ(hinge.anchor_a, Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(hinge.axis, Vec3(0.0, 1.0, 0.0));  // made unit
  ASSERT_TRUE(hinge.limits);
  EXPECT_EQ(hinge.limits->lower, -0.5);
  EXPECT_EQ(hinge.limits->upper, 0.5);
  ASSERT_TRUE(hinge.motor);
  EXPECT_EQ(hinge.motor->speed, 2.0);
  EXPECT_EQ(hinge.motor->max_effort, 10.0);
  EXPECT_TRUE(hinge.collide_connected);
  EXPECT_FALSE(hinge.visible);
  const JointSpec& rod = scene.joints[1];
  EXPECT_EQ(rod.min_length, 2.0);
  EXPECT_EQ(rod.max_length, 2.0);
  EXPECT_FALSE(rod.collide_connected);
  EXPECT_TRUE(rod.visible);
  const JointSpec& rope = scene.joints[2];
  EXPECT_EQ(rope.body_b, 0u);
  EXPECT_EQ(rope.min_length, 0.0);
  EXPECT_EQ(rope.max_length, 2.5);
  const JointSpec& spring = scene.joints[3];
  EXPECT_EQ(spring.stiffness, 100.0);
  EXPECT_EQ(spring.damping, 2.0);
  EXPECT_EQ(spring.min_length, 0.0);
  EXPECT_EQ(spring.max_length, kInfinity);
  // Built: the rod is rigid, the rope and the spring are not; the spring rests at 1 m.
  const sim::Simulation simulation = build_simulation(scene);
  const std::vector<physics::Joint>& built = simulation.joints().joints;
  ASSERT_EQ(built.size(), 4u);
  EXPECT_TRUE(physics::is_rigid_distance(built[1]));
  EXPECT_FALSE(physics::is_rigid_distance(built[2]));
  EXPECT_EQ(built[3].rest_length, 1.0);
}

// Two bodies a joint holds may start overlapping (a chain's links end to end), unless the joint
// lets them collide.
TEST(SceneLoader, ABodyMayOverlapTheBodyItIsJointedTo) {
  const std::string bodies = R"(duration = 1.0
[[bodies]]
name = "a"
shape = "cube"
size = 1.0
mass = 1.0
[[bodies]]
name = "b"
shape = "cube"
size = 1.0
mass = 1.0
position = [0.5, 0.0, 0.0]
[[joints]]
kind = "ball"
body_a = "b"
body_b = "a"
anchor = [0.25, 0.0, 0.0]
)";
  EXPECT_EQ(parse_valid(bodies).joints.size(), 1u);
  const Result<Scene> colliding = parse_scene(bodies + "collide_connected = true\n", "joined.toml");
  ASSERT_FALSE(colliding);
  EXPECT_NE(colliding.error().find("start overlapping"), std::string::npos) << colliding.error();
}

// [physics] gravity is each moving body's first law, as if written first in its table.
TEST(SceneLoader, PhysicsGravityIsTheFirstLawOfEveryMovingBodyWithoutOne) {
  const Scene scene = parse_valid(
      "duration = 1.0\n[physics]\ngravity = [0.5, -3.0, 0.25]\n"
      "[[bodies]]\nname = \"pushed\"\nshape = \"cube\"\nsize = 1.0\nmass = 2.0\n" +
      std::string(testing::kTorqueX) +
      "[[bodies]]\nname = \"own\"\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n"
      "position = [3.0, 0.0, 0.0]\n"
      "[[bodies.forces]]\nkind = \"torque\"\ntorque = [0.0, 1.0, 0.0]\n"
      "[[bodies.forces]]\nkind = \"gravity\"\nacceleration = [0.0, -1.0, 0.0]\n"
      "[[bodies]]\nname = \"peg\"\nshape = \"cube\"\nsize = 1.0\nstatic = true\n"
      "position = [6.0, 0.0, 0.0]\n");
  ASSERT_EQ(scene.bodies.size(), 3u);
  const BodySpec& pushed = scene.bodies[0];
  ASSERT_EQ(pushed.forces.size(), 2u);
  EXPECT_EQ(force_as<physics::Gravity>(pushed, 0).acceleration, Vec3(0.5, -3.0, 0.25));
  EXPECT_EQ(force_as<physics::ConstantTorque>(pushed, 1).torque, Vec3(1.0, 0.0, 0.0));
  // A body's own gravity law wins: it keeps its laws as written, and no other.
  const BodySpec& own = scene.bodies[1];
  ASSERT_EQ(own.forces.size(), 2u);
  EXPECT_EQ(force_as<physics::ConstantTorque>(own, 0).torque, Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(force_as<physics::Gravity>(own, 1).acceleration, Vec3(0.0, -1.0, 0.0));
  // A static body takes no law.
  EXPECT_TRUE(scene.bodies[2].forces.empty());
}

TEST(SceneLoader, WithoutPhysicsGravityABodyHasOnlyItsOwnLaws) {
  const Scene scene = parse_valid(testing::cube_scene(1.0));
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_TRUE(scene.bodies[0].forces.empty());
}

}  // namespace
}  // namespace tumble::scene
