// Every scene file in tests/scene/bad/ is wrong in one way, and says on its second line how:
//   # expect: line L, column C, key K, says "FRAGMENT"
// (key "-" for a TOML syntax error, which has no key; C is where the value starts, or the key
// for an unknown or missing one). Here each is loaded as the loader loads it: the message must
// begin "FILE:L:C: K: " and hold FRAGMENT. app/bad_scenes_test.cpp runs the same files through
// `tumble render`, `simulate` and `check`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "scene/scene_loader.hpp"

namespace tumble::scene {
namespace {

namespace fs = std::filesystem;

const fs::path kBadScenes = fs::path(TUMBLE_SOURCE_DIR) / "tests/scene/bad";

struct Expectation {
  int line = 0;
  int column = 0;
  std::string key;  // "-" for none
  std::string says;
};

// The file's "# expect:" line, read; line 0 if it cannot be read.
Expectation expectation_of(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  const std::string prefix = "# expect: line ";
  const std::size_t column_at = line.find(", column ");
  const std::size_t key_at = line.find(", key ");
  const std::size_t says_at = line.find(", says \"");
  if (line.rfind(prefix, 0) != 0 || column_at == std::string::npos || key_at == std::string::npos ||
      says_at == std::string::npos || line.back() != '"') {
    return {};
  }
  Expectation expected;
  expected.line = std::atoi(line.c_str() + prefix.size());
  expected.column = std::atoi(line.c_str() + column_at + 9);
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

// The scene below the two comment lines.
std::string scene_text_of(const fs::path& file) {
  std::ifstream in(file);
  std::string skipped;
  std::getline(in, skipped);
  std::getline(in, skipped);
  std::ostringstream rest;
  rest << in.rdbuf();
  return rest.str();
}

TEST(BadSceneFiles, EachStatesItsExpectationAndIsADifferentScene) {
  const std::vector<std::string> names = bad_scene_names();
  EXPECT_GE(names.size(), 200u);
  std::map<std::string, std::string> first_with_text;
  for (const std::string& name : names) {
    const fs::path file = kBadScenes / (name + ".toml");
    const Expectation expected = expectation_of(file);
    EXPECT_GT(expected.line, 0) << name << ".toml has no readable '# expect:' line";
    EXPECT_GT(expected.column, 0) << name;
    EXPECT_FALSE(expected.says.empty()) << name;
    const auto [it, inserted] = first_with_text.emplace(scene_text_of(file), name);
    EXPECT_TRUE(inserted) << name << ".toml is the same scene as " << it->second << ".toml";
  }
}

class BadSceneFile : public ::testing::TestWithParam<std::string> {};

TEST_P(BadSceneFile, IsRefusedAtItsLineColumnAndKeyWithItsMessage) {
  const std::string file = (kBadScenes / (GetParam() + ".toml")).string();
  const Expectation expected = expectation_of(file);
  ASSERT_GT(expected.line, 0) << file;

  const Result<Scene> result = load_scene_file(file);
  ASSERT_TRUE(!result.ok()) << "loaded: " << file;
  const std::string& message = result.error();
  const std::string prefix = file + ":" + std::to_string(expected.line) + ":" +
                             std::to_string(expected.column) + ": " +
                             (expected.key == "-" ? "" : expected.key + ": ");
  EXPECT_EQ(message.substr(0, prefix.size()), prefix) << message;
  EXPECT_NE(message.find(expected.says, prefix.size()), std::string::npos)
      << "expected \"" << expected.says << "\" in: " << message;
}

INSTANTIATE_TEST_SUITE_P(Files, BadSceneFile, ::testing::ValuesIn(bad_scene_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tumble::scene
