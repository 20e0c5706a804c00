// End-to-end tests of `tumble check` and of the same stability warnings from `tumble simulate`.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;

using tumble::testing::Outcome;

class CheckCommand : public tumble::testing::CommandTest {};

// A 2 kg cube in linear damping 600 N s/m: k = 300 /s, and k dt = 2.5 with explicit Euler.
constexpr const char* kStiffScene = R"(duration = 1.0
[physics]
dt = 0.008333333333333333
integrator = "euler"
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 2.0
velocity = [1.0, 0.0, 0.0]
[[bodies.forces]]
kind = "linear_damping"
coefficient = 600.0
)";

TEST_F(CheckCommand, EveryExampleSceneIsValidWithoutWarnings) {
  for (const auto& entry : fs::directory_iterator(fs::path(TUMBLE_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".toml") continue;  // scenes/models holds their meshes
    const Outcome run = tumble("check " + entry.path().string());
    EXPECT_EQ(run.exit_code, 0) << entry.path() << run.err;
    EXPECT_NE(run.out.find(": valid: "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("; 0 warnings"), std::string::npos) << run.out;
    EXPECT_EQ(run.err, "");
  }
}

// A cube over a floor with no gravity: check says so, and is quiet once [physics] gravity is given.
TEST_F(CheckCommand, WarnsOfABodyAboveAFloorThatNoGravityPullsDown) {
  const std::string bodies =
      "[[planes]]\nname = \"floor\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 1.0, "
      "0.0]\n[[bodies]]\nname = \"cube\"\nshape = \"cube\"\n"
      "size = 1.0\nmass = 1.0\nposition = [0.0, 2.0, 0.0]\n";
  const Outcome floating =
      tumble("check " + write("floating.toml", "duration = 1.0\n" + bodies).string());
  EXPECT_EQ(floating.exit_code, 0) << floating.err;
  EXPECT_NE(floating.out.find("tumble: warning: body \"cube\": no gravity acts, yet a floor (a "
                              "plane facing up) lies below, which nothing will ever bring it down "
                              "to; if it should fall, add [physics] gravity = [0, -9.81, 0]\n"),
            std::string::npos)
      << floating.out;
  EXPECT_NE(floating.out.find("; 1 warning\n"), std::string::npos) << floating.out;
  const Outcome falling =
      tumble("check " + write("falling.toml",
                              "duration = 1.0\n[physics]\ngravity = [0.0, -9.81, 0.0]\n" + bodies)
                            .string());
  EXPECT_EQ(falling.exit_code, 0) << falling.err;
  EXPECT_NE(falling.out.find("; 0 warnings\n"), std::string::npos) << falling.out;
}

// A hull of a 100-gon prism has 200 corners: tumble keeps 64, and says so.
TEST_F(CheckCommand, SaysAHullOfManyCornersIsReduced) {
  std::string text =
      "duration = 1.0\n[[bodies]]\nname = \"drum\"\nshape = \"hull\"\nmass = 1.0\n"
      "points = [";
  for (int k = 0; k < 100; ++k) {
    const double angle = 2.0 * 3.141592653589793 * k / 100.0;
    for (const double y : {-0.2, 0.2}) {
      text += (k > 0 || y > 0.0 ? ", [" : "[") + std::to_string(std::cos(angle)) + ", " +
              std::to_string(y) + ", " + std::to_string(std::sin(angle)) + "]";
    }
  }
  text += "]\n";
  const Outcome run = tumble("check " + write("drum.toml", text).string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("tumble: warning: body \"drum\": the hull of its points has 200 corners; "
                         "tumble keeps 64 of them (picked farthest first)"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("; 1 warning\n"), std::string::npos) << run.out;
}

TEST_F(CheckCommand, PrintsTheWarningsOfAValidSceneAndExitsZero) {
  const fs::path scene = write("stiff.toml", kStiffScene);
  const Outcome run = tumble("check " + scene.string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("tumble: warning: body \"cube\": linear damping makes the momentum "
                         "decay at k = c/m = 300 /s: k·dt = 2.5 is beyond euler's stability "
                         "limit k·dt <= 2, so the motion will blow up; use dt <= 0.00533 s"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("valid: 1 body, 120 steps of 0.00833333 s with euler; 1 warning\n"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(run.err, "");
}

// A scene with joints says how many it holds beside its bodies.
TEST_F(CheckCommand, CountsTheJoints) {
  const Outcome run = tumble("check " + std::string(TUMBLE_SOURCE_DIR) + "/scenes/chain.toml");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("valid: 30 bodies and 30 joints, 1920 steps of 0.00416667 s with rk4; "
                         "0 warnings\n"),
            std::string::npos)
      << run.out;
}

// A 100 kg cube on a column of thirteen 1 kg cubes on the floor: 56 contact points, solved one at
// a time, beyond the mass ratio that solver holds (a top 50 times as heavy collapses the column).
// Two cubes alone are one block and hold it: no warning.
TEST_F(CheckCommand, NamesTheBodiesOfAMassRatioTheContactCannotHold) {
  const auto scene_of = [](int light_cubes) {
    std::string text =
        "duration = 1.0\n[[planes]]\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 1.0, 0.0]\n";
    for (int i = 0; i <= light_cubes; ++i) {
      const bool top = i == light_cubes;
      text += "[[bodies]]\nname = \"" + (top ? std::string("heavy") : "cube" + std::to_string(i)) +
              "\"\nshape = \"cube\"\nsize = 1.0\nmass = " + (top ? "100.0" : "1.0") +
              "\nposition = [0.0, " + std::to_string(0.5 + i) +
              ", 0.0]\n[[bodies.forces]]\nkind = \"gravity\"\n";
    }
    return text;
  };
  const Outcome run = tumble("check " + write("ratio.toml", scene_of(13)).string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("tumble: warning: bodies \"cube12\" and \"heavy\": touch with a mass "
                         "ratio of 100 (100 kg on 1 kg) in a group of touching bodies with more "
                         "than 48 contact points"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("; 1 warning\n"), std::string::npos) << run.out;
  const Outcome pair = tumble("check " + write("pair.toml", scene_of(1)).string());
  EXPECT_EQ(pair.exit_code, 0) << pair.err;
  EXPECT_NE(pair.out.find("; 0 warnings\n"), std::string::npos) << pair.out;
}

TEST_F(CheckCommand, AnInvalidSceneExitsTwoWithItsLocation) {
  const fs::path scene =
      write("bad.toml", "duration = 1.0\n[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = -1.0\n");
  const Outcome run = tumble("check " + scene.string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.toml:5:8: bodies[0].mass: must be greater than 0"), std::string::npos)
      << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(tumble("check " + path("absent.toml")).exit_code, 2);
}

TEST_F(CheckCommand, SimulatePrintsTheSameWarningsThenStopsWhereTheBodyBlowsUp) {
  const fs::path scene = write("stiff.toml", kStiffScene);
  const Outcome run = tumble("simulate " + scene.string() + " --every 1000");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err.rfind("tumble: warning: body \"cube\": linear damping makes the momentum", 0),
            0u)
      << run.err;
  // The warning was right: k dt = 2.5 makes euler's velocity grow by 1.5 a step.
  EXPECT_NE(run.err.find("tumble: body \"cube\" blew up at t = "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("Likely cause: linear damping"), std::string::npos) << run.err;
  EXPECT_EQ(run.out.rfind("t,body,x,y,z,", 0), 0u);  // the CSV is untouched on standard output
}

}  // namespace
