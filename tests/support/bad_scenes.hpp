// The scene files of tests/scene/bad/, each wrong in one way, which say on their second line how:
//   # expect: line L, column C, key K, says "FRAGMENT"
// (key "-" for a TOML syntax error, which has no key; C is where the value starts, or the key for
// an unknown or missing one). tests/scene/bad_scenes_test.cpp loads each as the loader does and
// holds its message to this line; tests/cli/bad_scenes_test.cpp holds what the commands print.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tumble::testing {

inline const std::filesystem::path kBadScenes =
    std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests/scene/bad";

struct BadSceneExpectation {
  int line = 0;  // 0 when the file has no readable "# expect:" line
  int column = 0;
  std::string key;  // "-" for none
  std::string says;
};

// The file's "# expect:" line, read by hand: <regex> trips GCC 12's -Wmaybe-uninitialized in the
// sanitizer build.
inline BadSceneExpectation bad_scene_expectation(const std::filesystem::path& file) {
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
  BadSceneExpectation expected;
  expected.line = std::atoi(line.c_str() + prefix.size());
  expected.column = std::atoi(line.c_str() + column_at + 9);
  expected.key = line.substr(key_at + 6, says_at - key_at - 6);
  expected.says = line.substr(says_at + 8, line.size() - says_at - 9);
  return expected;
}

// The files' names without ".toml", sorted.
inline std::vector<std::string> bad_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kBadScenes)) {
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

inline std::string bad_scene_path(const std::string& name) {
  return (kBadScenes / (name + ".toml")).string();
}

// Whether `message` is the one the file `path` expects: it begins "PATH:L:C: K: " (no "K: " for
// key "-") and holds FRAGMENT after that.
inline ::testing::AssertionResult refused_as_expected(const std::string& path,
                                                      const std::string& message) {
  const BadSceneExpectation expected = bad_scene_expectation(path);
  if (expected.line == 0) {
    return ::testing::AssertionFailure() << path << " has no readable '# expect:' line";
  }
  const std::string prefix = path + ":" + std::to_string(expected.line) + ":" +
                             std::to_string(expected.column) + ": " +
                             (expected.key == "-" ? "" : expected.key + ": ");
  if (message.compare(0, prefix.size(), prefix) != 0) {
    return ::testing::AssertionFailure() << "expected \"" << prefix << "\" first in: " << message;
  }
  if (message.find(expected.says, prefix.size()) == std::string::npos) {
    return ::testing::AssertionFailure()
           << "expected \"" << expected.says << "\" after the key in: " << message;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace tumble::testing
