// The sequence comparison behind `tumble diff`: the same outcome on any number of threads.
#include "diff/diff_run.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "diff/diff_inputs.hpp"
#include "io/png_io.hpp"
#include "support/result_text.hpp"

namespace tumble::diff {
namespace {

namespace fs = std::filesystem;

// Frame k: grey, with k² pixels of the first rows changed in B only, so every frame differs by
// a different amount and the worst frames have a single right order.
io::Image frame(int k, bool changed) {
  io::Image image(40, 30);
  image.rgb.assign(image.rgb.size(), 90);
  for (int n = 0; changed && n < k * k; ++n) image.rgb[3 * n] = 200;
  return image;
}

class DiffRun : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(::testing::TempDir()) / ("tumble_DiffRun_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    for (const char* side : {"a", "b"}) fs::create_directories(root_ / side);
    for (int k = 0; k < 14; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.png", k);
      ASSERT_EQ(::tumble::testing::error_text(
                    io::write_png((root_ / "a" / name).string(), frame(k, false))),
                "");
      ASSERT_EQ(::tumble::testing::error_text(
                    io::write_png((root_ / "b" / name).string(), frame(k, true))),
                "");
    }
  }
  void TearDown() override { fs::remove_all(root_); }

  SequenceDiff run(unsigned threads) {
    DiffInput first, second;
    EXPECT_EQ(::tumble::testing::take(resolve_diff_input((root_ / "a").string()), first), "");
    EXPECT_EQ(::tumble::testing::take(resolve_diff_input((root_ / "b").string()), second), "");
    SequenceOptions options;
    options.keep_images = true;
    options.threads = threads;
    SequenceDiff diff;
    EXPECT_EQ(::tumble::testing::take(compare_sequences(first, second, options), diff), "");
    return diff;
  }

  fs::path root_;
};

TEST_F(DiffRun, OutcomesAndWorstFramesDoNotDependOnTheThreadCount) {
  const SequenceDiff serial = run(1);
  ASSERT_EQ(serial.frames.size(), 14u);
  for (int k = 0; k < 14; ++k) {
    EXPECT_EQ(serial.frames[k].index, k);
    EXPECT_EQ(serial.frames[k].figures->differing_pixels, k * k);
    EXPECT_EQ(serial.frames[k].match, k == 0);
  }
  // Thirteen frames fail; the ten kept are the worst, worst first: 13, 12, ..., 4.
  ASSERT_EQ(serial.worst.size(), kMaxKeptFrames);
  for (std::size_t n = 0; n < serial.worst.size(); ++n) {
    EXPECT_EQ(serial.worst[n].index, static_cast<std::int64_t>(13 - n));
  }
  for (unsigned threads : {2u, 5u}) {
    const SequenceDiff parallel = run(threads);
    ASSERT_EQ(parallel.frames.size(), serial.frames.size());
    for (std::size_t n = 0; n < serial.frames.size(); ++n) {
      EXPECT_EQ(parallel.frames[n].name, serial.frames[n].name);
      EXPECT_EQ(parallel.frames[n].figures->differing_pixels,
                serial.frames[n].figures->differing_pixels);
      EXPECT_EQ(parallel.frames[n].figures->rms, serial.frames[n].figures->rms);
    }
    ASSERT_EQ(parallel.worst.size(), serial.worst.size());
    for (std::size_t n = 0; n < serial.worst.size(); ++n) {
      EXPECT_EQ(parallel.worst[n].index, serial.worst[n].index);
      EXPECT_EQ(parallel.worst[n].difference.rgb, serial.worst[n].difference.rgb);
    }
  }
}

}  // namespace
}  // namespace tumble::diff
