// The font the text tests draw with: DejaVu Sans through fontconfig, as a scene gets by default.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "render/font.hpp"

namespace tumble::testing {

inline std::unique_ptr<render::Font> default_font() {
  Result<std::unique_ptr<render::Font>> font = render::Font::open(render::kDefaultFontFamily);
  EXPECT_TRUE(font) << font.error();
  return font ? std::move(font).value() : nullptr;
}

}  // namespace tumble::testing
