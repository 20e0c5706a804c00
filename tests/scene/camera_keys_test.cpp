// [[camera.keys]] and [camera] orbit_period as read from a scene file, and the errors of keys
// out of time or out of order (bad-scene files cover each with its line too).
#include "scene/camera_keys.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "scene/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tumble::scene {
namespace {

// A 4 s cube scene with `tables` appended, parsed; and its error.
Scene parsed(const std::string& tables) {
  return testing::parse_valid(testing::cube_scene(4.0) + tables);
}
std::string error_of(const std::string& tables) {
  return testing::error_of(testing::cube_scene(4.0) + tables);
}

constexpr const char* kTwoKeys = R"([camera]
fov_degrees = 35
orbit_period = 8.0
[[camera.keys]]
time = 0.0
position = [0, 2, 8]
look_at = [0, 0, 0]
[[camera.keys]]
time = 2.5
position = [8, 2, 0]
look_at = [0, 1, 0]
fov_degrees = 50
)";

TEST(CameraKeys, KeysAndOrbitAreRead) {
  const Scene scene = parsed(kTwoKeys);
  ASSERT_EQ(scene.camera.keys.size(), 2u);
  EXPECT_EQ(scene.camera.keys[0].time, 0.0);
  EXPECT_EQ(scene.camera.keys[0].fov_degrees, 35.0);  // [camera] fov_degrees
  EXPECT_EQ(scene.camera.keys[1].position, physics::Vec3(8, 2, 0));
  EXPECT_EQ(scene.camera.keys[1].fov_degrees, 50.0);
  EXPECT_EQ(scene.camera.orbit_period, 8.0);
}

TEST(CameraKeys, KeyTimesOutsideTheSceneOrOutOfOrderAreErrorsAtTheTime) {
  const std::string negative =
      "[[camera.keys]]\ntime = -0.5\nposition = [0, 0, 5]\n"
      "look_at = [0, 0, 0]\n";
  EXPECT_NE(error_of(negative).find("test.toml:7:8: camera.keys[0].time: must be from 0 to the "
                                    "duration, 4 s (got -0.5)"),
            std::string::npos)
      << error_of(negative);
  const std::string late =
      "[[camera.keys]]\ntime = 4.5\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\n";
  EXPECT_NE(error_of(late).find("camera.keys[0].time: must be from 0 to the duration"),
            std::string::npos);
  const std::string backwards =
      "[[camera.keys]]\ntime = 2.0\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\n"
      "[[camera.keys]]\ntime = 2.0\nposition = [0, 0, 6]\nlook_at = [0, 0, 0]\n";
  EXPECT_NE(error_of(backwards).find("test.toml:11:8: camera.keys[1].time: must be later than "
                                     "the key before, at 2 s"),
            std::string::npos)
      << error_of(backwards);
}

TEST(CameraKeys, KeysLeaveNoRoomForAPositionBesideThem) {
  const std::string both =
      "[camera]\nposition = [0, 0, 5]\n[[camera.keys]]\ntime = 0.0\n"
      "position = [0, 0, 5]\nlook_at = [0, 0, 0]\n";
  EXPECT_NE(error_of(both).find("camera.position: not used with [[camera.keys]]"),
            std::string::npos)
      << error_of(both);
  EXPECT_NE(error_of("[camera]\norbit_period = 0\n").find("camera.orbit_period: must be greater"),
            std::string::npos);
}

}  // namespace
}  // namespace tumble::scene
