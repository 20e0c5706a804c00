// Golden-image and determinism tests of the renderer. Goldens live in tests/render/golden/; to
// regenerate them after an intended change of the look, run the test with TUMBLE_UPDATE_GOLDEN=1
// and look at the new images before committing them.
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "io/image_diff.hpp"
#include "io/png_io.hpp"

namespace tumble::render {
namespace {

const std::string kShaders = std::string(TUMBLE_SOURCE_DIR) + "/shaders";
const std::string kGoldens = std::string(TUMBLE_SOURCE_DIR) + "/tests/render/golden/";

// Same machine, same Mesa: renders are bit-identical (see DrawingTwiceIsByteIdentical). The
// tolerance absorbs another Mesa or LLVM version rounding a shading or rasterisation decision
// differently: a pixel may differ by up to 8 of 255 per channel, and up to 1% of pixels by more.
constexpr io::DiffOptions kGoldenTolerance{.threshold = 8, .max_pixels = 160 * 120 / 100};

RenderSettings small_settings() {
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.ground.height = -1.0;
  return settings;
}

FrameView cube_view(const Quat& orientation) {
  FrameView view;
  view.camera.position = Vec3(2.6, 2.0, 3.6);
  view.boxes.push_back(Box{.orientation = orientation});
  return view;
}

io::Image draw(const RenderSettings& settings, const FrameView& view) {
  std::string error;
  const auto renderer = Renderer::create(settings, kShaders, error);
  EXPECT_TRUE(renderer) << error;
  io::Image image;
  if (renderer) renderer->draw(view, image);
  return image;
}

void expect_matches_golden(const io::Image& image, const std::string& name) {
  const std::string path = kGoldens + name + ".png";
  if (std::getenv("TUMBLE_UPDATE_GOLDEN")) {
    ASSERT_EQ(io::write_png(path, image, {.compression_level = 9, .filter = true}), "");
    GTEST_SKIP() << "wrote " << path;
  }
  io::Image golden;
  ASSERT_EQ(io::read_png(path, golden), "");
  ASSERT_EQ(golden.width, image.width);
  ASSERT_EQ(golden.height, image.height);
  const io::DiffResult diff = io::compare_images(golden, image, kGoldenTolerance);
  EXPECT_TRUE(diff.match) << name << ": " << diff.differing_pixels << " pixels differ, largest "
                          << diff.max_channel_difference << ", rms " << diff.rms;
}

TEST(Renderer, CubeAtRestMatchesGolden) {
  expect_matches_golden(draw(small_settings(), cube_view(Quat::Identity())), "cube_at_rest");
}

TEST(Renderer, TiltedBoxMatchesGolden) {
  FrameView view = cube_view(Quat(Eigen::AngleAxisd(0.7, Vec3(1, 0.5, 0.2).normalized())));
  view.boxes[0].size = Vec3(0.4, 1.0, 1.6);
  view.boxes[0].color = Color(0.2, 0.5, 0.8);
  expect_matches_golden(draw(small_settings(), view), "tilted_box");
}

TEST(Renderer, TwoBoxesWithoutGroundOrShadowsOrMsaaMatchGolden) {
  RenderSettings settings = small_settings();
  settings.ground.enabled = false;
  settings.shadows = false;
  settings.msaa = 1;
  FrameView view = cube_view(Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY())));
  view.boxes.push_back(Box{.position = Vec3(-1.2, 0.3, -0.5), .color = Color(0.3, 0.7, 0.3)});
  expect_matches_golden(draw(settings, view), "two_boxes_plain");
}

TEST(Renderer, DrawingTwiceIsByteIdentical) {
  const FrameView view = cube_view(Quat(Eigen::AngleAxisd(0.3, Vec3(0, 1, 1).normalized())));
  std::string error;
  const auto renderer = Renderer::create(small_settings(), kShaders, error);
  ASSERT_TRUE(renderer) << error;
  io::Image first, second;
  renderer->draw(view, first);
  renderer->draw(cube_view(Quat::Identity()), second);  // something else in between
  renderer->draw(view, second);
  EXPECT_EQ(first.rgb, second.rgb);
  // And a fresh renderer draws the same bytes.
  EXPECT_EQ(draw(small_settings(), view).rgb, first.rgb);
}

// The image is upright and the background and ground are where they belong: the top row is the
// background colour (sRGB as given, no ground reaches it), the bottom row is ground.
TEST(Renderer, ImageIsUprightWithBackgroundAboveAndGroundBelow) {
  RenderSettings settings = small_settings();
  settings.background = Color(0.2, 0.4, 0.6);
  settings.ground.color = Color(0.9, 0.9, 0.1);
  settings.ground.grid_spacing = 0.0;
  FrameView view = cube_view(Quat::Identity());
  view.camera.look_at = Vec3(0, 1.8, 0);  // looking level: the horizon crosses the middle
  const io::Image image = draw(settings, view);
  const std::uint8_t* top = image.row(0);
  EXPECT_NEAR(top[0], 51, 1);   // 0.2 * 255
  EXPECT_NEAR(top[1], 102, 1);  // 0.4 * 255
  EXPECT_NEAR(top[2], 153, 1);  // 0.6 * 255
  const std::uint8_t* bottom = image.row(image.height - 1);
  EXPECT_GT(bottom[0], 100);  // lit yellow ground: red and green well above blue
  EXPECT_GT(bottom[1], 100);
  EXPECT_LT(bottom[2], bottom[0] / 2);
}

TEST(Renderer, MissingShaderIsAClearErrorNamingTheFile) {
  std::string error;
  const auto renderer = Renderer::create(small_settings(), "/nonexistent/shaders", error);
  EXPECT_FALSE(renderer);
  EXPECT_NE(error.find("/nonexistent/shaders/body.vert: cannot open shader file"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace tumble::render
