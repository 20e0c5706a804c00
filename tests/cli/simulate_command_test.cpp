// End-to-end tests of `tumble simulate`, run as a separate process the way users run it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;

using tumble::testing::Outcome;
using tumble::testing::read_file;

class SimulateCommand : public tumble::testing::CommandTest {};

std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// A unit cube (I = 1/6) under a constant torque about z: L = τ t exactly at every step.
constexpr const char* kTorqueScene = R"(duration = 1.0
[physics]
dt = 0.1
integrator = "rk4"
[[bodies]]
name = "spun"
shape = "cube"
size = 1.0
mass = 1.0
[[bodies.forces]]
kind = "torque"
torque = [0.0, 0.0, 2.0]
)";

TEST_F(SimulateCommand, RunningTheDefaultSceneTwiceGivesByteIdenticalCsv) {
  const std::string scene = std::string(TUMBLE_SOURCE_DIR) + "/scenes/spinning_cube.toml";
  ASSERT_EQ(tumble("simulate " + scene + " --out " + (dir_ / "a.csv").string()).exit_code, 0);
  ASSERT_EQ(tumble("simulate " + scene + " --out " + (dir_ / "b.csv").string()).exit_code, 0);
  const std::string a = read_file(dir_ / "a.csv");
  EXPECT_EQ(parse_csv(a).size(), 1u + 2001u);  // header, t = 0, then 2000 steps of 0.01 s
  EXPECT_EQ(a, read_file(dir_ / "b.csv"));
  // And standard output carries the same bytes.
  EXPECT_EQ(tumble("simulate " + scene).out, a);
}

TEST_F(SimulateCommand, WritesAHeaderAndRowsAtZeroEveryNStepsAndTheLastStep) {
  const fs::path scene = write("torque.toml", kTorqueScene);
  const Outcome run = tumble("simulate " + scene.string() + " --every 3");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto rows = parse_csv(run.out);
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(run.out.substr(0, run.out.find('\n')),
            "t,body,x,y,z,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz,px,py,pz,Lx,Ly,Lz,energy");
  const int steps[] = {0, 3, 6, 9, 10};
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), 22u);
    const double t = std::stod(rows[r][0]);
    EXPECT_EQ(t, steps[r - 1] * 0.1);  // %.17g round-trips the double exactly
    EXPECT_EQ(rows[r][1], "spun");
    EXPECT_NEAR(std::stod(rows[r][20]), 2.0 * t, 1e-12);                   // Lz = τ t
    EXPECT_NEAR(std::stod(rows[r][14]), 12.0 * t, 1e-12);                  // wz = L / I
    EXPECT_NEAR(std::stod(rows[r][21]), 0.5 * 2.0 * t * 12.0 * t, 1e-10);  // ½ L ω
  }
}

TEST_F(SimulateCommand, ABadSceneExitsWithTwoNamesTheLineAndWritesNothing) {
  std::string text = kTorqueScene;
  text.replace(text.find("mass = 1.0"), 10, "mass = -1.0");
  const fs::path scene = write("bad.toml", text);
  const Outcome run =
      tumble("simulate " + scene.string() + " --out " + (dir_ / "out.csv").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.toml:9:8: bodies[0].mass: must be greater than 0"), std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.csv"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()),
            1);  // bad.toml only
}

TEST_F(SimulateCommand, AMissingOutputFolderIsAClearError) {
  const fs::path scene = write("torque.toml", kTorqueScene);
  const Outcome run =
      tumble("simulate " + scene.string() + " --out " + (dir_ / "no/such/out.csv").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no/such/out.csv"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("No such file or directory"), std::string::npos) << run.err;
}

TEST_F(SimulateCommand, AMissingSceneFileIsAClearError) {
  const Outcome run = tumble("simulate " + (dir_ / "absent.toml").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("absent.toml: cannot open scene file"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty());
}

TEST_F(SimulateCommand, BadUsageExitsWithTwo) {
  EXPECT_EQ(tumble("").exit_code, 2);
  EXPECT_EQ(tumble("simulate").exit_code, 2);
  EXPECT_EQ(tumble("simulate x.toml --every 0").exit_code, 2);
  EXPECT_EQ(tumble("frobnicate").exit_code, 2);
}

// Scenes without planes run the code they ran before contact existed: their CSVs are the bytes
// recorded then (tests/data/before_contact/, written by the last release without contact).
class ShippedSceneWithoutPlanes : public tumble::testing::CommandTest,
                                  public ::testing::WithParamInterface<std::string> {};

TEST_P(ShippedSceneWithoutPlanes, GivesTheCsvRecordedBeforeContact) {
  const std::string source = TUMBLE_SOURCE_DIR;
  const Outcome run =
      tumble("simulate " + source + "/scenes/" + GetParam() + ".toml --out " + path("now.csv"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string recorded =
      read_file(source + "/tests/data/before_contact/" + GetParam() + ".csv");
  ASSERT_FALSE(recorded.empty());
  EXPECT_TRUE(read_file(path("now.csv")) == recorded) << "the CSV of " << GetParam() << " changed";
}

// The 64-bit FNV-1a digest of `bytes`, and their count, as "<count> <16 hex digits>".
std::string fnv1a_digest(const std::string& bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  char text[64];
  std::snprintf(text, sizeof text, "%zu %016llx", bytes.size(),
                static_cast<unsigned long long>(hash));
  return text;
}

// 400 boxes spinning 2 m apart, colliding by default but never touching: the CSV (15 MB, so only
// its digest is kept) is the one the last release before contact wrote.
TEST_F(SimulateCommand, FourHundredSeparateBoxesGiveTheCsvRecordedBeforeContact) {
  const std::string source = TUMBLE_SOURCE_DIR;
  const Outcome run =
      tumble("simulate " + source + "/tests/data/four_hundred_boxes.toml --out " + path("now.csv"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::string recorded = read_file(source + "/tests/data/before_contact/four_hundred_boxes.fnv1a");
  while (!recorded.empty() && recorded.back() == '\n') recorded.pop_back();
  EXPECT_EQ(fnv1a_digest(read_file(path("now.csv"))), recorded);
}

// scenes/tower.toml gives gravity once in [physics]; tests/data/tower_per_body_gravity.toml is the
// same scene with a gravity law on each of its eleven bodies, as it was written before.
TEST_F(SimulateCommand, PhysicsGravityGivesTheCsvOfAGravityLawOnEachBody) {
  const std::string source = TUMBLE_SOURCE_DIR;
  ASSERT_NE(read_file(source + "/scenes/tower.toml").find("\ngravity = [0.0, -9.81, 0.0]"),
            std::string::npos);
  const Outcome once = tumble("simulate " + source + "/scenes/tower.toml --out " + path("a.csv"));
  ASSERT_EQ(once.exit_code, 0) << once.err;
  const Outcome each = tumble("simulate " + source +
                              "/tests/data/tower_per_body_gravity.toml --out " + path("b.csv"));
  ASSERT_EQ(each.exit_code, 0) << each.err;
  const std::string a = read_file(path("a.csv"));
  EXPECT_EQ(parse_csv(a).size(), 1u + 11u * 361u);  // header, then 11 bodies at 361 times
  EXPECT_TRUE(a == read_file(path("b.csv")));       // not EXPECT_EQ: 1.3 MB each
}

// A body array of 20 boxes falling onto a floor and each other, against the same 20 written out.
TEST_F(SimulateCommand, ABodyArrayOfTwentyGivesTheCsvOfTwentyBodiesWrittenOut) {
  const std::string head =
      "duration = 1.5\n[physics]\ngravity = [0.0, -9.81, 0.0]\n"
      "[[planes]]\nname = \"floor\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 1.0, "
      "0.0]\nrestitution = 0.3\n";
  const std::string body =
      "shape = \"box\"\nsize = [0.4, 0.3, 0.5]\nmass = 1.5\n"
      "angular_velocity = [0.0, 1.0, 2.0]\n"
      "rotation = { axis = [1, 0, 1], degrees = 30 }\n";
  std::string written = head;
  for (int i = 0; i < 20; ++i) {
    char position[96];
    std::snprintf(position, sizeof position, "position = [%.17g, %.17g, 0.0]\n", -8.0 + 0.8 * i,
                  1.0 + 0.25 * i);
    written += "[[bodies]]\nname = \"box_" + std::to_string(i) + "\"\n" + body + position;
  }
  const std::string array = head + "[[bodies]]\nname = \"box\"\n" + body +
                            "position = [-8.0, 1.0, 0.0]\ncount = 20\nspacing = [0.8, 0.25, 0.0]\n";
  const Outcome a = tumble("simulate " + write("array.toml", array).string());
  const Outcome b = tumble("simulate " + write("written.toml", written).string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(parse_csv(a.out).size(), 1u + 20u * 151u);
  EXPECT_TRUE(a.out == b.out);
}

INSTANTIATE_TEST_SUITE_P(Every, ShippedSceneWithoutPlanes,
                         ::testing::Values("spinning_cube", "thrown_cube", "pushed_cube",
                                           "intermediate_axis", "cube_on_spring"));

}  // namespace
