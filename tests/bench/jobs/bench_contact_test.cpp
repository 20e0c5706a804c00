// End-to-end tests of `tumble bench contact`, run as a separate process the way users run it:
// tumble's column is the run of tumble_pile.hpp for the same pile, bit for bit; Bullet's comes
// from contact_bench beside the executable, and a missing or broken one is said, with tumble's
// column still printed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "bench/pile.hpp"
#include "bench/tumble_pile.hpp"
#include "io/json_text.hpp"
#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;

using tumble::bench::PileRun;
using tumble::testing::Outcome;
using tumble::testing::read_file;

// The pile of the tests: 20 boxes for half a second, 30 steps (quick in both engines).
constexpr const char* kPile = "--bodies 20 --seconds 0.5 --seed 1";

class BenchContactCommand : public tumble::testing::CommandTest {
 protected:
  // A copy of tumble alone in a folder of its own (dir_/alone), where it looks for contact_bench.
  // The built executable links tumble's libraries statically, so it runs from anywhere.
  fs::path lone_tumble() const {
    fs::create_directories(dir_ / "alone");
    fs::copy_file(TUMBLE_EXECUTABLE, dir_ / "alone" / "tumble",
                  fs::copy_options::overwrite_existing);
    return dir_ / "alone" / "tumble";
  }
  // A stand-in for contact_bench beside the copy of tumble: a shell script of `body`.
  void fake_peer(const std::string& body) const {
    fs::create_directories(dir_ / "alone");
    write("alone/contact_bench", "#!/bin/sh\n" + body);
    fs::permissions(dir_ / "alone" / "contact_bench", fs::perms::owner_all);
  }
  Outcome run_alone(const std::string& arguments) const {
    return wait(start(arguments, "exec ", lone_tumble().string()));
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

// How often `part` occurs in `text`.
std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++count;
  }
  return count;
}

// The text of the JSON object `"name": {...}` at the top level of `json` (the engines' objects
// hold no braces of their own).
std::string object_named(const std::string& json, const std::string& name) {
  const std::size_t start = json.find("\"" + name + "\": {");
  if (start == std::string::npos) return "";
  return json.substr(start, json.find('}', start) - start + 1);
}

TEST_F(BenchContactCommand, TumblesColumnIsTheRunOfTheSamePileBitForBit) {
#ifndef TUMBLE_HAVE_BULLET
  GTEST_SKIP() << "contact_bench is built without Bullet (libbullet-dev not found)";
#endif
  fs::create_directories(dir_ / "out");
  const Outcome run = tumble(std::string("bench contact ") + kPile + " -q --out " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");  // -q: no progress
  EXPECT_NE(run.out.find("pile: 20 boxes (seed 1)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("tumble (impulse, rk4)  bullet 3.24 float"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("tumble / bullet, mean ms/step: "), std::string::npos) << run.out;

  const PileRun expected = tumble::bench::run_pile_in_tumble(tumble::bench::make_pile(20, 1, 0.5));
  ASSERT_EQ(expected.step_ms.size(), 30u);
  const std::string json = read_file(dir_ / "out" / "contact_bench.json");
  EXPECT_EQ(count_of(json, "\"steps\": 30"), 3u) << json;  // the pile's, and each engine's
  const std::string tumble = object_named(json, "tumble");
  EXPECT_NE(tumble.find("\"contacts\": " + tumble::io::json_array(expected.contacts) + ","),
            std::string::npos)
      << tumble;
  EXPECT_NE(tumble.find("\"depth_m\": " + tumble::io::json_array(expected.depth_m) + ","),
            std::string::npos)
      << tumble;
  EXPECT_NE(
      tumble.find("\"top_speed_m_per_s\": " + tumble::io::json_array(expected.top_speed) + "\n"),
      std::string::npos)
      << tumble;
  EXPECT_NE(tumble.find("\"largest_penetration_m\": " +
                        tumble::io::json_number(expected.largest_penetration_m) + ","),
            std::string::npos)
      << tumble;
  EXPECT_NE(tumble.find("\"largest_speed_at_end_m_per_s\": " +
                        tumble::io::json_number(expected.largest_final_speed) + ","),
            std::string::npos)
      << tumble;
  EXPECT_NE(tumble.find("\"boxes_out_of_bin\": 0,"), std::string::npos) << tumble;
  const std::string bullet = object_named(json, "bullet");
  EXPECT_NE(bullet.find("\"engine\": \"bullet 3.24 float"), std::string::npos) << bullet;
  EXPECT_NE(json.find("\"tumble_over_bullet\": {\"mean_ms_per_step\": "), std::string::npos);

  // The CSV: a header and a row per step, tumble's figures the same bits as the run's.
  const std::vector<std::string> csv = lines_of(read_file(dir_ / "out" / "contact_bench.csv"));
  ASSERT_EQ(csv.size(), 31u);
  EXPECT_EQ(csv[0],
            "step,t_s,tumble_ms,tumble_cpu_ms,tumble_contacts,tumble_depth_m,"
            "tumble_top_speed_m_per_s,bullet_ms,bullet_cpu_ms,bullet_contacts,bullet_depth_m,"
            "bullet_top_speed_m_per_s");
  for (std::size_t n = 0; n < 30; ++n) {
    const std::vector<std::string> cells = cells_of(csv[n + 1]);
    ASSERT_EQ(cells.size(), 12u) << csv[n + 1];
    EXPECT_EQ(cells[0], std::to_string(n));
    EXPECT_EQ(std::atoi(cells[4].c_str()), expected.contacts[n]) << "step " << n;
    EXPECT_EQ(std::strtod(cells[5].c_str(), nullptr), expected.depth_m[n]) << "step " << n;
    EXPECT_EQ(std::strtod(cells[6].c_str(), nullptr), expected.top_speed[n]) << "step " << n;
    EXPECT_GT(std::strtod(cells[7].c_str(), nullptr), 0.0)
        << "Bullet's step " << n << " took no time";
  }
  // Both engines start from the same pile in free fall: after the first step, before any box
  // lands, their fastest box moves at the same speed (to Bullet's integrator's rounding).
  const double tumble_first = std::strtod(cells_of(csv[1])[6].c_str(), nullptr);   // m/s
  const double bullet_first = std::strtod(cells_of(csv[1])[11].c_str(), nullptr);  // m/s
  EXPECT_GT(tumble_first, 0.1);
  EXPECT_NEAR(bullet_first, tumble_first, 1e-9 * tumble_first);
  for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
    EXPECT_TRUE(entry.path().filename() == "contact_bench.json" ||
                entry.path().filename() == "contact_bench.csv")
        << entry.path();
  }
}

TEST_F(BenchContactCommand, ShowsProgressOnStandardError) {
#ifndef TUMBLE_HAVE_BULLET
  GTEST_SKIP() << "contact_bench is built without Bullet (libbullet-dev not found)";
#endif
  const Outcome run = tumble(std::string("bench contact ") + kPile);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // Not a terminal: a line every 10% of both engines' 60 steps.
  EXPECT_NE(run.err.find(" 50%  30/60 steps"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("100%  60/60 steps"), std::string::npos) << run.err;
}

TEST_F(BenchContactCommand, AMissingOutFolderIsAnErrorNamingIt) {
  const Outcome run =
      tumble(std::string("bench contact ") + kPile + " --out " + path("no_such_folder"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--out: no folder " + path("no_such_folder")), std::string::npos)
      << run.err;
  EXPECT_EQ(run.out, "");  // said before the run, not after it
}

TEST_F(BenchContactCommand, AFileAsTheOutFolderIsAnErrorNamingIt) {
  write("a_file", "x");
  const Outcome run = tumble(std::string("bench contact ") + kPile + " --out " + path("a_file"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path("a_file") + " is not a folder"), std::string::npos) << run.err;
}

// Documented behaviour: the path looked at is named, tumble's column is printed, no files are
// written, and the exit code is 2.
TEST_F(BenchContactCommand, WithoutContactBenchTumblesColumnIsPrintedAndItFails) {
  fs::create_directories(dir_ / "out");
  const Outcome run = run_alone(std::string("bench contact ") + kPile + " -q --out " + path("out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no contact_bench at " + (dir_ / "alone" / "contact_bench").string()),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("tumble's column is still printed"), std::string::npos) << run.err;
  EXPECT_NE(run.out.find("tumble (impulse, rk4)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("median ms/step"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("bullet"), std::string::npos) << run.out;
  EXPECT_TRUE(fs::is_empty(dir_ / "out"));
}

TEST_F(BenchContactCommand, AContactBenchThatFailsIsAnErrorNamingIt) {
  fake_peer("echo 'tumble-pile-run 1'\necho 'engine fake'\nexit 3\n");
  const Outcome run = run_alone(std::string("bench contact ") + kPile + " -q");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("Bullet's column: " + (dir_ / "alone" / "contact_bench").string() +
                         " exited with status 3"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.out.find("tumble (impulse, rk4)"), std::string::npos) << run.out;
}

// A contact_bench from other sources would run another pile: its column is refused, not shown.
TEST_F(BenchContactCommand, AContactBenchOfAnotherPileIsRefused) {
  fake_peer("printf 'tumble-pile-run 1\\nengine fake\\npile 3 boxes\\n'\n");
  const Outcome run = run_alone(std::string("bench contact ") + kPile + " -q");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("line 3: the peer ran another pile: \"3 boxes\""), std::string::npos)
      << run.err;
  EXPECT_EQ(run.out.find("fake"), std::string::npos) << run.out;
}

TEST_F(BenchContactCommand, BadUsageExitsWithTwo) {
  EXPECT_EQ(tumble("bench contact --bodies -1").exit_code, 2);
  EXPECT_EQ(tumble("bench contact --bodies 1.5").exit_code, 2);
  EXPECT_EQ(tumble("bench contact --seconds -1").exit_code, 2);
  EXPECT_EQ(tumble("bench contact --out ''").exit_code, 2);
}

}  // namespace
