// poster.png and contact_sheet.png, written with every render: the poster is its frame's PNG byte
// for byte; the sheet is 4 × 3 tiles, each its frame shrunk 4 times by block means, above a strip
// with its time; with --frames A:B both keep to the frames rendered.
#include "pipeline/contact_sheet.hpp"

#include <gtest/gtest.h>

#include "io/png_io.hpp"
#include "support/command_test.hpp"
#include "support/render_scenes.hpp"
#include "support/result_text.hpp"

namespace tumble::pipeline {
namespace {

using testing::CommandTest;
namespace fs = std::filesystem;

TEST(ContactSheet, FramesAreTwelveSpreadEvenlyOrEveryFrameOfAShortRange) {
  EXPECT_EQ(contact_sheet_frames(0, 600),
            (std::vector<std::int64_t>{0, 54, 109, 163, 218, 272, 327, 381, 436, 490, 545, 599}));
  EXPECT_EQ(
      contact_sheet_frames(100, 112),
      (std::vector<std::int64_t>{100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111}));
  EXPECT_EQ(contact_sheet_frames(5, 9), (std::vector<std::int64_t>{5, 6, 7, 8}));
}

TEST(ContactSheet, ShrinkIsTheRoundedMeanOfEachFourByFourBlock) {
  io::Image image(9, 5);  // 2 × 1 tiles: the ninth column and fifth row are left out
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 9; ++x) {
      image.row(y)[3 * x + 0] = static_cast<std::uint8_t>(10 * x);
      image.row(y)[3 * x + 1] = static_cast<std::uint8_t>(y);
      image.row(y)[3 * x + 2] = (x + y) % 2 ? 255 : 0;
    }
  }
  const io::Image tile = shrink_for_sheet(image);
  ASSERT_EQ(tile.width, 2);
  ASSERT_EQ(tile.height, 1);
  EXPECT_EQ(tile.row(0)[0], 15);   // mean of 0, 10, 20, 30
  EXPECT_EQ(tile.row(0)[3], 55);   // mean of 40 .. 70
  EXPECT_EQ(tile.row(0)[1], 2);    // mean of 0, 1, 2, 3 = 1.5, rounded half up
  EXPECT_EQ(tile.row(0)[2], 128);  // a checkerboard: 127.5, rounded half up
}

class ContactSheetRun : public CommandTest {
 protected:
  std::string out(const std::string& file) const { return path("out/spin/" + file); }
  std::string frame(std::int64_t k) const {
    char name[32];
    std::snprintf(name, sizeof name, "frames/frame_%05lld.png", static_cast<long long>(k));
    return out(name);
  }

  // Each tile of the sheet equals its frame shrunk (block means computed here, not by the sink):
  // exactly, since both read the same 8-bit pixels.
  void expect_tiles_are_frames(const std::vector<std::int64_t>& frames) {
    io::Image sheet;
    ASSERT_EQ(::tumble::testing::take(io::read_png(out("contact_sheet.png")), sheet), "");
    const int strip = sheet_label_height(16);
    ASSERT_EQ(sheet.width, 4 * 24);
    ASSERT_EQ(sheet.height, 3 * (16 + strip));
    for (std::size_t i = 0; i < frames.size(); ++i) {
      io::Image image;
      ASSERT_EQ(::tumble::testing::take(io::read_png(frame(frames[i])), image), "");
      const int left = static_cast<int>(i % 4) * 24;
      const int top = static_cast<int>(i / 4) * (16 + strip);
      int differing = 0;
      for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 24; ++x) {
          for (int c = 0; c < 3; ++c) {
            int sum = 0;
            for (int dy = 0; dy < 4; ++dy) {
              for (int dx = 0; dx < 4; ++dx) sum += image.row(4 * y + dy)[3 * (4 * x + dx) + c];
            }
            differing += sheet.row(top + y)[3 * (left + x) + c] != (sum + 8) / 16;
          }
        }
      }
      EXPECT_EQ(differing, 0) << "tile " << i << " (frame " << frames[i] << ")";
    }
  }
};

// 24 frames (1.2 s at 20 fps) of 96 × 64 pixels: tiles of 24 × 16.
TEST_F(ContactSheetRun, PosterIsItsFramesPngAndTheSheetHoldsTheFramesShrunk) {
  const fs::path scene = write("spin.toml", testing::spinning_cube_scene(1.2));
  const testing::Outcome run = tumble("render -q " + scene.string() + " -o " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(testing::read_file(out("poster.png")), testing::read_file(frame(12)));  // 24 / 2
  expect_tiles_are_frames(contact_sheet_frames(0, 24));
}

TEST_F(ContactSheetRun, PosterTimeChoosesTheNearestFrame) {
  const fs::path scene =
      write("spin.toml", testing::spinning_cube_scene(1.2, "[output]\nposter_time = 0.33\n"));
  ASSERT_EQ(tumble("render -q " + scene.string() + " -o " + path("out")).exit_code, 0);
  EXPECT_EQ(testing::read_file(out("poster.png")), testing::read_file(frame(7)));  // 6.6 frames
}

TEST_F(ContactSheetRun, WithAFrameRangeBothKeepToTheFramesRendered) {
  const fs::path scene = write("spin.toml", testing::spinning_cube_scene(1.2));
  ASSERT_EQ(
      tumble("render -q " + scene.string() + " -o " + path("out") + " --frames 3:9").exit_code, 0);
  EXPECT_FALSE(fs::exists(out("poster.png")));  // frame 12 was not rendered
  expect_tiles_are_frames({3, 4, 5, 6, 7, 8});
}

}  // namespace
}  // namespace tumble::pipeline
