// Every scene file in tests/scene/bad/ is wrong in one way, and says on its second line how
// (support/bad_scenes.hpp). Here each is loaded as the loader loads it: the message must begin
// "FILE:L:C: K: " and hold FRAGMENT. cli/bad_scenes_test.cpp runs the same files through
// `tumble render`, `simulate` and `check`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene_loader.hpp"
#include "support/bad_scenes.hpp"

namespace tumble::scene {
namespace {

namespace fs = std::filesystem;
using tumble::testing::bad_scene_expectation;
using tumble::testing::bad_scene_names;
using tumble::testing::bad_scene_path;
using tumble::testing::BadSceneExpectation;

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
    const fs::path file = bad_scene_path(name);
    const BadSceneExpectation expected = bad_scene_expectation(file);
    EXPECT_GT(expected.line, 0) << name << ".toml has no readable '# expect:' line";
    EXPECT_GT(expected.column, 0) << name;
    EXPECT_FALSE(expected.says.empty()) << name;
    const auto [it, inserted] = first_with_text.emplace(scene_text_of(file), name);
    EXPECT_TRUE(inserted) << name << ".toml is the same scene as " << it->second << ".toml";
  }
}

class BadSceneFile : public ::testing::TestWithParam<std::string> {};

TEST_P(BadSceneFile, IsRefusedAtItsLineColumnAndKeyWithItsMessage) {
  const std::string file = bad_scene_path(GetParam());
  const Result<Scene> result = load_scene_file(file);
  ASSERT_TRUE(!result.ok()) << "loaded: " << file;
  EXPECT_TRUE(tumble::testing::refused_as_expected(file, result.error()));
}

INSTANTIATE_TEST_SUITE_P(Files, BadSceneFile, ::testing::ValuesIn(bad_scene_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tumble::scene
