// What a frame shows of the forces: a spring from its attachment to where its anchor is at the
// frame's time, and only while it acts (as a push is drawn only while it pushes).
#include "app/scene_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "scene/scene_builder.hpp"

namespace tumble::app {
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
  const Framing acting = frame_scene(scene, 60, never_stop);
  EXPECT_LT((acting.camera.look_at - Vec3(1, 2, 0)).norm(), 1e-12);
  // Acting only after the last frame: never drawn, so only the cube is framed.
  std::get<physics::Spring>(scene.bodies.front().forces.front()).start = 5.0;
  std::get<physics::Spring>(scene.bodies.front().forces.front()).end = 6.0;
  const Framing never = frame_scene(scene, 60, never_stop);
  EXPECT_EQ(never.camera.look_at, Vec3::Zero());
}

}  // namespace
}  // namespace tumble::app
