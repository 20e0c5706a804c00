// `count` and `spacing` on a [[bodies]] table make the same bodies as writing each out
// (tests/cli/simulate_command_test.cpp compares their runs' CSV byte for byte).
#include "scene/body_arrays.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/scene_text.hpp"

namespace tumble::scene {
namespace {

using physics::Vec3;
using testing::parse_valid;

// Every field a body array sets or copies, compared exactly.
void expect_same_bodies(const Scene& got, const Scene& want) {
  ASSERT_EQ(got.bodies.size(), want.bodies.size());
  for (std::size_t i = 0; i < got.bodies.size(); ++i) {
    const BodySpec& a = got.bodies[i];
    const BodySpec& b = want.bodies[i];
    EXPECT_EQ(a.name, b.name) << i;
    EXPECT_EQ(a.position, b.position) << a.name;
    EXPECT_EQ(a.velocity, b.velocity) << a.name;
    EXPECT_EQ(a.orientation.coeffs(), b.orientation.coeffs()) << a.name;
    EXPECT_EQ(a.angular_velocity, b.angular_velocity) << a.name;
    EXPECT_EQ(a.color, b.color) << a.name;
    EXPECT_EQ(a.mass, b.mass) << a.name;
    EXPECT_EQ(a.size, b.size) << a.name;
    EXPECT_EQ(a.forces.size(), b.forces.size()) << a.name;
    EXPECT_EQ(a.material.friction, b.material.friction) << a.name;
  }
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

TEST(BodyArrays, ALineOfTwentyIsTwentyBodiesWrittenOut) {
  const std::string head = "duration = 1.0\n[physics]\ngravity = [0.0, -9.81, 0.0]\n";
  const std::string array = head +
                            "[[bodies]]\nname = \"row\"\nshape = \"cube\"\nsize = 0.5\nmass = 2.0\n"
                            "position = [-9.5, 1.0, 0.25]\nvelocity = [0.0, 1.0, 0.0]\n"
                            "count = 20\nspacing = [0.75, 0.0, 0.1]\n"
                            "colors = [\"#ff0000\", [0.0, 0.5, 1.0], \"#00ff00\"]\n";
  std::string written = head;
  const char* colors[] = {"\"#ff0000\"", "[0.0, 0.5, 1.0]", "\"#00ff00\""};
  for (int i = 0; i < 20; ++i) {
    const Vec3 at = Vec3(-9.5, 1.0, 0.25) + static_cast<double>(i) * Vec3(0.75, 0.0, 0.1);
    written += "[[bodies]]\nname = \"row_" + std::to_string(i) +
               "\"\nshape = \"cube\"\nsize = 0.5\nmass = 2.0\nposition = [" + number(at.x()) +
               ", " + number(at.y()) + ", " + number(at.z()) +
               "]\nvelocity = [0.0, 1.0, 0.0]\ncolor = " + colors[i % 3] + "\n";
  }
  expect_same_bodies(parse_valid(array), parse_valid(written));
}

TEST(BodyArrays, AGridNamesItsBodiesXFastestThenYThenZ) {
  const Scene scene = parse_valid(
      "duration = 1.0\n[[bodies]]\nname = \"g\"\nshape = \"cube\"\nsize = 0.5\nmass = 1.0\n"
      "count = [3, 2, 2]\nspacing = [1.0, 2.0, 4.0]\n");
  ASSERT_EQ(scene.bodies.size(), 12u);
  EXPECT_EQ(scene.bodies[0].name, "g_0");
  EXPECT_EQ(scene.bodies[0].position, Vec3(0.0, 0.0, 0.0));
  EXPECT_EQ(scene.bodies[2].position, Vec3(2.0, 0.0, 0.0));
  EXPECT_EQ(scene.bodies[3].position, Vec3(0.0, 2.0, 0.0));
  EXPECT_EQ(scene.bodies[6].position, Vec3(0.0, 0.0, 4.0));
  EXPECT_EQ(scene.bodies[11].name, "g_11");
  EXPECT_EQ(scene.bodies[11].position, Vec3(2.0, 2.0, 4.0));
}

TEST(BodyArrays, BodiesWithoutAColourTakeTheDefaultOfTheirPlaceInTheScene) {
  const Scene scene = parse_valid(
      "duration = 1.0\n[[bodies]]\nname = \"row\"\nshape = \"cube\"\nsize = 0.5\nmass = 1.0\n"
      "count = 3\nspacing = [1.0, 0.0, 0.0]\n"
      "[[bodies]]\nshape = \"cube\"\nsize = 0.5\nmass = 1.0\nposition = [0.0, 2.0, 0.0]\n");
  ASSERT_EQ(scene.bodies.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(scene.bodies[i].color, detail::default_body_color(i));
  // The body after the array is the scene's fourth: its default name says so.
  EXPECT_EQ(scene.bodies[3].name, "body3");
}

TEST(BodyArrays, AnArrayOfOneIsItsBodyRenamed) {
  const Scene scene =
      parse_valid(testing::cube_scene(1.0) + "name = \"one\"\ncount = 1\nspacing = [0, 0, 0]\n");
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.bodies[0].name, "one_0");
}

TEST(BodyArrays, AnOverlapWithinAnArrayIsBlamedOnItsSpacing) {
  EXPECT_EQ(testing::error_of(testing::cube_scene(1.0) +
                              "name = \"r\"\ncount = 2\nspacing = [0.5, 0, 0]\n"),
            "test.toml:8:11: bodies[0].spacing: bodies \"r_0\" and \"r_1\" start overlapping by "
            "0.5 m (bodies collide; give one `collide = false`, or set [physics] "
            "collide_bodies = false)");
}

}  // namespace
}  // namespace tumble::scene
