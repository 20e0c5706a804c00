// Every scene file in tests/scene/bad/ is wrong in one way, and says on its second line how
// (support/bad_scenes.hpp). Each is run through `tumble render`,
// `tumble simulate` and `tumble check`: each must exit with 2, print the file, line and key and
// the fragment, and write nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/bad_scenes.hpp"
#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;

using tumble::testing::bad_scene_expectation;
using tumble::testing::bad_scene_names;
using tumble::testing::bad_scene_path;
using tumble::testing::BadSceneExpectation;

class BadScene : public tumble::testing::CommandTest,
                 public ::testing::WithParamInterface<std::string> {
 protected:
  // The message must name the file and line, then the key, then say what is wrong.
  void expect_message(const Outcome& run, const std::string& file,
                      const BadSceneExpectation& expected) {
    EXPECT_EQ(run.exit_code, 2) << run.err;
    const std::string location = file + ":" + std::to_string(expected.line) + ":";
    EXPECT_NE(run.err.find("tumble: " + location), std::string::npos)
        << "expected " << location << " in: " << run.err;
    if (expected.key != "-") {
      EXPECT_NE(run.err.find(": " + expected.key + ": "), std::string::npos)
          << "expected key " << expected.key << " in: " << run.err;
    }
    EXPECT_NE(run.err.find(expected.says), std::string::npos)
        << "expected \"" << expected.says << "\" in: " << run.err;
  }
};

TEST(BadScenes, AtLeastFortyFilesEachWithAnExpectation) {
  const std::vector<std::string> names = bad_scene_names();
  EXPECT_GE(names.size(), 40u);
  for (const std::string& name : names) {
    const BadSceneExpectation expected = bad_scene_expectation(bad_scene_path(name));
    EXPECT_GT(expected.line, 0) << name << ".toml has no readable '# expect:' line";
    EXPECT_FALSE(expected.says.empty()) << name;
  }
}

TEST_P(BadScene, IsRejectedWithItsLineAndKeyAndNothingIsWritten) {
  const std::string file = bad_scene_path(GetParam());
  const BadSceneExpectation expected = bad_scene_expectation(file);
  ASSERT_GT(expected.line, 0) << file;

  const Outcome render = tumble("render " + file + " -o " + path("out"));
  expect_message(render, file, expected);
  EXPECT_FALSE(fs::exists(path("out"))) << "render wrote output for a bad scene";

  const Outcome simulate = tumble("simulate " + file + " --out " + path("states.csv"));
  expect_message(simulate, file, expected);
  EXPECT_TRUE(fs::is_empty(dir_)) << "simulate wrote output for a bad scene";

  const Outcome check = tumble("check " + file);
  expect_message(check, file, expected);
}

INSTANTIATE_TEST_SUITE_P(Files, BadScene, ::testing::ValuesIn(bad_scene_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
