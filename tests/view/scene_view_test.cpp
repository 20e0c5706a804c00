// What a frame shows of the forces: a spring from its attachment to where its anchor is at the
// frame's time, and only while it acts (as a push is drawn only while it pushes).
#include "view/scene_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "scene/scene_builder.hpp"

namespace tumble::view {
namespace {

using physics::Vec3;

// A unit cube at rest at the origin, held by a spring that acts from 0.25 s to 0.75 s while its
// anchor goes from (2, 0, 0) at 0 s to (2, 4, 0) at 0.5 s. Stiffness 0: the cube stays put.
scene::Scene dragged_cube_scene() {
  scene::Scene scene;
  scene.name = "dragged";
  scene.duration = 1.0;
  scene::BodySpec cube;
  cube.name = "cube";
  cube.forces = {physics::Spring{.anchor_keys = {{.time = 0.0, .anchor = Vec3(2, 0, 0)},
                                                 {.time = 0.5, .anchor = Vec3(2, 4, 0)}},
                                 .attachment = Vec3(0.5, 0, 0),
                                 .start = 0.25,
                                 .end = 0.75}};
  scene.bodies = {cube};
  return scene;
}

render::FrameView view_at(const scene::Scene& scene, double t) {
  const physics::BodyState at_rest = scene::initial_state(scene.bodies.front());
  return frame_view(scene, Framing{}, {at_rest}, t);
}

TEST(SceneView, SpringIsDrawnOnlyWhileItActs) {
  const scene::Scene scene = dragged_cube_scene();
  EXPECT_EQ(view_at(scene, 0.0).boxes.size(), 1u);  // the cube alone
  EXPECT_EQ(view_at(scene, 0.249).boxes.size(), 1u);
  EXPECT_EQ(view_at(scene, 0.25).boxes.size(), 3u);  // the cube, the rod and the anchor block
  EXPECT_EQ(view_at(scene, 0.749).boxes.size(), 3u);
  EXPECT_EQ(view_at(scene, 0.75).boxes.size(), 1u);  // let go
  EXPECT_EQ(view_at(scene, 2.0).boxes.size(), 1u);
}

TEST(SceneView, SpringRunsFromTheAttachmentToTheAnchorAtTheFramesTime) {
  const scene::Scene scene = dragged_cube_scene();
  for (const double t : {0.25, 0.5, 0.7}) {
    SCOPED_TRACE(t);
    const Vec3 anchor = Vec3(2, 4 * std::min(t / 0.5, 1.0), 0);
    const render::FrameView view = view_at(scene, t);
    ASSERT_EQ(view.boxes.size(), 3u);
    const render::Box& rod = view.boxes[1];
    const render::Box& block = view.boxes[2];
    EXPECT_LT((block.position - anchor).norm(), 1e-12);
    // The rod's middle is half way from the attachment (0.5, 0, 0) to the anchor, and it is as
    // long as the distance between them.
    EXPECT_LT((rod.position - 0.5 * (Vec3(0.5, 0, 0) + anchor)).norm(), 1e-12);
    EXPECT_NEAR(rod.size.z(), (anchor - Vec3(0.5, 0, 0)).norm(), 1e-12);
  }
}

// The camera frames the anchor where it is drawn: while the spring acts, at the frames' times.
TEST(SceneView, FramingTakesInTheAnchorOnlyWhereItIsDrawn) {
  scene::Scene scene = dragged_cube_scene();
  const auto never_stop = [] { return false; };
  // Acting from 0.25 s: the anchor is drawn from (2, 2, 0) up to (2, 4, 0), the cube at the origin.
  const Result<Framing> acting = frame_scene(scene, 60, never_stop);
  ASSERT_TRUE(acting) << acting.error();
  EXPECT_LT((acting->camera.look_at - Vec3(1, 2, 0)).norm(), 1e-12);
  // Acting only after the last frame: never drawn, so only the cube is framed.
  std::get<physics::Spring>(scene.bodies.front().forces.front()).start = 5.0;
  std::get<physics::Spring>(scene.bodies.front().forces.front()).end = 6.0;
  const Result<Framing> never = frame_scene(scene, 60, never_stop);
  ASSERT_TRUE(never) << never.error();
  EXPECT_EQ(never->camera.look_at, Vec3::Zero());
}

// The framing pass runs the physics only for what the scene leaves open: the camera's position
// or look_at, or (with no planes) the ground's height. Counted in physics steps.
TEST(SceneView, TheFramingPassRunsOnlyWhenTheCameraOrGroundIsLeftOpen) {
  scene::Scene scene = dragged_cube_scene();
  scene.camera.position = Vec3(4, 3, 6);
  scene.camera.look_at = Vec3::Zero();
  scene.ground_height = -1.0;
  const auto never_stop = [] { return false; };
  ASSERT_FALSE(framing_needs_motion(scene));
  const Result<Framing> given = frame_scene(scene, 60, never_stop);
  ASSERT_TRUE(given) << given.error();
  EXPECT_EQ(given->physics_steps, 0);
  EXPECT_EQ(given->camera.position, Vec3(4, 3, 6));
  EXPECT_EQ(given->ground.height, -1.0);

  scene::Scene open_ground = scene;
  open_ground.ground_height.reset();
  scene::Scene open_look = scene;
  open_look.camera.look_at.reset();
  scene::Scene open_position = scene;
  open_position.camera.position.reset();
  for (const scene::Scene* open : {&open_ground, &open_look, &open_position}) {
    EXPECT_TRUE(framing_needs_motion(*open));
    const Result<Framing> framed = frame_scene(*open, 60, never_stop);
    ASSERT_TRUE(framed) << framed.error();
    EXPECT_NEAR(framed->physics_steps, 99, 1);  // to the last frame, 59/60 s, at dt = 0.01 s
  }

  // With planes the floor is a plane: the camera alone decides.
  scene::Scene floored = scene;
  floored.ground_height.reset();
  scene::PlaneSpec floor;
  floor.point = Vec3(0, -1, 0);
  floored.planes.push_back(floor);
  EXPECT_FALSE(framing_needs_motion(floored));
  const Result<Framing> on_floor = frame_scene(floored, 60, never_stop);
  ASSERT_TRUE(on_floor) << on_floor.error();
  EXPECT_EQ(on_floor->physics_steps, 0);
  EXPECT_EQ(on_floor->ground.height, -1.0);
}

// A stop asked for during the framing pass is a returned error, not an exception.
TEST(SceneView, AStopDuringTheFramingPassIsAnError) {
  const scene::Scene scene = dragged_cube_scene();
  const Result<Framing> stopped = frame_scene(scene, 60, [] { return true; });
  ASSERT_FALSE(stopped);
  EXPECT_EQ(stopped.error(), "interrupted");
}

// A recording keeps, of each frame, the overlays it draws in the scene: its arrows (a vector's,
// an axes' three) exactly as drawn, and each trail's point at the frame's time.
TEST(SceneView, RecordedMotionKeepsTheArrowsAndTrailPointsEachFrameDraws) {
  scene::Scene scene = dragged_cube_scene();
  scene.bodies.front().velocity = Vec3(1.0, 0.0, 0.0);
  scene.bodies.front().forces.clear();
  scene.camera.position = Vec3(4, 3, 6);
  scene.camera.look_at = Vec3::Zero();
  scene.ground_height = -1.0;
  scene::VectorOverlay velocity;
  velocity.scale = 0.5;
  velocity.label = "v";
  scene::TrailOverlay trail;
  trail.point = Vec3(0.5, 0.0, 0.0);
  scene::AxesOverlay axes;
  axes.length = 2.0;
  scene.overlays = {velocity, trail, axes};
  const Result<Framing> framing = frame_scene(scene, 60, [] { return false; });
  ASSERT_TRUE(framing) << framing.error();
  SimulatedFrames frames(scene, *framing, [] { return false; });
  frames.record_motion();
  std::vector<render::FrameView> views;
  for (std::int64_t k = 0; k < 3; ++k) {
    Result<render::FrameView> view = frames.view(k);
    ASSERT_TRUE(view) << view.error();
    views.push_back(std::move(*view));
  }
  ASSERT_EQ(frames.motion().size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const FrameMotion& motion = frames.motion()[k];
    ASSERT_EQ(motion.arrows.size(), 4u);  // the velocity and three axes
    for (std::size_t a = 0; a < 4; ++a) {
      EXPECT_EQ(motion.arrows[a].from, views[k].arrows[a].from);
      EXPECT_EQ(motion.arrows[a].to, views[k].arrows[a].to);
      EXPECT_EQ(motion.arrows[a].label, views[k].arrows[a].label);
    }
    const double x = static_cast<double>(k) / 60.0;  // m: the cube moves at 1 m/s along x
    EXPECT_NEAR(motion.arrows[0].from.x(), x, 1e-12);
    EXPECT_NEAR(motion.arrows[0].to.x(), x + 0.5, 1e-12);
    ASSERT_EQ(motion.trail_points.size(), 1u);
    EXPECT_NEAR(motion.trail_points[0].x(), x + 0.5, 1e-12);
    EXPECT_NEAR((motion.arrows[1].to - motion.arrows[1].from).norm(), 2.0, 1e-12);
  }
}

}  // namespace
}  // namespace tumble::view
