// The dropped cube at rest, as rendered: resting on the floor with no gap and no sinking a
// viewer could see, and its shadow meeting its base (a golden image of the scene's last frame).
// Regenerate the golden after an intended change of the look with TUMBLE_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>
#include <variant>

#include "diff/image_diff.hpp"
#include "io/png_io.hpp"
#include "physics/contact.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "support/command_test.hpp"
#include "support/render_golden.hpp"
#include "support/result_text.hpp"

using tumble::testing::read_file;

namespace {

const std::string kSource = TUMBLE_SOURCE_DIR;
const std::string kScene = kSource + "/scenes/dropped_cube.toml";

class DroppedCube : public tumble::testing::CommandTest {
 protected:
  // The last frame of the 4 s scene at 60 frames/s, at 320 × 180.
  tumble::io::Image last_frame(const std::string& scene, const std::string& folder) const {
    const tumble::testing::Outcome run = tumble("render " + scene + " -o " + path(folder) +
                                                " --width 320 --height 180 --no-video "
                                                "--frames 239:240 -q");
    EXPECT_EQ(run.exit_code, 0) << run.err;
    tumble::io::Image frame;
    EXPECT_EQ(
        ::tumble::testing::take(
            tumble::io::read_png(path(folder) + "/dropped_cube/frames/frame_00239.png"), frame),
        "");
    return frame;
  }
};

TEST_F(DroppedCube, RestsOnTheFloorWithinAPixelAt720p) {
  const auto loaded = tumble::scene::load_scene_file(kScene);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const tumble::scene::Scene& scene = *loaded;
  tumble::sim::Simulation simulation = tumble::scene::build_simulation(scene);
  const auto states = simulation.states_at(scene.duration);
  const tumble::physics::Plane floor = tumble::scene::plane(scene.planes.front());
  const double gap = tumble::physics::closest_corner_separation(
      states.front(), 0.5 * scene.bodies.front().size, floor);  // m: > 0 floating, < 0 sunk
  // One pixel of a 720-line image at the cube's distance from the scene's camera (m).
  const double distance = (*scene.camera.position - states.front().position()).norm();
  const double pixel =
      2.0 * distance * std::tan(0.5 * scene.camera.fov_degrees * std::numbers::pi / 180.0) / 720.0;
  std::printf("[ measured ] dropped cube at rest: gap %.3g m, a pixel at 720p is %.3g m\n", gap,
              pixel);
  EXPECT_LE(std::abs(gap), pixel);
  EXPECT_LE(std::abs(gap), 1e-6);  // and in fact far below it
}

// As the renderer's goldens: 8 levels per channel, on at most 1% of the pixels.
constexpr tumble::diff::DiffOptions kTolerance{.threshold = 8, .max_pixels = 320 * 180 / 100};

// In the default look, and in the plain one (common::Look::plain's keys), each its golden.
TEST_F(DroppedCube, LastFrameMatchesItsGolden) {
  tumble::testing::expect_matches_golden(last_frame(kScene, "out"), "dropped_cube_at_rest",
                                         kTolerance);
}

TEST_F(DroppedCube, LastFrameInThePlainLookMatchesTheGoldenOfBeforeTheLook) {
  const std::string plain = read_file(kScene) +
                            "\n[render]\nshadow_softness = 0\nambient_occlusion = 0\n"
                            "fill_light = 0.45\nexposure = 1.0\n";
  write("dropped_cube.toml", plain);
  tumble::testing::expect_matches_golden(last_frame(path("dropped_cube.toml"), "plain"),
                                         "dropped_cube_at_rest_plain", kTolerance);
}

// The first 1.5 s of scenes/pile.toml, 600 boxes, while the column lands (every island sub-stepped,
// up to 32 times a step, fast pairs' points and bodies' corners near planes found again within
// steps): the CSV of two runs, and the frames of a pipelined and a serial render, are the same
// bytes; the last is the pile's golden in the default look. (1.5 s, not more: the sanitizer build
// takes about 25 s a simulated second here.)
class PilePour : public tumble::testing::CommandTest {
 protected:
  std::string pour() const {
    std::string text = read_file(kSource + "/scenes/pile.toml");
    const std::string duration = "duration = 20.0";
    const std::size_t at = text.find(duration);
    EXPECT_NE(at, std::string::npos);
    text.replace(at, duration.size(), "duration = 1.5");
    const std::string file = path("pour.toml");
    std::ofstream(file) << text;
    return file;
  }
};

TEST_F(PilePour, SimulateAndRenderGiveTheSameBytesEveryWay) {
  const std::string scene = pour();
  ASSERT_EQ(tumble("simulate " + scene + " --every 30 --out " + path("a.csv")).exit_code, 0);
  ASSERT_EQ(tumble("simulate " + scene + " --every 30 --out " + path("b.csv")).exit_code, 0);
  const std::string csv = read_file(path("a.csv"));
  EXPECT_GT(csv.size(), 100000u);  // 600 bodies, 4 rows of each
  EXPECT_EQ(csv, read_file(path("b.csv")));
  const std::string frames = " -q --frames 88:90 --width 320 --height 180 --no-video ";
  ASSERT_EQ(tumble("render" + frames + scene + " -o " + path("piped")).exit_code, 0);
  ASSERT_EQ(tumble("render --serial" + frames + scene + " -o " + path("serial")).exit_code, 0);
  for (int k = 88; k < 90; ++k) {
    const std::string name = "pile/frames/frame_000" + std::to_string(k) + ".png";
    const std::string piped = read_file(path("piped") + "/" + name);
    EXPECT_FALSE(piped.empty()) << name;
    EXPECT_EQ(piped, read_file(path("serial") + "/" + name)) << name;
  }
  tumble::io::Image last;
  ASSERT_EQ(::tumble::testing::take(
                tumble::io::read_png(path("serial") + "/pile/frames/frame_00089.png"), last),
            "");
  tumble::testing::expect_matches_golden(last, "pile_landing", kTolerance);
}

// The tower's last frame (6 s) at 320 × 180 in the default look: boxes on boxes, their soft
// shadows down the tower's side and on the floor, the floor's occlusion at its foot.
class Tower : public tumble::testing::CommandTest {};

TEST_F(Tower, LastFrameMatchesItsGolden) {
  const tumble::testing::Outcome run =
      tumble("render " + kSource + "/scenes/tower.toml -o " + path("out") +
             " --width 320 --height 180 --no-video --frames 359:360 -q");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  tumble::io::Image frame;
  ASSERT_EQ(::tumble::testing::take(
                tumble::io::read_png(path("out") + "/tower/frames/frame_00359.png"), frame),
            "");
  tumble::testing::expect_matches_golden(frame, "tower", kTolerance);
}

}  // namespace
