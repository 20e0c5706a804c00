// poster.png and contact_sheet.png, written with every render: the poster is its frame's PNG byte
// for byte; the sheet is 4 × 3 tiles apart by gaps, each its frame shrunk 4 times by block means,
// above a thin strip with its time in the scene's font; with --frames A:B both keep to the frames
// rendered.
#include "pipeline/contact_sheet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>

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

// The sheet of a 720p render's frames (each a flat grey, tiles of 320 × 180): gaps of the
// strip's colour between and around the tiles, and under each tile a strip 8 px high (a fifth or
// less of the pixel font's 44) whose label, light on dark, covers part of it.
TEST(ContactSheet, TilesHaveGapsAndThinLabelledStrips) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "tumble_contact_sheet_test.png").string();
  Result<std::unique_ptr<ContactSheet>> opened = ContactSheet::open(path, 0, 240, 60, {});
  ASSERT_TRUE(opened) << opened.error();
  ContactSheet& sheet_sink = **opened;
  for (std::int64_t k = 0; k < 240; ++k) {
    io::Image frame(1280, 720);
    std::fill(frame.rgb.begin(), frame.rgb.end(), std::uint8_t{150});
    ASSERT_EQ(testing::error_text(sheet_sink.write(k, frame)), "");
  }
  ASSERT_EQ(testing::error_text(sheet_sink.finish()), "");
  io::Image sheet;
  ASSERT_EQ(testing::take(io::read_png(path), sheet), "");
  std::filesystem::remove(path);
  const int strip = sheet_label_height(180), gap = sheet_gap(180);
  EXPECT_EQ(strip, 8);
  EXPECT_LE(strip * 5, 11 * (180 / 45));  // the pixel font's strip: 11 rows of 4 px
  EXPECT_EQ(gap, 6);
  ASSERT_EQ(sheet.width, gap + 4 * (320 + gap));
  ASSERT_EQ(sheet.height, gap + 3 * (180 + strip + gap));
  const auto pixel = [&](int x, int y) {
    const std::uint8_t* p = sheet.row(y) + 3 * x;
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  const std::array<int, 3> strip_color{38, 40, 44}, tile_color{150, 150, 150};
  for (int i = 0; i < kSheetTiles; ++i) {
    const auto [left, top] = sheet_tile_origin(i, 320, 180);
    // The gap left of the tile and the one above it, and the tile itself.
    EXPECT_EQ(pixel(left - 1, top + 90), strip_color) << "tile " << i;
    EXPECT_EQ(pixel(left - gap, top + 90), strip_color) << "tile " << i;
    EXPECT_EQ(pixel(left + 160, top - 1), strip_color) << "tile " << i;
    EXPECT_EQ(pixel(left, top), tile_color) << "tile " << i;
    EXPECT_EQ(pixel(left + 319, top + 179), tile_color) << "tile " << i;
    // The label: light pixels in the strip, within its 8 rows, centred under the tile.
    int lit = 0, lit_left = 320, lit_right = -1;
    for (int y = top + 180; y < top + 180 + strip; ++y) {
      for (int x = left; x < left + 320; ++x) {
        if (pixel(x, y)[0] < 120) continue;
        ++lit;
        lit_left = std::min(lit_left, x - left);
        lit_right = std::max(lit_right, x - left);
      }
    }
    EXPECT_GT(lit, 20) << "tile " << i;  // "t = 0.00 s": eight glyphs of a few pixels each
    EXPECT_NEAR(lit_left + lit_right, 320, 8) << "tile " << i;
    EXPECT_LT(lit_right - lit_left, 80) << "tile " << i;
    // Below the strip, the gap again.
    EXPECT_EQ(pixel(left + 160, top + 180 + strip), strip_color) << "tile " << i;
  }
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
    const int strip = sheet_label_height(16), gap = sheet_gap(16);
    ASSERT_EQ(sheet.width, gap + 4 * (24 + gap));
    ASSERT_EQ(sheet.height, gap + 3 * (16 + strip + gap));
    for (std::size_t i = 0; i < frames.size(); ++i) {
      io::Image image;
      ASSERT_EQ(::tumble::testing::take(io::read_png(frame(frames[i])), image), "");
      const auto [left, top] = sheet_tile_origin(static_cast<int>(i), 24, 16);
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

// A font that is not installed is an error when the sheet is opened, before any frame is drawn,
// naming the sheet and the family.
TEST(ContactSheet, AMissingFontIsAnErrorBeforeAnyFrame) {
  const Result<std::unique_ptr<ContactSheet>> opened =
      ContactSheet::open("sheet.png", 0, 240, 60, {}, "No Such Font Family 1234");
  ASSERT_FALSE(opened);
  EXPECT_NE(opened.error().find("sheet.png: its labels' font: "), std::string::npos);
  EXPECT_NE(opened.error().find("No Such Font Family 1234"), std::string::npos);
}

}  // namespace
}  // namespace tumble::pipeline
