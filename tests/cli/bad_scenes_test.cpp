// Every scene file in tests/scene/bad/ is wrong in one way, and says on its second line how:
//   # expect: line L, key K, says "FRAGMENT"
// (key "-" for a TOML syntax error, which has no key). Each is run through `tumble render`,
// `tumble simulate` and `tumble check`: each must exit with 2, print the file, line and key and
// the fragment, and write nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;

const fs::path kBadScenes = fs::path(TUMBLE_SOURCE_DIR) / "tests/scene/bad";

struct Expectation {
  int line = 0;
  std::string key;  // "-" for none
  std::string says;
};

Expectation expectation_of(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  // Read by hand: <regex> trips GCC 12's -Wmaybe-uninitialized in the sanitizer build.
  const std::string prefix = "# expect: line ";
  const std::size_t key_at = line.find(", key ");
  const std::size_t says_at = line.find(", says \"");
  if (line.rfind(prefix, 0) != 0 || key_at == std::string::npos || says_at == std::string::npos ||
      line.back() != '"') {
    return {};
  }
  Expectation expected;
  expected.line = std::atoi(line.c_str() + prefix.size());
  expected.key = line.substr(key_at + 6, says_at - key_at - 6);
  expected.says = line.substr(says_at + 8, line.size() - says_at - 9);
  return expected;
}

std::vector<std::string> bad_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kBadScenes)) {
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class BadScene : public tumble::testing::CommandTest,
                 public ::testing::WithParamInterface<std::string> {
 protected:
  // The message must name the file and line, then the key, then say what is wrong.
  void expect_message(const Outcome& run, const std::string& file, const Expectation& expected) {
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
    const Expectation expected = expectation_of(kBadScenes / (name + ".toml"));
    EXPECT_GT(expected.line, 0) << name << ".toml has no readable '# expect:' line";
    EXPECT_FALSE(expected.says.empty()) << name;
  }
}

TEST_P(BadScene, IsRejectedWithItsLineAndKeyAndNothingIsWritten) {
  const std::string file = (kBadScenes / (GetParam() + ".toml")).string();
  const Expectation expected = expectation_of(file);
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
