// End-to-end tests of `tumble render --golden DIR`: a render compared with a stored golden render
// in one step, with `tumble diff`'s exit codes and outputs.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/command_test.hpp"
#include "support/scene_text.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;
using tumble::testing::read_file;

// The golden scene: half a second at 30 frames/s of a cube spinning about a tilted axis, 15 frames
// of 160x120 (tumble::testing::spin_scene); and the same cube turned 1° more about y at the start:
// q = (cos 0.5°, 0, sin 0.5°, 0).
constexpr const char* kTurned =
    "orientation = [0.99996192306417131, 0.0, 0.0087265354983739347, 0.0]\n";

class RenderGolden : public tumble::testing::CommandTest {
 protected:
  void SetUp() override {
    CommandTest::SetUp();
    scene_ = write("spin.toml", tumble::testing::spin_scene(160, 120)).string();
    turned_ = write("turned.toml", tumble::testing::spin_scene(160, 120, kTurned)).string();
    const Outcome golden = tumble("render -q " + scene_ + " -o " + path("golden"));
    ASSERT_EQ(golden.exit_code, 0) << golden.err;
  }
  std::string golden() const { return path("golden") + "/spin"; }
  std::string scene_, turned_;
};

TEST_F(RenderGolden, ARenderMatchesTheGoldenItWasMadeAs) {
  const Outcome run = tumble("render -q " + scene_ + " -o " + path("actual") + " --golden " +
                             golden() + " --json " + path("figures.json"));
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_TRUE(run.out.starts_with("match: 0 of 15 frames differ")) << run.out;
  EXPECT_TRUE(fs::exists(path("actual") + "/spin/frames/frame_00014.png"));
  EXPECT_NE(read_file(path("figures.json")).find(",\n  \"match\": true,"), std::string::npos);
}

TEST_F(RenderGolden, ACubeTurnedOneDegreeMoreFailsWithAReportAndJUnit) {
  const Outcome run =
      tumble("render -q " + turned_ + " -o " + path("actual") + " --golden " + golden() +
             " --metric perceptual --report " + path("report") + " --junit " + path("junit.xml"));
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_NE(run.out.find("mismatch: 15 of 15 frames differ"), std::string::npos) << run.out;
  EXPECT_TRUE(fs::exists(path("report") + "/index.html"));
  // Every frame shows the turned cube: each of the 15 test cases fails.
  const std::string junit = read_file(path("junit.xml"));
  EXPECT_NE(junit.find("tests=\"15\" failures=\"15\""), std::string::npos) << junit;
  // The render itself is complete: a mismatch is the golden's verdict, not a failed render.
  EXPECT_TRUE(fs::exists(path("actual") + "/spin/spin.mp4"));
}

TEST_F(RenderGolden, AFrameRangeIsComparedOverItsFramesOnly) {
  const Outcome run = tumble("render -q --frames 5:8 " + scene_ + " -o " + path("actual") +
                             " --golden " + golden());
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_TRUE(run.out.starts_with("match: 0 of 3 frames differ")) << run.out;
}

TEST_F(RenderGolden, ARenderWithoutFramesComparesItsVideo) {
  const Outcome run = tumble("render -q --no-frames " + scene_ + " -o " + path("actual") +
                             " --golden " + golden() + "/spin.mp4 --metric max --threshold 0");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_TRUE(run.out.starts_with("match: 0 of 15 frames differ")) << run.out;
}

// The golden's video against the new render's PNG frames, at 160x120: the PNGs are converted as
// the video holds them and H.264's quantisation is not counted, so the same scene passes at the
// default perceptual threshold, while max 0 and the 1°-turned cube fail.
TEST_F(RenderGolden, AVideoGoldenMatchesTheSameSceneAndNotACubeTurnedOneDegreeMore) {
  const std::string video = " --golden " + golden() + "/spin.mp4";
  const Outcome same =
      tumble("render -q " + scene_ + " -o " + path("same") + video + " --metric perceptual");
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  EXPECT_TRUE(same.out.starts_with("match: 0 of 15 frames differ")) << same.out;
  EXPECT_NE(same.out.find("note: B's frames converted to yuv420p BT.709 limited range"),
            std::string::npos)
      << same.out;
  const Outcome exact = tumble("render -q " + scene_ + " -o " + path("exact") + video +
                               " --metric max --threshold 0");
  EXPECT_EQ(exact.exit_code, 1) << exact.out << exact.err;
  const Outcome turned =
      tumble("render -q " + turned_ + " -o " + path("turned") + video + " --metric perceptual");
  EXPECT_EQ(turned.exit_code, 1) << turned.out << turned.err;
  EXPECT_NE(turned.out.find("mismatch: "), std::string::npos) << turned.out;
}

TEST_F(RenderGolden, AGoldenInTheFolderTheRenderReplacesIsRefusedBeforeRendering) {
  const std::string before = read_file(golden() + "/frames/frame_00003.png");
  const Outcome run =
      tumble("render -q " + turned_ + " -o " + path("golden") + " --golden " + golden());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("the folder this render replaces"), std::string::npos) << run.err;
  EXPECT_EQ(read_file(golden() + "/frames/frame_00003.png"), before);
}

TEST_F(RenderGolden, AMissingGoldenOrABadOptionIsAnErrorBeforeRendering) {
  Outcome run =
      tumble("render -q " + scene_ + " -o " + path("actual") + " --golden " + path("nowhere"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path("nowhere") + ": no such file or folder"), std::string::npos)
      << run.err;
  run = tumble("render -q " + scene_ + " -o " + path("actual") + " --golden " + golden() +
               " --metric rms --max-pixels 3");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--max-pixels"), std::string::npos) << run.err;
  run = tumble("render -q " + scene_ + " -o " + path("actual") + " --golden " + golden() +
               "/frames/frame_00000.png");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("not one PNG"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(path("actual")));
}

TEST_F(RenderGolden, ComparisonOptionsNeedAGolden) {
  const Outcome run =
      tumble("render -q " + scene_ + " -o " + path("actual") + " --metric perceptual");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--golden"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(path("actual")));
}

}  // namespace
