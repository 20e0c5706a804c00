// End-to-end tests of `tumble diff`, run as a separate process the way users and scripts run it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/image.hpp"
#include "io/png_io.hpp"
#include "support/command_test.hpp"
#include "support/result_text.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::io::Image;

using tumble::testing::Outcome;
using tumble::testing::read_file;

// 4x3 pixels, all different: 12 pixels, 36 channels.
Image base_image() {
  Image image(4, 3);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    image.rgb[i] = static_cast<std::uint8_t>(30 + 5 * i);
  }
  return image;
}

class DiffCommand : public tumble::testing::CommandTest {
 protected:
  void SetUp() override {
    CommandTest::SetUp();
    Image changed = base_image();
    changed.row(1)[3 * 2 + 0] += 10;  // pixel (2, 1), red + 10
    ASSERT_EQ(::tumble::testing::error_text(tumble::io::write_png(path("a.png"), base_image())),
              "");
    ASSERT_EQ(
        ::tumble::testing::error_text(tumble::io::write_png(path("a_copy.png"), base_image())), "");
    ASSERT_EQ(::tumble::testing::error_text(tumble::io::write_png(path("b.png"), changed)), "");
  }
};

TEST_F(DiffCommand, IdenticalImagesMatchWithExitZero) {
  const Outcome run = tumble("diff " + path("a.png") + " " + path("a_copy.png"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "match: 0 of 12 pixels differ (0%), largest channel difference 0, RMS 0\n");
  EXPECT_EQ(run.err, "");
}

TEST_F(DiffCommand, OneChangedPixelIsAMismatchWithExitOne) {
  const Outcome run = tumble("diff " + path("a.png") + " " + path("b.png"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  // 1/12 = 8.33%; RMS = sqrt(10² / 36) = 1.667.
  EXPECT_EQ(run.out,
            "mismatch: 1 of 12 pixels differ (8.33%), largest channel difference 10, RMS 1.667\n");
}

TEST_F(DiffCommand, ThresholdAndMaxPixelsLoosenTheMatch) {
  Outcome run = tumble("diff " + path("a.png") + " " + path("b.png") + " --threshold 9");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  run = tumble("diff " + path("a.png") + " " + path("b.png") + " --threshold 10");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(run.out,
            "match: 0 of 12 pixels differ (0%), largest channel difference 10, RMS 1.667\n");
  run = tumble("diff " + path("a.png") + " " + path("b.png") + " --max-pixels 1");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(run.out,
            "match: 1 of 12 pixels differ (8.33%), largest channel difference 10, RMS 1.667\n");
}

TEST_F(DiffCommand, OutWritesTheDiffImageAtTheImagesSize) {
  const Outcome run =
      tumble("diff " + path("a.png") + " " + path("b.png") + " --out " + path("diff.png"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  Image diff;
  ASSERT_EQ(::tumble::testing::take(tumble::io::read_png(path("diff.png")), diff), "");
  EXPECT_EQ(diff.width, 4);
  EXPECT_EQ(diff.height, 3);
  const std::uint8_t* changed = diff.row(1) + 3 * 2;
  EXPECT_EQ(changed[0], 128 + 10 / 2);  // red, brighter with the difference
  EXPECT_EQ(changed[1], 0);
  EXPECT_EQ(changed[2], 0);
  const std::uint8_t* same = diff.row(0);
  EXPECT_EQ(same[0], same[1]);  // grey
  EXPECT_EQ(same[1], same[2]);
}

TEST_F(DiffCommand, OutIsWrittenAlsoWhenTheImagesMatch) {
  const Outcome run =
      tumble("diff " + path("a.png") + " " + path("a_copy.png") + " --out " + path("diff.png"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  Image diff;
  ASSERT_EQ(::tumble::testing::take(tumble::io::read_png(path("diff.png")), diff), "");
  EXPECT_EQ(diff.width, 4);
  EXPECT_EQ(diff.height, 3);
}

TEST_F(DiffCommand, AMissingFileIsAnErrorWithExitTwo) {
  const Outcome run = tumble("diff " + path("a.png") + " " + path("absent.png"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err,
            "tumble: " + path("absent.png") + ": cannot open: No such file or directory\n");
  EXPECT_EQ(run.out, "");
}

TEST_F(DiffCommand, AFileThatIsNotAPngIsAnErrorWithExitTwo) {
  std::ofstream(dir_ / "notes.txt") << "not an image\n";
  const Outcome run = tumble("diff " + path("notes.txt") + " " + path("a.png"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path("notes.txt") + ": not a PNG file"), std::string::npos) << run.err;
}

TEST_F(DiffCommand, DifferentSizesAreAnErrorNamingBothSizes) {
  ASSERT_EQ(::tumble::testing::error_text(tumble::io::write_png(path("wide.png"), Image(5, 3))),
            "");
  const Outcome run =
      tumble("diff " + path("a.png") + " " + path("wide.png") + " --out " + path("diff.png"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "tumble: cannot compare images of different sizes: " + path("a.png") +
                         " is 4x3, " + path("wide.png") + " is 5x3\n");
  EXPECT_FALSE(fs::exists(dir_ / "diff.png"));
}

TEST_F(DiffCommand, AnUnwritableOutIsAnErrorWithExitTwo) {
  const Outcome run = tumble("diff " + path("a.png") + " " + path("a_copy.png") + " --out " +
                             path("no/such/diff.png"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no/such/diff.png"), std::string::npos) << run.err;
}

TEST_F(DiffCommand, OutOfRangeOptionsAreRefusedWithReadableMessages) {
  const std::string images = path("a.png") + " " + path("b.png");
  Outcome run = tumble("diff " + images + " --threshold 256");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("expected a whole number from 0 to 255, got 256"), std::string::npos)
      << run.err;
  run = tumble("diff " + images + " --threshold -1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("expected a whole number from 0 to 255, got -1"), std::string::npos)
      << run.err;
  run = tumble("diff " + images + " --max-pixels -1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("expected a whole number >= 0, got -1"), std::string::npos) << run.err;
  run = tumble("diff " + images + " --max-pixels 1.5");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(tumble("diff " + path("a.png")).exit_code, 2);
  EXPECT_EQ(run.out, "");
}

}  // namespace
