// contact_sheet.png: twelve frames of a render at a quarter of their size, in a grid of four
// columns and three rows read like text, each above a strip that gives its time, to see a whole
// motion at a glance.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/frame_sinks.hpp"

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
// `tile_height` pixels.
int sheet_label_height(int tile_height);

// Collects the tiles as their frames pass, and composes and writes the sheet at finish().
class ContactSheet final : public FrameSink {
 public:
  // A sheet of the rendered frames [first, end) of a video at `fps` frames per second.
  ContactSheet(std::string path, std::int64_t first, std::int64_t end, int fps,
               const io::PngSettings& settings);
  const char* stage() const override { return "contact_sheet"; }
  Result<void> write(std::int64_t frame, const io::Image& image) override;
  Result<void> finish() override;

 private:
  std::string path_;
  int fps_;
  io::PngSettings settings_;
  std::vector<std::int64_t> frames_;  // shown, in tile order
  std::vector<io::Image> tiles_;      // one per frame of frames_, once it has passed
};

}  // namespace tumble::pipeline
