// [[overlays]] read from a scene file: every kind with every key, the defaults, and `[render]
// font`. Mistakes are covered by tests/scene/bad/overlay_*.toml (app/bad_scenes_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "scene/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tumble::scene {
namespace {

using physics::Vec3;

using testing::parse_valid;

constexpr const char* kBodies = R"(duration = 2.0
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 1.0
color = "#ff0000"
[[bodies.forces]]
kind = "gravity"
[[bodies.forces]]
kind = "spring"
anchor = [0, 2, 0]
stiffness = 10.0
[[bodies.forces]]
kind = "gravity"
[[bodies]]
name = "lid"
shape = "box"
size = [0.5, 2.0, 1.0]
mass = 1.0
position = [3, 0, 0]
)";

TEST(OverlayTables, ReadsEveryKeyOfEveryKind) {
  const Scene scene = parse_valid(std::string(kBodies) + R"(
[render]
font = "DejaVu Serif"
[[overlays]]
kind = "text"
text = "v = {lid.speed:.3f}"
anchor = "bottom-right"
offset = [-10, -20]
size = 40
color = "#102030"
background = "#00000080"
start = 0.5
end = 1.5
fade = 0.25
[[overlays]]
kind = "vector"
body = "cube"
quantity = "force"
law = "gravity"
point = [0.5, 0, 0]
scale = 0.1
color = [0, 0, 1, 0.5]
label = "mg"
[[overlays]]
kind = "vector"
body = "lid"
quantity = [0, 1, 0]
[[overlays]]
kind = "trail"
body = "lid"
point = [0.25, 1, 0.5]
length = 1.5
color = "#ffffff"
[[overlays]]
kind = "axes"
body = "cube"
length = 2.5
)");
  EXPECT_EQ(scene.font, "DejaVu Serif");
  ASSERT_EQ(scene.overlays.size(), 5u);
  const auto& text = std::get<TextOverlay>(scene.overlays[0]);
  ASSERT_EQ(text.text.values.size(), 1u);
  EXPECT_EQ(text.text.values[0].body, 1u);
  EXPECT_EQ(text.anchor, common::Anchor::kBottomRight);
  EXPECT_EQ(text.offset, Eigen::Vector2d(-10, -20));
  EXPECT_EQ(text.size, 40.0);
  EXPECT_EQ(text.color, Rgba(0x10 / 255.0, 0x20 / 255.0, 0x30 / 255.0, 1.0));
  ASSERT_TRUE(text.background);
  EXPECT_EQ(*text.background, Rgba(0, 0, 0, 0x80 / 255.0));
  EXPECT_EQ(text.start, 0.5);
  EXPECT_EQ(text.end, 1.5);
  EXPECT_EQ(text.fade, 0.25);
  const auto& force = std::get<VectorOverlay>(scene.overlays[1]);
  EXPECT_EQ(force.body, 0u);
  EXPECT_EQ(force.quantity, VectorQuantity::force);
  EXPECT_EQ(force.laws, (std::vector<std::size_t>{0, 2}));  // both gravity laws, not the spring
  EXPECT_EQ(force.point, Vec3(0.5, 0, 0));
  EXPECT_EQ(force.scale, 0.1);
  EXPECT_EQ(force.color, Rgba(0, 0, 1, 0.5));
  EXPECT_EQ(force.label, "mg");
  const auto& constant = std::get<VectorOverlay>(scene.overlays[2]);
  EXPECT_EQ(constant.quantity, VectorQuantity::constant);
  EXPECT_EQ(constant.constant, Vec3(0, 1, 0));
  const auto& trail = std::get<TrailOverlay>(scene.overlays[3]);
  EXPECT_EQ(trail.body, 1u);
  EXPECT_EQ(trail.point, Vec3(0.25, 1, 0.5));
  EXPECT_EQ(trail.length, 1.5);
  EXPECT_EQ(trail.color, Rgba(1, 1, 1, 1));
  EXPECT_EQ(std::get<AxesOverlay>(scene.overlays[4]).length, 2.5);
}

TEST(OverlayTables, DefaultsAreDocumented) {
  const Scene scene = parse_valid(std::string(kBodies) + R"(
[[overlays]]
kind = "text"
text = "title"
anchor = "bottom"
[[overlays]]
kind = "vector"
body = "cube"
quantity = "force"
[[overlays]]
kind = "trail"
body = "cube"
[[overlays]]
kind = "axes"
body = "lid"
)");
  EXPECT_EQ(scene.font, "");
  ASSERT_EQ(scene.overlays.size(), 4u);
  const auto& text = std::get<TextOverlay>(scene.overlays[0]);
  EXPECT_EQ(text.offset, Eigen::Vector2d(0, -24));  // 24 px in from the bottom edge
  EXPECT_EQ(text.size, 28.0);
  EXPECT_EQ(text.color, Rgba(1, 1, 1, 1));
  EXPECT_FALSE(text.background);
  EXPECT_EQ(text.start, 0.0);
  EXPECT_TRUE(std::isinf(text.end));
  EXPECT_EQ(text.fade, 0.0);
  const auto& force = std::get<VectorOverlay>(scene.overlays[1]);
  EXPECT_EQ(force.laws, (std::vector<std::size_t>{0, 1, 2}));  // every law of the body
  EXPECT_EQ(force.point, Vec3::Zero());
  EXPECT_EQ(force.scale, 1.0);
  EXPECT_EQ(force.label, "");
  const auto& trail = std::get<TrailOverlay>(scene.overlays[2]);
  EXPECT_EQ(trail.point, Vec3::Zero());
  EXPECT_EQ(trail.length, 2.0);
  EXPECT_EQ(trail.color, Rgba(1, 0, 0, 1));                         // the body's colour
  EXPECT_EQ(std::get<AxesOverlay>(scene.overlays[3]).length, 2.0);  // the longest edge
}

TEST(OverlayTables, ASceneWithoutOverlaysHasNone) {
  EXPECT_TRUE(parse_valid(kBodies).overlays.empty());
}

}  // namespace
}  // namespace tumble::scene
