// A scene's [[overlays]] from file to picture: golden frames of each kind at 320×180 and
// 1280×720 (a text with ω, τ, Δ, ² and live values; a labelled vector; a trail; axes), texts
// fading in and out, trails of a chunk that starts late the same as the whole render's, and
// warnings for characters the font lacks. Goldens live in tests/render/golden/
// (TUMBLE_UPDATE_GOLDEN=1 rewrites them: look at them before committing).
#include "view/overlay_view.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <variant>

#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "support/render_golden.hpp"
#include "view/scene_view.hpp"

namespace tumble::view {
namespace {

// A cube tossed up and spun about a tilted axis under gravity, the camera given (no framing
// pass), the ground's grid and shadows on: what a documentation video looks like, drawn in the
// plain look its goldens were drawn in (parse() sets it).
constexpr const char* kScene = R"(name = "overlays"
duration = 2.0
[physics]
dt = 0.005
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 2.0
velocity = [1.0, 3.0, 0.0]
angular_velocity = [1.0, 3.0, 0.5]
[[bodies.forces]]
kind = "gravity"
[camera]
position = [3.0, 3.0, 7.0]
look_at = [0.8, 0.6, 0.0]
[ground]
height = -1.0
)";

scene::Scene parse(const std::string& overlays) {
  Result<scene::Scene> result = scene::parse_scene(std::string(kScene) + overlays, "test.toml");
  if (!result) {
    ADD_FAILURE() << result.error();
    return {};
  }
  scene::Scene scene = std::move(result).value();
  scene.render.look = common::Look::plain();
  return scene;
}

// Frame `frame` of the scene at width × height, drawn as `tumble render` draws it (render_job).
io::Image render_frame(scene::Scene scene, int width, int height, std::int64_t frame) {
  scene.render.width = width;
  scene.render.height = height;
  const Result<Framing> framing = frame_scene(scene, 120, [] { return false; });
  EXPECT_TRUE(framing) << (framing ? "" : framing.error());
  if (!framing) return {};
  const render::RenderSettings settings = renderer_settings(scene, *framing);
  SimulatedFrames source(scene, *framing, [] { return false; });
  const Result<render::FrameView> view = source.view(frame);
  EXPECT_TRUE(view) << (view ? "" : view.error());
  return view ? testing::draw(settings, *view) : io::Image{};
}

// As the text goldens (render/text_layer_test.cpp): 8 of 255 per channel, and 1% of the pixels
// beyond that, for another Mesa, LLVM or FreeType rounding an edge otherwise. Same machine:
// bit-identical (the frame pipeline's serial twin checks that).
void expect_golden(const std::string& overlays, const std::string& name, std::int64_t frame = 30) {
  const scene::Scene scene = parse(overlays);
  for (const auto& [width, height] : {std::pair{320, 180}, std::pair{1280, 720}}) {
    const io::Image image = render_frame(scene, width, height, frame);
    testing::expect_matches_golden(
        image, name + "_" + std::to_string(width) + "x" + std::to_string(height),
        {.threshold = 8, .max_pixels = static_cast<std::int64_t>(width) * height / 100});
  }
}

TEST(OverlayView, TextWithSymbolsAndLiveValuesMatchesGolden) {
  expect_golden(R"(
[[overlays]]
kind = "text"
text = "ω = {cube.angular_speed:.2f} rad/s   τ = 0 N·m\nΔt = {time:.2f} s   v² = {cube.speed:.1f}² m²/s²"
background = "#00000080"
[[overlays]]
kind = "text"
text = "frame {frame}: x = {cube.position.x:.3f} m"
anchor = "bottom-right"
size = 32
color = "#102040"
)",
                "overlay_text");
}

TEST(OverlayView, VectorWithLabelMatchesGolden) {
  expect_golden(R"(
[[overlays]]
kind = "vector"
body = "cube"
quantity = "angular_velocity"
scale = 0.5
label = "ω"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "velocity"
point = [0.5, 0.5, 0.5]
scale = 0.4
label = "v"
)",
                "overlay_vector");
}

TEST(OverlayView, TrailMatchesGolden) {
  expect_golden(R"(
[[overlays]]
kind = "trail"
body = "cube"
point = [0.5, 0.5, 0.5]
length = 0.75
color = "#2040ff"
)",
                "overlay_trail", 45);  // t = 0.75 s: the whole flight from the throw
}

TEST(OverlayView, AxesMatchGolden) {
  expect_golden(R"(
[[overlays]]
kind = "axes"
body = "cube"
)",
                "overlay_axes");
}

// A chunk from frame 40 (`--frames 40:`) draws frame 40's trail as the whole render does: the
// trail's past is recorded before the first frame.
TEST(OverlayView, AChunkDrawsTheTrailOfTheWholeRender) {
  const scene::Scene scene = parse(R"(
[[overlays]]
kind = "trail"
body = "cube"
point = [0.5, 0.5, 0.5]
length = 0.5
)");
  const Result<Framing> framing = frame_scene(scene, 120, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames whole(scene, *framing, [] { return false; });
  SimulatedFrames chunk(scene, *framing, [] { return false; });
  for (std::int64_t k = 0; k < 40; ++k) ASSERT_TRUE(whole.view(k));
  // As a chunk's render runs it: the physics first, without drawing, to the trail's oldest point.
  const Result<std::int64_t> steps = chunk.seek(40);
  ASSERT_TRUE(steps);
  // 0.5 s at 60 fps before frame 40 is frame 10: the first step at or past 1/6 s, dt 0.005 s.
  EXPECT_EQ(*steps, 34);
  EXPECT_EQ(chunk.simulation().step_count(), 34);
  for (const std::int64_t k : {40, 41}) {
    const Result<render::FrameView> a = whole.view(k), b = chunk.view(k);
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->lines.size(), 1u);
    ASSERT_EQ(b->lines.size(), 1u);
    EXPECT_EQ(a->lines[0].points.size(), 31u);  // 0.5 s at 60 fps, both ends kept
    EXPECT_EQ(a->lines[0].points, b->lines[0].points) << "frame " << k;
    EXPECT_EQ(a->lines[0].opacity, b->lines[0].opacity) << "frame " << k;
    EXPECT_EQ(a->lines[0].opacity.back(), 1.0);
    EXPECT_EQ(a->lines[0].opacity.front(), 0.0);
  }
}

// start 0.5 s, end 1.5 s, fade 0.25 s, at 60 fps: nothing before 0.5 s, 0.4 at 0.6 s (0.1 s
// into the fade in), whole at 1.0 s, 0.4 at 1.4 s, nothing from 1.5 s.
TEST(OverlayView, TextsShowFromStartToEndFadingInAndOut) {
  const scene::Scene scene = parse(R"(
[[overlays]]
kind = "text"
text = "caption"
start = 0.5
end = 1.5
fade = 0.25
)");
  const Result<Framing> framing = frame_scene(scene, 120, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames source(scene, *framing, [] { return false; });
  const auto opacity_at = [&](std::int64_t frame) {
    const Result<render::FrameView> view = source.view(frame);
    EXPECT_TRUE(view);
    return view && !view->texts.empty() ? view->texts[0].opacity : 0.0;
  };
  EXPECT_EQ(opacity_at(29), 0.0);                  // 0.483 s
  EXPECT_EQ(opacity_at(30), 0.0);                  // 0.5 s: starts, fully faded
  EXPECT_NEAR(opacity_at(36), 0.1 / 0.25, 1e-12);  // 0.6 s
  EXPECT_EQ(opacity_at(60), 1.0);                  // 1.0 s
  EXPECT_NEAR(opacity_at(84), 0.1 / 0.25, 1e-12);  // 1.4 s
  EXPECT_EQ(opacity_at(90), 0.0);                  // 1.5 s: ended
}

TEST(OverlayView, WarnsOfEachCharacterTheFontLacksAndNoneOfThePhysicsSymbols) {
  const scene::Scene scene = parse(R"(
[[overlays]]
kind = "text"
text = "ω τ θ Δ ² · → ≈ ° {time} 中"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "velocity"
label = "v中"
)");
  Result<std::unique_ptr<render::Font>> font = render::Font::open(overlay_font(scene));
  ASSERT_TRUE(font) << font.error();
  const std::vector<std::string> warnings = missing_character_warnings(scene, font->get());
  ASSERT_EQ(warnings.size(), 1u);  // 中 once, though written twice
  EXPECT_NE(warnings[0].find("U+4E2D"), std::string::npos) << warnings[0];
  EXPECT_TRUE(missing_character_warnings(scene, nullptr).empty());
}

// Axes, vectors and trails on every shape: a ball, a capsule, a cylinder and a hull (a
// tetrahedron turned 30° about z, its points' centre of mass at (1/4, 1/4, 1/4) of their frame),
// spinning in place with no gravity. At the start each body's axes start at its centre; a vector
// or trail without `point` starts at the centre of mass, and one with a `point` on the hull starts
// where that point of the hull's own frame is, `position` + R (p − c), within 1e-12 m.
TEST(OverlayView, AxesVectorsAndTrailsWorkOnEveryShape) {
  using physics::Vec3;
  const std::string text = R"(name = "shapes"
duration = 1.0
[physics]
dt = 0.01
[[bodies]]
name = "ball"
shape = "sphere"
radius = 0.3
mass = 1.0
position = [-3.0, 0.0, 0.0]
angular_velocity = [0.0, 1.0, 0.0]
[[bodies]]
name = "capsule"
shape = "capsule"
radius = 0.2
length = 0.6
mass = 1.0
position = [-1.0, 0.0, 0.0]
angular_velocity = [0.0, 1.0, 0.0]
[[bodies]]
name = "cylinder"
shape = "cylinder"
radius = 0.3
length = 0.4
mass = 1.0
position = [1.0, 0.0, 0.0]
angular_velocity = [0.0, 1.0, 0.0]
[[bodies]]
name = "hull"
shape = "hull"
points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
mass = 1.0
position = [3.0, 0.0, 0.0]
orientation = [0.9659258262890683, 0.0, 0.0, 0.25881904510252074]
angular_velocity = [0.0, 1.0, 0.0]
[camera]
position = [0.0, 2.0, 9.0]
look_at = [0.0, 0.0, 0.0]
)";
  std::string overlays;
  for (const char* body : {"ball", "capsule", "cylinder", "hull"}) {
    overlays += std::string("[[overlays]]\nkind = \"axes\"\nbody = \"") + body + "\"\n";
    overlays += std::string("[[overlays]]\nkind = \"vector\"\nbody = \"") + body +
                "\"\nquantity = \"angular_velocity\"\n";
    overlays += std::string("[[overlays]]\nkind = \"trail\"\nbody = \"") + body + "\"\n";
  }
  overlays +=
      "[[overlays]]\nkind = \"vector\"\nbody = \"hull\"\nquantity = \"velocity\"\n"
      "point = [1.0, 0.0, 0.0]\n";
  overlays += "[[overlays]]\nkind = \"trail\"\nbody = \"hull\"\npoint = [1.0, 0.0, 0.0]\n";
  Result<scene::Scene> parsed = scene::parse_scene(text + overlays, "shapes.toml");
  ASSERT_TRUE(parsed) << parsed.error();
  const scene::Scene& scene = *parsed;
  const Result<Framing> framing = frame_scene(scene, 120, [] { return false; });
  ASSERT_TRUE(framing) << (framing ? "" : framing.error());
  SimulatedFrames source(scene, *framing, [] { return false; });
  const Result<render::FrameView> view = source.view(0);
  ASSERT_TRUE(view) << (view ? "" : view.error());
  // Per body: three axes and one ω vector; then the hull's v at its corner.
  ASSERT_EQ(view->arrows.size(), 4u * 4u + 1u);
  const std::array<double, 4> x{-3.0, -1.0, 1.0, 3.0};
  for (std::size_t body = 0; body < 4; ++body) {
    for (std::size_t k = 0; k < 4; ++k) {
      const render::Arrow& arrow = view->arrows[4 * body + k];
      EXPECT_NEAR((arrow.from - Vec3(x[body], 0.0, 0.0)).norm(), 0.0, 1e-12)
          << "body " << body << " arrow " << k;
    }
    // ω along +y, 1 m long at scale 1.
    EXPECT_NEAR((view->arrows[4 * body + 3].to - Vec3(x[body], 1.0, 0.0)).norm(), 0.0, 1e-12);
  }
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond(0.9659258262890683, 0.0, 0.0, 0.25881904510252074).toRotationMatrix();
  const Vec3 corner = Vec3(3.0, 0.0, 0.0) + turn * (Vec3(1.0, 0.0, 0.0) - Vec3::Constant(0.25));
  EXPECT_NEAR((view->arrows.back().from - corner).norm(), 0.0, 1e-12);
  ASSERT_EQ(view->lines.size(), 5u);
  for (std::size_t body = 0; body < 4; ++body) {
    ASSERT_FALSE(view->lines[body].points.empty());
    EXPECT_NEAR((view->lines[body].points.back() - Vec3(x[body], 0.0, 0.0)).norm(), 0.0, 1e-12);
  }
  EXPECT_NEAR((view->lines[4].points.back() - corner).norm(), 0.0, 1e-12);
}

TEST(OverlayView, OnlyWhatTheOverlaysDrawIsSetUp) {
  EXPECT_FALSE(overlays_need_font(parse("")));
  EXPECT_FALSE(overlays_need_lines(parse("")));
  const scene::Scene axes = parse("[[overlays]]\nkind = \"axes\"\nbody = \"cube\"\n");
  EXPECT_FALSE(overlays_need_font(axes));
  EXPECT_TRUE(overlays_need_lines(axes));
  const scene::Scene text = parse(
      "[render]\nfont = \"DejaVu Serif\"\n[[overlays]]\nkind = "
      "\"text\"\ntext = \"t\"\n");
  EXPECT_TRUE(overlays_need_font(text));
  EXPECT_FALSE(overlays_need_lines(text));
  EXPECT_EQ(overlay_font(text), "DejaVu Serif");
  EXPECT_EQ(overlay_font(axes), render::kDefaultFontFamily);
}

// A 1 kg cube resting on the floor (impulse contact): the contact force arrow points up with
// length m g × scale within 1 %, from the centre of its bottom face. (With penalty contact the
// cube rings on its corner springs: not at rest.)
TEST(OverlayView, AContactForceArrowOnARestingCubeIsItsWeightUp) {
  for (const char* method : {"impulse"}) {
    const std::string text = std::string(R"(name = "resting"
duration = 2.0
[physics]
dt = 0.005
contact = ")") + method + R"("
gravity = [0, -9.81, 0]
[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 1.0
position = [0, 0.5, 0]
[camera]
position = [3, 3, 7]
look_at = [0, 0.5, 0]
[[overlays]]
kind = "vector"
body = "cube"
quantity = "contact_force"
scale = 0.1
)";
    const Result<scene::Scene> loaded = scene::parse_scene(text, "resting.toml");
    ASSERT_TRUE(loaded) << loaded.error();
    const Result<Framing> framing = frame_scene(*loaded, 60, [] { return false; });
    ASSERT_TRUE(framing);
    SimulatedFrames source(*loaded, *framing, [] { return false; });
    for (const std::int64_t frame : {30, 45, 59}) {
      const Result<render::FrameView> view = source.view(frame);
      ASSERT_TRUE(view && view->arrows.size() == 1u) << method;
      const physics::Vec3 arrow = view->arrows[0].to - view->arrows[0].from;
      EXPECT_NEAR(arrow.y(), 0.981, 0.01 * 0.981) << method << " frame " << frame;
      EXPECT_NEAR(arrow.x(), 0.0, 1e-3 * 0.981) << method;
      EXPECT_NEAR(arrow.z(), 0.0, 1e-3 * 0.981) << method;
      if (std::string(method) == "impulse") {  // its contact points: the bottom face's corners
        EXPECT_NEAR(view->arrows[0].from.y(), 0.0, 0.01) << "frame " << frame;
        EXPECT_NEAR(view->arrows[0].from.x(), 0.0, 1e-6);
        EXPECT_NEAR(view->arrows[0].from.z(), 0.0, 1e-6);
      }
    }
  }
}

// A cube tossed up and falling (no plane to touch) has no contact: its contact force is exactly
// zero, so the renderer draws no arrow (too short to read), where the momentum balance alone
// would leave a rounding's worth.
TEST(OverlayView, ABodyInTheAirHasNoContactForce) {
  const scene::Scene scene = parse(R"(
[[overlays]]
kind = "vector"
body = "cube"
quantity = "contact_force"
label = "contact"
)");
  const Result<Framing> framing = frame_scene(scene, 60, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames source(scene, *framing, [] { return false; });
  for (const std::int64_t frame : {5, 10, 20}) {
    const Result<render::FrameView> view = source.view(frame);
    ASSERT_TRUE(view && view->arrows.size() == 1u);
    EXPECT_EQ(view->arrows[0].to, view->arrows[0].from) << "frame " << frame;
  }
}

// A torque arrow is the torque of the body's force laws about its centre: a push of 2 N along z
// at (1, 0, 0) of the body turns it about -y with 2 N m.
TEST(OverlayView, ATorqueArrowIsTheTorqueOfTheLaws) {
  const scene::Scene scene = parse(R"(
[[bodies.forces]]
kind = "force_at_point"
force = [0, 0, 2]
point = [1, 0, 0]
[[overlays]]
kind = "vector"
body = "cube"
quantity = "torque"
law = "force_at_point"
scale = 1.0
)");
  const Result<Framing> framing = frame_scene(scene, 1, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames source(scene, *framing, [] { return false; });
  const Result<render::FrameView> view = source.view(0);
  ASSERT_TRUE(view && view->arrows.size() == 1u);
  const physics::Vec3 torque = view->arrows[0].to - view->arrows[0].from;
  EXPECT_TRUE(torque.isApprox(physics::Vec3(0, -2, 0), 1e-12)) << torque.transpose();
}

// A text with `body` is a label at the body's point (offset kept), not a text at an anchor.
TEST(OverlayView, ATextThatFollowsABodyIsALabelAtItsPoint) {
  const scene::Scene scene = parse(R"(
[[overlays]]
kind = "text"
text = "cube {cube.speed:.1f} m/s"
body = "cube"
point = [0.0, 0.5, 0.0]
offset = [4, -10]
background = "#00000080"
)");
  const Result<Framing> framing = frame_scene(scene, 60, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames source(scene, *framing, [] { return false; });
  const Result<render::FrameView> view = source.view(0);
  ASSERT_TRUE(view);
  EXPECT_TRUE(view->texts.empty());
  ASSERT_EQ(view->labels.size(), 1u);
  EXPECT_EQ(view->labels[0].text, "cube 3.2 m/s");                           // |(1, 3, 0)| = 3.16
  EXPECT_TRUE(view->labels[0].position.isApprox(physics::Vec3(0, 0.5, 0)));  // starts at 0
  EXPECT_EQ(view->labels[0].offset, Eigen::Vector2d(4, -10));
  EXPECT_TRUE(view->labels[0].background.has_value());
}

// The vectors' default colours are none of the axes' red, green and blue, nor near each other.
TEST(OverlayView, DefaultVectorColoursAreNotTheAxesColours) {
  const scene::Scene scene = parse(R"(
[[bodies.forces]]
kind = "force"
force = [0, 0, 1]
[[overlays]]
kind = "axes"
body = "cube"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "velocity"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "angular_velocity"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "angular_momentum"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "force"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "contact_force"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "torque"
)");
  std::vector<render::Rgba> axes, vectors;
  for (const scene::OverlaySpec& overlay : scene.overlays) {
    if (const auto* vector = std::get_if<scene::VectorOverlay>(&overlay)) {
      vectors.push_back(vector->color);
    }
  }
  const Result<Framing> framing = frame_scene(scene, 1, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames source(scene, *framing, [] { return false; });
  const Result<render::FrameView> view = source.view(0);
  ASSERT_TRUE(view && view->arrows.size() >= 3u);
  for (int i = 0; i < 3; ++i) axes.push_back(view->arrows[static_cast<std::size_t>(i)].color);
  ASSERT_EQ(vectors.size(), 6u);
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    for (const render::Rgba& axis : axes) {
      EXPECT_GT((vectors[i] - axis).head<3>().norm(), 0.35) << "vector " << i;
    }
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_GT((vectors[i] - vectors[j]).head<3>().norm(), 0.3) << i << " and " << j;
    }
  }
}

}  // namespace
}  // namespace tumble::view
