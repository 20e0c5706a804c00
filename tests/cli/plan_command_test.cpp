// End-to-end tests of `tumble plan`: the ranges printed for a few frame counts, as text and JSON,
// the overrides render takes, and its errors.
#include <gtest/gtest.h>

#include <string>

#include "support/command_test.hpp"
#include "support/scene_text.hpp"

namespace {

using tumble::testing::Outcome;

// 15 frames: half a second at 30 frames/s.
const std::string kScene = tumble::testing::spin_scene(64, 36);

class PlanCommand : public tumble::testing::CommandTest {
 protected:
  Outcome plan(const std::string& arguments) {
    return tumble("plan " + write("spin.toml", kScene).string() + " " + arguments);
  }
  void expect_plan(const std::string& arguments, const std::string& lines) {
    const Outcome run = plan(arguments);
    EXPECT_EQ(run.exit_code, 0) << arguments << ": " << run.err;
    EXPECT_EQ(run.out, lines) << arguments;
  }
};

TEST_F(PlanCommand, PrintsOneRangePerChunkEvenlyWithTheRemainderFirst) {
  expect_plan("--chunks 3", "0:5\n5:10\n10:15\n");
  expect_plan("--chunks 4", "0:4\n4:8\n8:12\n12:15\n");
  expect_plan("--chunks 1", "0:15\n");
  expect_plan("--chunks 15", [] {
    std::string lines;
    for (int k = 0; k < 15; ++k) lines += std::to_string(k) + ":" + std::to_string(k + 1) + "\n";
    return lines;
  }());
}

// --chunk-frames K: ceil(15 / K) chunks, split as --chunks would.
TEST_F(PlanCommand, ChunkFramesPlansTheFewestChunksOfAtMostKFrames) {
  expect_plan("--chunk-frames 4", "0:4\n4:8\n8:12\n12:15\n");
  expect_plan("--chunk-frames 5", "0:5\n5:10\n10:15\n");
  expect_plan("--chunk-frames 14", "0:8\n8:15\n");
  expect_plan("--chunk-frames 100", "0:15\n");
}

TEST_F(PlanCommand, CountsTheFramesAsRenderDoesWithItsRateOverrides) {
  expect_plan("--chunks 2 --fps 60", "0:15\n15:30\n");
  // --quality high is 60 frames/s; an --fps beside it wins, as in render.
  expect_plan("--chunks 2 --quality high", "0:15\n15:30\n");
  expect_plan("--chunks 2 --quality high --fps 30", "0:8\n8:15\n");
}

TEST_F(PlanCommand, PrintsJson) {
  expect_plan("--chunks 2 --json",
              "{\"scene\": \"spin\", \"frames\": 15, \"chunks\": [{\"index\": 1, \"first\": 0, "
              "\"end\": 8}, {\"index\": 2, \"first\": 8, \"end\": 15}]}\n");
}

TEST_F(PlanCommand, RefusesMoreChunksThanFramesAndAMissingOrDoubleChoice) {
  const Outcome many = plan("--chunks 16");
  EXPECT_EQ(many.exit_code, 2);
  EXPECT_NE(many.err.find("16 chunks cannot split the scene's 15 frames"), std::string::npos)
      << many.err;
  EXPECT_EQ(many.out, "");
  const Outcome neither = plan("");
  EXPECT_EQ(neither.exit_code, 2);
  EXPECT_NE(neither.err.find("give --chunks N or --chunk-frames K"), std::string::npos);
  const Outcome both = plan("--chunks 2 --chunk-frames 3");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("excludes"), std::string::npos) << both.err;
  const Outcome zero = plan("--chunks 0");
  EXPECT_EQ(zero.exit_code, 2);
}

}  // namespace
