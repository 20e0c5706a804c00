// What the renderer's golden-image tests share: the shaders and goldens of the source tree, one
// frame drawn by a fresh renderer, and the comparison with a stored golden (TUMBLE_UPDATE_GOLDEN=1
// writes the golden instead: look at it before committing it).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "diff/image_diff.hpp"
#include "io/png_io.hpp"
#include "render/renderer.hpp"
#include "support/result_text.hpp"

namespace tumble::testing {

inline const std::string kShaders = std::string(TUMBLE_SOURCE_DIR) + "/shaders";
inline const std::string kGoldens = std::string(TUMBLE_SOURCE_DIR) + "/tests/render/golden/";

inline io::Image draw(const render::RenderSettings& settings, const render::FrameView& view) {
  std::string error;
  const auto renderer =
      ::tumble::testing::value_or_empty(render::Renderer::create(settings, kShaders), error);
  EXPECT_TRUE(renderer) << error;
  io::Image image;
  if (renderer) renderer->draw(view, image);
  return image;
}

inline void expect_matches_golden(const io::Image& image, const std::string& name,
                                  const diff::DiffOptions& tolerance) {
  const std::string path = kGoldens + name + ".png";
  if (std::getenv("TUMBLE_UPDATE_GOLDEN")) {
    ASSERT_EQ(::tumble::testing::error_text(
                  io::write_png(path, image, {.compression_level = 9, .filter = true})),
              "");
    GTEST_SKIP() << "wrote " << path;
  }
  io::Image golden;
  ASSERT_EQ(::tumble::testing::take(io::read_png(path), golden), "");
  ASSERT_EQ(golden.width, image.width);
  ASSERT_EQ(golden.height, image.height);
  const diff::DiffResult diff = diff::compare_images(golden, image, tolerance);
  EXPECT_TRUE(diff.match) << name << ": " << diff.differing_pixels << " pixels differ, largest "
                          << diff.max_channel_difference << ", rms " << diff.rms;
}

}  // namespace tumble::testing
