// What `tumble join` checks before writing: every frame once (naming missing and doubled frames)
// and one scene with one set of settings (naming the folders and the setting).
#include "job/join_inputs.hpp"

#include <gtest/gtest.h>

#include "support/result_text.hpp"

namespace tumble::job {
namespace {

using tumble::testing::error_text;

TEST(JoinInputs, RangesThatCoverEveryFrameOnceHaveNoProblem) {
  EXPECT_EQ(error_text(check_coverage({{0, 7}, {7, 8}, {8, 15}}, {"a", "b", "c"}, 15)), "");
}

TEST(JoinInputs, NamesMissingFramesAsRanges) {
  EXPECT_EQ(error_text(check_coverage({{0, 40}, {60, 100}}, {"a", "b"}, 100)),
            "frames 40:60 are missing");
  EXPECT_EQ(error_text(check_coverage({{10, 20}}, {"a"}, 30)),
            "frames 0:10 are missing; frames 20:30 are missing");
}

TEST(JoinInputs, NamesDoubledFramesAndTheFoldersThatHoldThem) {
  EXPECT_EQ(error_text(check_coverage({{0, 12}, {10, 20}}, {"a", "b"}, 20)),
            "frames 10:12 are in both a and b");
  // A chunk inside another: all of it doubled.
  EXPECT_EQ(error_text(check_coverage({{0, 20}, {5, 8}}, {"a", "b"}, 20)),
            "frames 5:8 are in both a and b");
}

ChunkReport chunk(const std::string& folder, const std::string& settings, const std::string& hash) {
  ChunkReport report;
  report.folder = folder;
  report.scene = "spin";
  report.scene_file = "spin.toml";
  report.scene_hash = hash;
  report.scene_frames = 15;
  report.settings = *io::parse_json(settings);
  return report;
}

TEST(JoinInputs, NamesTheSettingThatDiffersAndTheTwoFolders) {
  const std::string settings = R"({"width": 64, "preset": "veryfast"})";
  EXPECT_EQ(error_text(check_one_render({chunk("a", settings, "ab"), chunk("b", settings, "ab")})),
            "");
  EXPECT_EQ(
      error_text(check_one_render({chunk("a", settings, "ab"),
                                   chunk("b", R"({"width": 80, "preset": "veryfast"})", "cd")})),
      "chunks a and b differ in width: 64 and 80");
  const std::string other_scene =
      error_text(check_one_render({chunk("a", settings, "ab12"), chunk("b", settings, "cd34")}));
  EXPECT_EQ(
      other_scene.rfind("chunks a and b differ in the scene they rendered (scene_hash ab12", 0), 0u)
      << other_scene;
}

}  // namespace
}  // namespace tumble::job
