// The values overlays show: printf's formatting of each placeholder, the vectors arrows draw,
// and a live value in frame k equal, to its printed precision, to the one computed from
// `tumble simulate`'s states interpolated at t = k / fps.
#include "view/overlay_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>

#include "physics/forces.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "scene/text_template.hpp"
#include "support/command_test.hpp"
#include "view/scene_view.hpp"

namespace tumble::view {
namespace {

using physics::Vec3;

scene::BodySpec spinning_cube() {
  scene::BodySpec cube;
  cube.name = "cube";
  cube.mass = 2.0;
  cube.position = Vec3(1.0, -2.0, 0.5);
  cube.velocity = Vec3(3.0, 4.0, 0.0);
  cube.angular_velocity = Vec3(0.0, 0.0, 6.0);
  return cube;
}

std::string formatted(const std::string& text, double t = 1.25, std::int64_t frame = 75) {
  const scene::BodySpec cube = spinning_cube();
  const Result<scene::TextTemplate> parsed = scene::parse_text_template(text, {cube.name});
  EXPECT_TRUE(parsed) << (parsed ? "" : parsed.error());
  const std::vector<physics::BodyState> states = {scene::initial_state(cube)};
  return parsed ? format_text(*parsed, StepPair{states, states}, t, frame) : "";
}

// Mass 2 kg, edge 1 m: I = m s² / 6 = 1/3 kg m², so L = 2 kg m²/s about z; E = ½ m v² + ½ I ω²
// = 25 + 6 = 31 J.
TEST(OverlayValues, FormatsEachQuantityAsPrintfDoes) {
  EXPECT_EQ(formatted("t = {time:.1f} s, frame {frame}"), "t = 1.2 s, frame 75");  // 1.25: even
  EXPECT_EQ(formatted("{cube.speed}"), "5.00");
  EXPECT_EQ(formatted("{cube.velocity:.1f}"), "(3.0, 4.0, 0.0)");
  EXPECT_EQ(formatted("{cube.position.y:.3f}"), "-2.000");
  EXPECT_EQ(formatted("{cube.angular_speed:.0f} rad/s"), "6 rad/s");
  EXPECT_EQ(formatted("{cube.angular_velocity.z:.2e}"), "6.00e+00");
  EXPECT_EQ(formatted("{cube.angular_momentum.z:.4f}"), "2.0000");
  EXPECT_EQ(formatted("{cube.kinetic_energy:.3g} J"), "31 J");
}

// A joint's placeholders read its values (joint_view.hpp): a door on a hinge turned 0.25 rad and
// turning at 2 rad/s, pulled by 30 N along x.
TEST(OverlayValues, FormatsAJointsValues) {
  const Result<scene::TextTemplate> parsed = scene::parse_text_template(
      "{door.angle:.3f} rad, {door.speed:.1f} rad/s, {door.force:.0f} N, {door.force.x:.1f}", {},
      {{"door", physics::JointKind::hinge}});
  ASSERT_TRUE(parsed) << parsed.error();
  const std::vector<JointValue> values = {
      {.coordinate = 0.25, .rate = 2.0, .force = Vec3(30.0, 0.0, -4.0)}};
  const std::vector<physics::BodyState> none;
  EXPECT_EQ(format_text(*parsed, StepPair{none, none}, 0.0, 0, values),
            "0.250 rad, 2.0 rad/s, (30, 0, -4) N, 30.0");
}

// Python's sign, width, fill and alignment (its format mini-language's subset).
TEST(OverlayValues, PadsWithSignWidthAndFill) {
  EXPECT_EQ(formatted("[{cube.position.x:+8.3f}]"), "[  +1.000]");
  EXPECT_EQ(formatted("[{cube.position.y:+8.3f}]"), "[  -2.000]");
  EXPECT_EQ(formatted("[{cube.position.y:08.3f}]"), "[-002.000]");
  EXPECT_EQ(formatted("[{cube.position.x: .1f}]"), "[ 1.0]");
  EXPECT_EQ(formatted("[{cube.position.x:*<7.1f}]"), "[1.0****]");
  EXPECT_EQ(formatted("[{cube.position.x:^7.1f}]"), "[  1.0  ]");
  EXPECT_EQ(formatted("[{cube.position.x:2.1f}]"), "[1.0]");         // wider than asked: kept whole
  EXPECT_EQ(formatted("[{cube.position.x:<08.3f}]"), "[1.000000]");  // as Python: '0' fills
  EXPECT_EQ(formatted("[{cube.position.x:*<08.3f}]"), "[1.000***]");
  EXPECT_EQ(formatted("{cube.velocity:+5.1f}"), "( +3.0,  +4.0,  +0.0)");
  EXPECT_EQ(formatted("[{frame:5d}] [{frame:+}] [{frame:<4}]", 1.0, 75), "[   75] [+75] [75  ]");
}

// A shown quantity is the quantity at the two steps around t, interpolated as itself: halfway
// between a body at rest and one at 2 m/s along x and 2 along y, the speed is the mean of 0 and
// 2√2, not the length of the mean velocity... which here is the same; so: one step moving along
// +x at 2 m/s, the next along +y at 2 m/s. The lerped velocity (1, 1, 0) has length √2, but the
// speed was 2 at both steps and is shown as 2.
TEST(OverlayValues, AQuantityIsInterpolatedAsItself) {
  scene::BodySpec cube = spinning_cube();
  cube.angular_velocity = Vec3::Zero();
  cube.velocity = Vec3(2, 0, 0);
  const std::vector<physics::BodyState> before = {scene::initial_state(cube)};
  cube.velocity = Vec3(0, 2, 0);
  const std::vector<physics::BodyState> after = {scene::initial_state(cube)};
  const StepPair halfway{before, after, 0.5};
  EXPECT_EQ(body_quantity(scene::BodyQuantity::speed, halfway, 0).x(), 2.0);
  EXPECT_EQ(body_quantity(scene::BodyQuantity::kinetic_energy, halfway, 0).x(), 4.0);  // ½ 2 2²
  EXPECT_TRUE(body_quantity(scene::BodyQuantity::velocity, halfway, 0).isApprox(Vec3(1, 1, 0)));
  EXPECT_EQ(body_quantity(scene::BodyQuantity::speed, StepPair{before, after, 0.0}, 0).x(), 2.0);
}

TEST(OverlayValues, AVectorIsItsQuantityAtItsPoint) {
  scene::BodySpec cube = spinning_cube();
  cube.forces = {physics::Gravity{}, physics::ConstantForce{.force = Vec3(1, 0, 0)}};
  const physics::BodyState state = scene::initial_state(cube);
  const std::vector<physics::BodyState> states = {state};
  const StepPair steps{states, states};
  scene::VectorOverlay arrow;
  arrow.quantity = scene::VectorQuantity::velocity;
  EXPECT_EQ(vector_value(arrow, cube, steps, state, 0.0), Vec3(3, 4, 0));
  // v + ω × r at r = (0.5, 0, 0): (3, 4, 0) + (0, 0, 6) × (0.5, 0, 0) = (3, 7, 0).
  arrow.point = Vec3(0.5, 0, 0);
  EXPECT_TRUE(vector_value(arrow, cube, steps, state, 0.0).isApprox(Vec3(3, 7, 0), 1e-15));
  arrow.quantity = scene::VectorQuantity::angular_momentum;
  EXPECT_TRUE(vector_value(arrow, cube, steps, state, 0.0).isApprox(Vec3(0, 0, 2), 1e-15));
  arrow.quantity = scene::VectorQuantity::force;
  arrow.laws = {0};
  EXPECT_TRUE(vector_value(arrow, cube, steps, state, 0.0).isApprox(Vec3(0, -2 * 9.81, 0), 1e-15));
  arrow.laws = {0, 1};
  EXPECT_TRUE(vector_value(arrow, cube, steps, state, 0.0).isApprox(Vec3(1, -2 * 9.81, 0), 1e-15));
  arrow.quantity = scene::VectorQuantity::constant;
  arrow.constant = Vec3(0, 0, -1);
  EXPECT_EQ(vector_value(arrow, cube, steps, state, 0.0), Vec3(0, 0, -1));
}

class LiveValues : public testing::CommandTest {};

// A cube thrown and spun under gravity and damping, stepped at 7 ms and drawn at 24 fps, so that
// frame times fall between steps. Frame k's text, as the render source makes it, against the
// states `tumble simulate` prints for the steps around k / 24 s, interpolated linearly (position
// and momentum are lerped, physics/interpolation.hpp; a speed as a number): the printed value is
// the computed one rounded, so within half a unit of its last digit.
TEST_F(LiveValues, AFramesValueIsSimulatesStateInterpolatedAtItsTime) {
  const std::string text = R"(name = "live"
duration = 1.0
[physics]
dt = 0.007
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 2.0
velocity = [1.5, 4.0, -0.5]
angular_velocity = [0.3, 2.0, 1.0]
[[bodies.forces]]
kind = "gravity"
[[bodies.forces]]
kind = "linear_damping"
coefficient = 0.7
[render]
fps = 24
[camera]
position = [3, 3, 7]
look_at = [0, 0, 0]
[ground]
height = -3.0
[[overlays]]
kind = "text"
text = "{cube.speed:.4f}|{cube.position.y:.5f}"
)";
  const std::filesystem::path file = write("live.toml", text);
  const testing::Outcome run = tumble("simulate " + file.string() + " --out " + path("s.csv"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // t, body, x, y, z, vx, vy, vz, ...: one row a step.
  std::vector<std::array<double, 7>> rows;
  std::ifstream csv(path("s.csv"));
  std::string line;
  std::getline(csv, line);  // header
  while (std::getline(csv, line)) {
    std::array<double, 7> row{};
    std::stringstream fields(line);
    std::string field;
    for (int column = 0, kept = 0; std::getline(fields, field, ',') && kept < 7; ++column) {
      if (column == 1) continue;  // the body's name
      row[static_cast<std::size_t>(kept++)] = std::strtod(field.c_str(), nullptr);
    }
    rows.push_back(row);
  }
  ASSERT_GT(rows.size(), 100u);

  const Result<scene::Scene> loaded = scene::load_scene_file(file.string());
  ASSERT_TRUE(loaded.ok());
  const scene::Scene& scene = *loaded;
  const Result<Framing> framing = frame_scene(scene, 24, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames source(scene, *framing, [] { return false; });
  for (std::int64_t k = 0; k < 24; ++k) {
    const double t = static_cast<double>(k) / 24.0;
    const std::size_t n = static_cast<std::size_t>(std::floor(t / 0.007));
    ASSERT_LT(n + 1, rows.size());
    const double alpha = (t - rows[n][0]) / (rows[n + 1][0] - rows[n][0]);
    const auto lerp = [&](int column) {
      return rows[n][column] + alpha * (rows[n + 1][column] - rows[n][column]);
    };
    // The speed at each step, lerped as a number (overlay_values.hpp's StepPair).
    const double speed_before = Vec3(rows[n][4], rows[n][5], rows[n][6]).norm();  // m/s
    const double speed_after = Vec3(rows[n + 1][4], rows[n + 1][5], rows[n + 1][6]).norm();
    const double speed = speed_before + alpha * (speed_after - speed_before);
    const double y = lerp(2);  // m
    const Result<render::FrameView> view = source.view(k);
    ASSERT_TRUE(view && view->texts.size() == 1u);
    const std::string& shown = view->texts[0].text;
    const std::size_t bar = shown.find('|');
    ASSERT_NE(bar, std::string::npos) << shown;
    EXPECT_NEAR(std::strtod(shown.c_str(), nullptr), speed, 0.5e-4 + 1e-12) << "frame " << k;
    EXPECT_NEAR(std::strtod(shown.c_str() + bar + 1, nullptr), y, 0.5e-5 + 1e-12) << "frame " << k;
    EXPECT_EQ(shown.substr(0, bar).size(), std::to_string(static_cast<int>(speed)).size() + 5)
        << "4 decimals: " << shown;
  }
}

// The tennis racket at dt = 0.004 s drawn at 30 fps: no force and no torque, so the kinetic
// energy and the angular momentum are conserved (RK4 keeps them to ~1e-13 over this run). Every
// frame shows the same string for each, through the flip at t ≈ 2.9 s, though frame times fall
// between steps and the drawn orientation is slerped.
TEST(ExactValues, AConservedQuantityReadsTheSameOnEveryFrame) {
  const std::string text = R"(name = "racket"
duration = 4.0
[physics]
dt = 0.004
integrator = "rk4"
[[bodies]]
name = "box"
shape = "box"
size = [0.3, 1.0, 2.0]
mass = 1.0
angular_velocity = [0.01, 3.0, 0.01]
[render]
fps = 30
[camera]
position = [4.5, 2.5, 5.5]
look_at = [0, 0, 0]
[ground]
height = -1.6
[[overlays]]
kind = "text"
text = "{box.kinetic_energy:.6f}|{box.angular_momentum.x:.6f}|{box.angular_momentum.y:.6f}|{box.angular_momentum.z:.6f}"
)";
  const Result<scene::Scene> loaded = scene::parse_scene(text, "racket.toml");
  ASSERT_TRUE(loaded) << loaded.error();
  const Result<Framing> framing = frame_scene(*loaded, 120, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames source(*loaded, *framing, [] { return false; });
  std::string first;
  for (std::int64_t k = 0; k < 120; ++k) {
    const Result<render::FrameView> view = source.view(k);
    ASSERT_TRUE(view && view->texts.size() == 1u);
    if (k == 0) first = view->texts[0].text;
    EXPECT_EQ(view->texts[0].text, first) << "frame " << k;
  }
  // I = (0.417, 0.341, 0.091) kg m², ω = (0.01, 3, 0.01): E = ½ Σ I ω² = 1.533775 J.
  EXPECT_EQ(first.substr(0, first.find('|')), "1.533775");
}

}  // namespace
}  // namespace tumble::view
