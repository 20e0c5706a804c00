// Every scene file in tests/scene/bad/ is wrong in one way, and says on its second line how
// (support/bad_scenes.hpp); scene/bad_scenes_test.cpp holds the loader's message for each to that
// line. Here the commands must refuse them the same way and write nothing:
// - every file, through `render`, `simulate` and `check` as the command functions main runs
//   (run_render, run_simulate, run_check), in this process: each must fail with the file's message;
// - a few files that stand for the kinds of mistake, through the tumble executable: each command
//   must then exit with 2 and print that message after "tumble: ", which is main's part.
// Starting tumble three times for each of 213 files cost about two minutes of a release test run,
// and much more under the sanitizers, for what the in-process runs show in two seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/check_command.hpp"
#include "cli/render_command.hpp"
#include "cli/simulate_command.hpp"
#include "support/bad_scenes.hpp"
#include "support/command_test.hpp"

namespace tumble::cli {
namespace {

namespace fs = std::filesystem;
using tumble::testing::bad_scene_names;
using tumble::testing::bad_scene_path;
using tumble::testing::Outcome;
using tumble::testing::refused_as_expected;

// Run through the tumble executable; each must be one of the files.
const std::vector<std::string> kThroughTheExecutable = {
    "syntax_unterminated_string",    // TOML syntax: no key
    "misspelt_mass",                 // an unknown key
    "missing_duration",              // a missing key
    "mass_negative",                 // a value out of range
    "width_odd_with_video",          // a rule between keys
    "output_directory_parent",       // a path the output may not take
    "overlay_placeholder_unclosed",  // an overlay's text
    "bodies_start_overlapping",      // the bodies, placed
};

// A command's printed figures, warnings or progress, none of which a refused scene may cause.
class Printed {
 public:
  Printed() : file_(std::tmpfile()) {}
  ~Printed() {
    if (file_) std::fclose(file_);
  }
  Printed(const Printed&) = delete;
  Printed& operator=(const Printed&) = delete;
  std::FILE* file() const { return file_; }
  long size() const {
    std::fflush(file_);
    return std::ftell(file_);
  }

 private:
  std::FILE* file_;
};

class BadScenes : public tumble::testing::CommandTest {};

TEST_F(BadScenes, AreManyAndSomeRunThroughTheExecutable) {
  const std::vector<std::string> names = bad_scene_names();
  EXPECT_GE(names.size(), 200u);
  for (const std::string& name : kThroughTheExecutable) {
    EXPECT_TRUE(std::find(names.begin(), names.end(), name) != names.end())
        << name << ".toml is not in " << tumble::testing::kBadScenes;
  }
}

TEST_F(BadScenes, CheckRefusesEachWithItsMessage) {
  for (const std::string& name : bad_scene_names()) {
    const std::string file = bad_scene_path(name);
    Printed out;
    const CommandResult checked = run_check({.scene_path = file}, out.file());
    ASSERT_FALSE(checked.ok()) << "check passed " << file;
    EXPECT_TRUE(refused_as_expected(file, checked.error()));
    EXPECT_EQ(out.size(), 0) << file;
  }
}

TEST_F(BadScenes, SimulateRefusesEachWithItsMessageAndWritesNothing) {
  for (const std::string& name : bad_scene_names()) {
    const std::string file = bad_scene_path(name);
    Printed err;
    const CommandResult simulated =
        run_simulate({.scene_path = file, .out = path("states.csv")}, err.file());
    ASSERT_FALSE(simulated.ok()) << "simulate ran " << file;
    EXPECT_TRUE(refused_as_expected(file, simulated.error()));
    EXPECT_EQ(err.size(), 0) << file;
    EXPECT_TRUE(fs::is_empty(dir_)) << "simulate wrote a file for " << file;
  }
}

TEST_F(BadScenes, RenderRefusesEachWithItsMessageAndWritesNothing) {
  for (const std::string& name : bad_scene_names()) {
    const std::string file = bad_scene_path(name);
    Printed out, err;
    job::RenderOptions options;
    options.scene_path = file;
    options.output_root = path("out");
    const CommandResult rendered = run_render(options, std::nullopt, out.file(), err.file());
    ASSERT_FALSE(rendered.ok()) << "render ran " << file;
    EXPECT_TRUE(refused_as_expected(file, rendered.error()));
    EXPECT_EQ(out.size() + err.size(), 0) << file;
    EXPECT_TRUE(fs::is_empty(dir_)) << "render wrote output for " << file;
  }
}

class BadSceneThroughTheExecutable : public tumble::testing::CommandTest,
                                     public ::testing::WithParamInterface<std::string> {
 protected:
  // Exit code 2 and one line: "tumble: " and the file's message.
  static void expect_refused(const Outcome& run, const std::string& file) {
    EXPECT_EQ(run.exit_code, 2) << run.err;
    ASSERT_EQ(run.err.rfind("tumble: ", 0), 0u) << run.err;
    ASSERT_FALSE(run.err.empty());
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
    EXPECT_TRUE(refused_as_expected(file, run.err.substr(8, run.err.size() - 9)));
    EXPECT_EQ(run.out, "");
  }
};

TEST_P(BadSceneThroughTheExecutable, EveryCommandExitsWithTwoAndItsMessageAndWritesNothing) {
  const std::string file = bad_scene_path(GetParam());

  expect_refused(tumble("render " + file + " -o " + path("out")), file);
  EXPECT_FALSE(fs::exists(path("out"))) << "render wrote output for a bad scene";

  expect_refused(tumble("simulate " + file + " --out " + path("states.csv")), file);
  EXPECT_TRUE(fs::is_empty(dir_)) << "simulate wrote output for a bad scene";

  expect_refused(tumble("check " + file), file);
}

INSTANTIATE_TEST_SUITE_P(Files, BadSceneThroughTheExecutable,
                         ::testing::ValuesIn(kThroughTheExecutable),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tumble::cli
