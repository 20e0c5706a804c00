// [render] motion_blur end to end: a dark cube crossing the view at 1 px per picture leaves, at
// each side, a ramp of partly covered pixels as long as the pictures' span (samples − 1 px; the
// sharp edge has at most its antialiased pixel); a chunk draws a blurred frame as the whole render
// does; the key is checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "io/png_io.hpp"
#include "support/command_test.hpp"
#include "support/result_text.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;
using tumble::testing::read_file;

// 320 × 180, fov 40° at 10 m: 2·10·tan 20° / 180 = 0.040444 m a pixel. At 30 frames/s, 8 pictures
// over half the frame interval are 1/480 s apart, so 19.413 m/s moves the cube 1 px a picture.
std::string scene(const std::string& blur) {
  return "name = \"blur\"\nduration = 0.2\n[physics]\ndt = 0.004166666666666667\n"
         "[[bodies]]\nname = \"cube\"\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n"
         "position = [-2.0, 0.0, 0.0]\nvelocity = [19.4133, 0.0, 0.0]\ncolor = \"#202020\"\n"
         "[camera]\nposition = [0.0, 0.0, 10.0]\nlook_at = [0.0, 0.0, 0.0]\n"
         "fov_degrees = 40.0\n[ground]\nheight = -5.0\n"
         "[render]\nwidth = 320\nheight = 180\nfps = 30\nshadows = false\n" +
         blur;
}

double linear(int level) {
  const double c = level / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The pixels of the middle row's two edges that the cube covers in part: its coverage, in linear
// light (c = (background − pixel) / (background − cube)), between 0.02 and 0.98. The row's first
// pixel is the background; the cube's level is the one in the middle of its dark run (its face;
// its dark outline, darker still, has c > 1). Counted left and right of that middle.
std::pair<int, int> edge_ramps(const tumble::io::Image& image) {
  const int row = image.height / 2;
  const auto red = [&](int x) { return static_cast<int>(image.rgb[3 * (row * image.width + x)]); };
  const double background = linear(red(0));
  int darkest = 255;
  for (int x = 0; x < image.width; ++x) darkest = std::min(darkest, red(x));
  long sum = 0, count = 0;
  for (int x = 0; x < image.width; ++x) {
    if (linear(red(x)) < 0.5 * (background + linear(darkest))) sum += x, count += 1;
  }
  const int middle = static_cast<int>(sum / count);
  const double cube = linear(red(middle));
  int left = 0, right = 0;
  for (int x = 0; x < image.width; ++x) {
    const double covered = (background - linear(red(x))) / (background - cube);
    if (covered > 0.02 && covered < 0.98) (x < middle ? left : right) += 1;
  }
  return {left, right};
}

class MotionBlur : public tumble::testing::CommandTest {
 protected:
  tumble::io::Image frame(const std::string& name, const std::string& blur, int k,
                          const std::string& arguments = "") {
    const fs::path file = write(name + ".toml", scene(blur));
    const Outcome run =
        tumble("render -q --no-video " + file.string() + " -o " + path(name) + " " + arguments);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    tumble::io::Image image;
    const fs::path folder =
        dir_ / name / ("blur" + std::string(arguments.empty() ? "" : ".chunk-2-of-2"));
    char png[32];
    std::snprintf(png, sizeof png, "frame_%05d.png", k);
    EXPECT_EQ(
        tumble::testing::take(tumble::io::read_png((folder / "frames" / png).string()), image), "");
    return image;
  }
};

TEST_F(MotionBlur, ACubeMovingAPixelAPictureLeavesARampAsLongAsTheShutter) {
  const tumble::io::Image sharp = frame("sharp", "", 3);
  const tumble::io::Image blurred =
      frame("blurred", "motion_blur = { samples = 8, shutter = 0.5 }\n", 3);
  const auto [sharp_left, sharp_right] = edge_ramps(sharp);
  const auto [left, right] = edge_ramps(blurred);
  std::printf("[ measured ] ramps: sharp %d and %d px, blurred %d and %d px\n", sharp_left,
              sharp_right, left, right);
  EXPECT_LE(sharp_left, 1);  // the sharp edge: its antialiased pixel at most
  EXPECT_LE(sharp_right, 1);
  // 8 pictures 1 px apart span 7 px: each edge ramps over 7 px (coverage 1/8 .. 7/8).
  EXPECT_NEAR(left, 7, 1);
  EXPECT_NEAR(right, 7, 1);
  // A quarter of the frame interval: 8 pictures half a pixel apart span 3.5 px.
  const tumble::io::Image quarter =
      frame("quarter", "motion_blur = { samples = 8, shutter = 0.25 }\n", 3);
  const auto [quarter_left, quarter_right] = edge_ramps(quarter);
  std::printf("[ measured ] ramps at a quarter's shutter: %d and %d px\n", quarter_left,
              quarter_right);
  EXPECT_NEAR(quarter_left, 3.5, 1);
  EXPECT_NEAR(quarter_right, 3.5, 1);
}

TEST_F(MotionBlur, AChunkDrawsABlurredFrameAsTheWholeRenderDoesAndTwoRunsAgree) {
  const std::string blur = "motion_blur = { samples = 8, shutter = 0.5 }\n";
  const tumble::io::Image whole = frame("whole", blur, 4);
  const tumble::io::Image again = frame("again", blur, 4);
  const tumble::io::Image chunk = frame("chunk", blur, 4, "--chunk 2/2");
  EXPECT_EQ(whole.rgb, again.rgb);
  EXPECT_EQ(whole.rgb, chunk.rgb);
}

TEST_F(MotionBlur, TheKeyIsCheckedWithItsLineAndKey) {
  const std::pair<std::string, std::string> cases[] = {
      {"motion_blur = 8\n", "render.motion_blur: expected a table"},
      {"motion_blur = { shutter = 0.5 }\n", "render.motion_blur.samples: missing required key"},
      {"motion_blur = { samples = 1 }\n", "render.motion_blur.samples: must be from 2 to 64"},
      {"motion_blur = { samples = 8, shutter = 1.5 }\n",
       "render.motion_blur.shutter: must be more than 0 and at most 1"},
      {"motion_blur = { samples = 8, speed = 1 }\n", "render.motion_blur.speed: unknown key"},
  };
  for (const auto& [key, message] : cases) {
    const fs::path file = write("bad.toml", scene(key));
    const Outcome run = tumble("check " + file.string());
    EXPECT_EQ(run.exit_code, 2) << key;
    EXPECT_NE(run.err.find(message), std::string::npos) << key << run.err;
    EXPECT_NE(run.err.find("bad.toml:24:"), std::string::npos) << key << run.err;
  }
}

}  // namespace
