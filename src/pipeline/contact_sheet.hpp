// contact_sheet.png: twelve frames of a render at a quarter of their size, in a grid of four
// columns and three rows read like text, apart by gaps, each above a thin strip that gives its
// time in the scene's font, to see a whole motion at a glance.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/frame_sinks.hpp"
#include "render/font.hpp"

namespace tumble::pipeline {

inline constexpr int kSheetColumns = 4;
inline constexpr int kSheetRows = 3;
inline constexpr int kSheetTiles = kSheetColumns * kSheetRows;
inline constexpr int kSheetShrink = 4;  // a tile is the frame shrunk this many times each way

// The frames a sheet of the rendered frames [first, end) shows, in order: twelve spread evenly
// from first to end − 1 (tile i shows first + round(i (n − 1) / 11), n = end − first), or every
// frame when fewer than twelve are rendered.
std::vector<std::int64_t> contact_sheet_frames(std::int64_t first, std::int64_t end);

// `image` shrunk kSheetShrink times each way (width / 4 × height / 4, rounded down, at least 1):
// each pixel the rounded mean of its 4 × 4 block (alpha left out).
io::Image shrink_for_sheet(const io::Image& image);

// The height in pixels of the strip under each tile that holds its time, for tiles of
// `tile_height` pixels: tile_height / 22, at least 8 (8 under the 180-row tiles of a 720p render).
int sheet_label_height(int tile_height);
// The gap in pixels between tiles, and around them: tile_height / 30, at least 2.
int sheet_gap(int tile_height);
// The top-left pixel (x, y) of tile `index` (0 .. kSheetTiles − 1, read like text) on the sheet.
std::array<int, 2> sheet_tile_origin(int index, int tile_width, int tile_height);

// Collects the tiles as their frames pass, and composes and writes the sheet at finish().
class ContactSheet final : public FrameSink {
 public:
  // A sheet of the rendered frames [first, end) of a video at `fps` frames per second, its
  // times written in `font_family` (fontconfig's name: the scene's [render] font), opened here,
  // before any frame is drawn: an error names the sheet and the font.
  static Result<std::unique_ptr<ContactSheet>> open(
      std::string path, std::int64_t first, std::int64_t end, int fps,
      const io::PngSettings& settings, std::string_view font_family = render::kDefaultFontFamily);
  const char* stage() const override { return "contact_sheet"; }
  Result<void> write(std::int64_t frame, const io::Image& image) override;
  // Writes the sheet; an error when the PNG cannot be written.
  Result<void> finish() override;

 private:
  ContactSheet() = default;
  std::string path_;
  int fps_ = 1;
  io::PngSettings settings_;
  std::unique_ptr<render::Font> font_;
  std::vector<std::int64_t> frames_;  // shown, in tile order
  std::vector<io::Image> tiles_;      // one per frame of frames_, once it has passed
};

}  // namespace tumble::pipeline
