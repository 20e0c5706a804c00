// The camera of each frame: exactly a key at its time, the smoothstep-eased value between keys,
// an orbit that comes back after one period, a followed body kept at the look-at point, and a
// rendered frame whose box lands where the keyed camera projects it.
#include "view/camera_path.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_builder.hpp"
#include "support/render_golden.hpp"
#include "view/scene_view.hpp"

namespace tumble::view {
namespace {

using physics::Vec3;

std::vector<scene::CameraKey> two_keys() {
  return {{.time = 1.0, .position = Vec3(0, 2, 8), .look_at = Vec3(0, 0, 0), .fov_degrees = 40},
          {.time = 3.0, .position = Vec3(8, 2, 0), .look_at = Vec3(1, 1, 1), .fov_degrees = 60}};
}

void expect_near(const Vec3& got, const Vec3& expected, double tolerance) {
  EXPECT_LE((got - expected).norm(), tolerance)
      << got.transpose() << " vs " << expected.transpose();
}

TEST(CameraPath, EaseIsSmoothstepWithItsClosedFormValues) {
  EXPECT_EQ(ease(0.0), 0.0);
  EXPECT_EQ(ease(1.0), 1.0);
  EXPECT_EQ(ease(0.5), 0.5);
  EXPECT_DOUBLE_EQ(ease(0.25), 0.15625);  // 3/16 − 2/64
  // Zero slope at both ends: (ease(h) − ease(0)) / h → 0 as h → 0.
  EXPECT_LT(ease(1e-4) / 1e-4, 1e-3);
  EXPECT_LT((1.0 - ease(1.0 - 1e-4)) / 1e-4, 1e-3);
}

TEST(CameraPath, CameraIsExactlyEachKeyAtItsTimeAndHeldOutsideThem) {
  const auto keys = two_keys();
  for (const scene::CameraKey& key : keys) {
    const render::Camera camera = keyed_camera(keys, Vec3::UnitY(), key.time);
    EXPECT_EQ(camera.position, key.position);
    EXPECT_EQ(camera.look_at, key.look_at);
    EXPECT_EQ(camera.fov_degrees, key.fov_degrees);
  }
  EXPECT_EQ(keyed_camera(keys, Vec3::UnitY(), 0.0).position, keys[0].position);
  EXPECT_EQ(keyed_camera(keys, Vec3::UnitY(), 5.0).position, keys[1].position);
}

TEST(CameraPath, BetweenKeysTheCameraIsTheEasedValue) {
  const auto keys = two_keys();
  // Halfway in time is halfway along (ease(0.5) = 0.5); a quarter of the way in time is 0.15625
  // of the way along.
  const render::Camera half = keyed_camera(keys, Vec3::UnitY(), 2.0);
  expect_near(half.position, Vec3(4, 2, 4), 1e-12);
  expect_near(half.look_at, Vec3(0.5, 0.5, 0.5), 1e-12);
  EXPECT_NEAR(half.fov_degrees, 50.0, 1e-12);
  const render::Camera quarter = keyed_camera(keys, Vec3::UnitY(), 1.5);
  expect_near(quarter.position, Vec3(8 * 0.15625, 2, 8 - 8 * 0.15625), 1e-12);
  EXPECT_NEAR(quarter.fov_degrees, 40.0 + 20.0 * 0.15625, 1e-12);
}

TEST(CameraPath, OrbitTurnsAboutUpAndReturnsAfterOnePeriod) {
  scene::CameraSpec spec;
  spec.orbit_period = 4.0;  // s
  const render::Camera base{.position = Vec3(3, 2, 0), .look_at = Vec3(0, 1, 0)};
  const render::Camera start = camera_at(spec, base, -1, {}, 0.0);
  expect_near(start.position, base.position, 1e-15);
  // A quarter turn, counter-clockwise seen from above: +x goes to −z.
  expect_near(camera_at(spec, base, -1, {}, 1.0).position, Vec3(0, 2, -3), 1e-12);
  const render::Camera turned = camera_at(spec, base, -1, {}, 4.0);
  expect_near(turned.position, base.position, 1e-12);
  expect_near(turned.look_at, base.look_at, 0.0);
  // The distance to the look-at point and the height stay as they were all the way round.
  for (double t = 0.0; t < 4.0; t += 0.37) {
    const render::Camera camera = camera_at(spec, base, -1, {}, t);
    EXPECT_NEAR((camera.position - camera.look_at).norm(), std::sqrt(10.0), 1e-12);
    EXPECT_NEAR(camera.position.y(), 2.0, 1e-12);
  }
}

TEST(CameraPath, FollowKeepsTheOffsetToTheBody) {
  scene::CameraSpec spec;
  scene::BodySpec body;
  body.position = Vec3(5, 0, -2);
  const physics::BodyState state = scene::initial_state(body);
  const render::Camera base{.position = Vec3(0, 3, 6), .look_at = Vec3(0, 0, 0)};
  const render::Camera camera = camera_at(spec, base, 0, {state}, 0.7);
  EXPECT_EQ(camera.look_at, Vec3(5, 0, -2));
  EXPECT_EQ(camera.position, Vec3(5, 3, 4));
}

// Where the keyed camera puts a thin box in a frame: its front face (z = 0.01 m, 1 m wide,
// centred at the origin) seen from the second key's position (1, 0, 5) looking along −z, by the
// pinhole projection x_pixel = W/2 + (x − x_camera) / (depth tan(fov/2)) × H/2.
TEST(CameraPath, RenderedBoxLandsWhereTheKeyedCameraProjectsIt) {
  scene::Scene scene;
  scene.duration = 2.0;
  scene.fps = 10;
  scene.render.width = 320;
  scene.render.height = 180;
  scene.render.ground.enabled = false;
  scene.render.shadows = false;
  scene.camera.keys = {
      {.time = 0.0, .position = Vec3(0, 0, 5), .look_at = Vec3(0, 0, 0), .fov_degrees = 40},
      {.time = 1.0, .position = Vec3(1, 0, 5), .look_at = Vec3(1, 0, 0), .fov_degrees = 40}};
  scene::BodySpec plate;
  plate.name = "plate";
  plate.size = Vec3(1.0, 1.0, 0.02);
  plate.color = Vec3(1.0, 0.0, 0.0);
  scene.bodies = {plate};
  scene.ground_height = -5.0;
  const Result<Framing> framing = frame_scene(scene, 20, [] { return false; });
  ASSERT_TRUE(framing) << framing.error();
  const std::vector<physics::BodyState> states = {scene::initial_state(plate)};
  render::RenderSettings settings;
  static_cast<common::RenderSettings&>(settings) = scene.render;
  settings.msaa = 1;  // hard edges: each pixel is the box's or the background's
  for (const double t : {0.0, 1.0}) {
    const io::Image image = testing::draw(settings, frame_view(scene, *framing, states, t));
    ASSERT_EQ(image.width, 320);
    int left = image.width, right = -1;
    const int middle_row = image.height / 2;
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* pixel = image.row(middle_row) + 3 * x;
      if (pixel[0] > 2 * pixel[2] + 40) {  // the red box, not the blue-grey background
        left = std::min(left, x);
        right = std::max(right, x);
      }
    }
    const double camera_x = t == 0.0 ? 0.0 : 1.0;               // m
    const double focal = 90.0 / std::tan(20.0 * M_PI / 180.0);  // px: (H/2) / tan(fov/2)
    const double depth = 5.0 - 0.01;                            // m, to the front face
    const double expected_left = 160.0 + (-0.5 - camera_x) / depth * focal;
    const double expected_right = 160.0 + (0.5 - camera_x) / depth * focal;
    // Pixel x covers [x, x + 1): the first covered pixel starts within one pixel of the edge.
    EXPECT_NEAR(left, expected_left, 1.0) << "t = " << t;
    EXPECT_NEAR(right + 1, expected_right, 1.0) << "t = " << t;
  }
}

}  // namespace
}  // namespace tumble::view
