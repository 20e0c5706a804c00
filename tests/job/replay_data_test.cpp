// The html replay's data holds, of every frame a render recorded, the camera and the overlays it
// draws in the scene, as numbers the page reads back; the picture's settings as the scene has them.
#include "job/replay_data.hpp"

#include <gtest/gtest.h>

#include "io/json_reader.hpp"
#include "scene/scene_loader.hpp"

namespace tumble::job {
namespace {

constexpr const char* kScene = R"(name = "sliding_cube"
duration = 1.0
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
velocity = [1.0, 0.0, 0.0]
[camera]
position = [4.0, 3.0, 6.0]
look_at = [0.0, 0.0, 0.0]
[ground]
height = -1.0
[render]
width = 320
height = 180
fps = 30
[[overlays]]
kind = "vector"
body = "body0"
quantity = "velocity"
scale = 0.5
label = "v \"<\" c"
[[overlays]]
kind = "trail"
body = "body0"
point = [0.5, 0.0, 0.0]
length = 0.5
[[overlays]]
kind = "axes"
body = "body0"
)";

struct Recorded {
  scene::Scene scene;
  view::Framing framing;
  std::vector<view::FrameMotion> motion;
};

// Frames first .. first + count - 1 of `text`, recorded as a render records them.
Recorded record(const std::string& text, std::int64_t first, std::int64_t count) {
  Recorded out{.scene = {}, .framing = {}, .motion = {}};
  Result<scene::Scene> loaded = scene::parse_scene(text, "scene.toml");
  if (!loaded) {
    ADD_FAILURE() << loaded.error();
    return out;
  }
  out.scene = std::move(*loaded);
  Result<view::Framing> framing = view::frame_scene(out.scene, 30, [] { return false; });
  if (!framing) {
    ADD_FAILURE() << framing.error();
    return out;
  }
  out.framing = *framing;
  view::SimulatedFrames frames(out.scene, out.framing, [] { return false; });
  EXPECT_TRUE(frames.seek(first));
  frames.record_motion();
  for (std::int64_t k = first; k < first + count; ++k) EXPECT_TRUE(frames.view(k));
  out.motion = frames.motion();
  return out;
}

io::JsonValue parsed(const std::string& json) {
  Result<io::JsonValue> value = io::parse_json(json);
  EXPECT_TRUE(value) << value.error() << "\n" << json;
  return value ? *value : io::JsonValue{};
}

std::vector<double> numbers(const io::JsonValue* array) {
  std::vector<double> out;
  if (array) {
    for (const io::JsonValue& item : array->items) out.push_back(item.number);
  }
  return out;
}

TEST(ReplayData, HoldsEveryFramesArrowsTrailPointsAndTheScenesPictureSettings) {
  const Recorded run = record(kScene, 3, 4);
  ASSERT_EQ(run.motion.size(), 4u);
  const io::JsonValue data =
      parsed(replay_data_json(run.scene, run.framing, run.motion, /*first_frame=*/3));
  EXPECT_EQ(data.find("name")->string, "sliding_cube");
  EXPECT_EQ(data.find("fps")->number, 30);
  EXPECT_EQ(data.find("first_frame")->number, 3);
  EXPECT_EQ(data.find("frames")->number, 4);
  EXPECT_EQ(data.find("width")->number, 320);
  EXPECT_EQ(data.find("height")->number, 180);
  EXPECT_EQ(numbers(data.find("background")), std::vector<double>({0.78, 0.84, 0.9}));
  EXPECT_EQ(data.find("transparent")->text, "false");
  EXPECT_EQ(numbers(data.find("camera")->find("position")), std::vector<double>({4, 3, 6}));
  EXPECT_EQ(data.find("camera")->find("fov_degrees")->number, 40);
  EXPECT_EQ(data.find("camera_path")->kind, io::JsonValue::Kind::null);
  EXPECT_EQ(data.find("ground")->find("height")->number, -1);
  EXPECT_GE(data.find("ground")->find("half_extent")->number, 30);

  const io::JsonValue& arrows = *data.find("arrows");
  ASSERT_EQ(arrows.items.size(), 4u);  // the velocity, then the axes' x, y and z
  EXPECT_EQ(arrows.items[0].find("label")->string, "v \"<\" c");
  EXPECT_EQ(arrows.items[1].find("label")->string, "");
  const std::vector<double> from = numbers(arrows.items[0].find("from"));
  const std::vector<double> to = numbers(arrows.items[0].find("to"));
  ASSERT_EQ(from.size(), 12u);
  ASSERT_EQ(to.size(), 12u);
  for (std::size_t k = 0; k < 4; ++k) {
    const double x = static_cast<double>(3 + k) / 30.0;  // m, at 1 m/s
    EXPECT_NEAR(from[3 * k], x, 1e-6);
    EXPECT_NEAR(to[3 * k], x + 0.5, 1e-6);  // 0.5 m per m/s
    EXPECT_NEAR(from[3 * k] - run.motion[k].arrows[0].from.x(), 0.0, 1e-6);
  }
  const io::JsonValue& trails = *data.find("trails");
  ASSERT_EQ(trails.items.size(), 1u);
  EXPECT_EQ(trails.items[0].find("length")->number, 0.5);
  const std::vector<double> points = numbers(trails.items[0].find("points"));
  ASSERT_EQ(points.size(), 12u);
  EXPECT_NEAR(points[9], 6.0 / 30.0 + 0.5, 1e-6);  // the body point 0.5 m along x, frame 6
}

TEST(ReplayData, AMovingCameraHasItsPathAndTheSameFramesGiveTheSameText) {
  std::string orbiting = kScene;
  orbiting.insert(orbiting.find("[ground]"), "orbit_period = 4.0\n");
  const Recorded run = record(orbiting, 0, 3);
  ASSERT_EQ(run.motion.size(), 3u);
  const std::string json = replay_data_json(run.scene, run.framing, run.motion, 0);
  const io::JsonValue data = parsed(json);
  const io::JsonValue* path = data.find("camera_path");
  ASSERT_EQ(path->kind, io::JsonValue::Kind::object);
  const std::vector<double> positions = numbers(path->find("position"));
  ASSERT_EQ(positions.size(), 9u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(positions[3 * k], run.motion[k].camera.position.x(), 1e-6);
    EXPECT_NEAR(positions[3 * k + 2], run.motion[k].camera.position.z(), 1e-6);
  }
  EXPECT_NE(positions[0], positions[6]);  // it turned
  EXPECT_EQ(numbers(path->find("fov_degrees")), std::vector<double>({40, 40, 40}));
  const Recorded again = record(orbiting, 0, 3);
  EXPECT_EQ(replay_data_json(again.scene, again.framing, again.motion, 0), json);
}

}  // namespace
}  // namespace tumble::job
