// The html replay's own files are found as the shaders are (TUMBLE_WEB_DIR, else the source
// tree), and a missing three.js bundle is an error that says what to run.
#include "job/replay_assets.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace tumble::job {
namespace {

namespace fs = std::filesystem;

class ReplayAssetsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ =
        fs::path(::testing::TempDir()) / ("tumble_replay_assets_" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_ / "dist");
    std::ofstream(folder_ / "replay.html") << "<!-- tumble: data -->";
    std::ofstream(folder_ / "replay.js") << "play();";
  }
  void TearDown() override {
    ::unsetenv("TUMBLE_WEB_DIR");
    fs::remove_all(folder_);
  }
  fs::path folder_;
};

TEST_F(ReplayAssetsTest, TheSourceTreesWebFolderIsFoundWithoutTheVariable) {
  ::unsetenv("TUMBLE_WEB_DIR");
  EXPECT_EQ(find_web_directory(), TUMBLE_SOURCE_DIR "/web");
}

TEST_F(ReplayAssetsTest, TheVariableNamesTheFolderOrNone) {
  ::setenv("TUMBLE_WEB_DIR", folder_.c_str(), 1);
  EXPECT_EQ(find_web_directory(), folder_.string());
  const std::string empty = (folder_ / "dist").string();
  ::setenv("TUMBLE_WEB_DIR", empty.c_str(), 1);
  EXPECT_EQ(find_web_directory(), "");
  const Result<ReplayAssets> assets = load_replay_assets();
  ASSERT_FALSE(assets);
  EXPECT_EQ(assets.error(), "no html replay files (replay.html) in TUMBLE_WEB_DIR=" + empty);
}

TEST_F(ReplayAssetsTest, AMissingThreeJsSaysWhatToRun) {
  ::setenv("TUMBLE_WEB_DIR", folder_.c_str(), 1);
  Result<ReplayAssets> assets = load_replay_assets();
  ASSERT_FALSE(assets);
  EXPECT_EQ(assets.error(), "the html replay needs three.js, and " + folder_.string() +
                                "/dist/three.bundle.js is missing: run scripts/install-deps (or "
                                "`npm ci && npm run bundle` in " +
                                folder_.string() + ")");
  std::ofstream(folder_ / "dist/three.bundle.js") << "var TumbleThree = {};";
  assets = load_replay_assets();
  ASSERT_TRUE(assets) << assets.error();
  EXPECT_EQ(assets->directory, folder_.string());
  EXPECT_EQ(assets->markup, "<!-- tumble: data -->");
  EXPECT_EQ(assets->replay_js, "play();");
  EXPECT_EQ(assets->three_js, "var TumbleThree = {};");
}

}  // namespace
}  // namespace tumble::job
