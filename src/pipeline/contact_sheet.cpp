#include "pipeline/contact_sheet.hpp"

#include <algorithm>
#include <cstdio>

#include "io/pixel_font.hpp"

namespace tumble::pipeline {
namespace {

constexpr std::array<std::uint8_t, 3> kStripColor = {38, 40, 44};
constexpr std::array<std::uint8_t, 3> kLabelColor = {235, 235, 235};

// Image pixels per font pixel, at least 1: labels 7 font pixels tall read at a glance beside a
// tile when they are about a sixth of its height (28 px under the 180-row tiles of a 720p render).
int label_scale(int tile_height) {
  return std::max(1, tile_height / 45);
}

void copy_into(io::Image& sheet, const io::Image& tile, int left, int top) {
  for (int y = 0; y < tile.height; ++y) {
    std::copy(tile.row(y), tile.row(y) + tile.row_bytes(),
              sheet.row(top + y) + 3 * static_cast<std::size_t>(left));
  }
}

void fill_rows(io::Image& sheet, int left, int top, int width, int height,
               const std::array<std::uint8_t, 3>& rgb) {
  for (int y = top; y < top + height; ++y) {
    std::uint8_t* pixel = sheet.row(y) + 3 * static_cast<std::size_t>(left);
    for (int x = 0; x < width; ++x, pixel += 3) std::copy(rgb.begin(), rgb.end(), pixel);
  }
}

}  // namespace

std::vector<std::int64_t> contact_sheet_frames(std::int64_t first, std::int64_t end) {
  const std::int64_t count = end - first;
  std::vector<std::int64_t> frames;
  if (count <= kSheetTiles) {
    for (std::int64_t k = first; k < end; ++k) frames.push_back(k);
    return frames;
  }
  for (std::int64_t i = 0; i < kSheetTiles; ++i) {
    frames.push_back(first + (2 * i * (count - 1) + (kSheetTiles - 1)) / (2 * (kSheetTiles - 1)));
  }
  return frames;
}

io::Image shrink_for_sheet(const io::Image& image) {
  io::Image out(std::max(1, image.width / kSheetShrink), std::max(1, image.height / kSheetShrink));
  const int block_width = std::min(kSheetShrink, image.width);
  const int block_height = std::min(kSheetShrink, image.height);
  const int samples = block_width * block_height;
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int dy = 0; dy < block_height; ++dy) {
          const std::uint8_t* row = image.row(y * kSheetShrink + dy);
          for (int dx = 0; dx < block_width; ++dx) sum += row[3 * (x * kSheetShrink + dx) + c];
        }
        out.row(y)[3 * x + c] = static_cast<std::uint8_t>((sum + samples / 2) / samples);
      }
    }
  }
  return out;
}

int sheet_label_height(int tile_height) {
  return (io::kPixelFontHeight + 4) * label_scale(tile_height);
}

ContactSheet::ContactSheet(std::string path, std::int64_t first, std::int64_t end, int fps,
                           const io::PngSettings& settings)
    : path_(std::move(path)),
      fps_(fps),
      settings_(settings),
      frames_(contact_sheet_frames(first, end)) {}

Result<void> ContactSheet::write(std::int64_t frame, const io::Image& image) {
  if (std::find(frames_.begin(), frames_.end(), frame) != frames_.end()) {
    tiles_.push_back(shrink_for_sheet(image));
  }
  return Result<void>::success();
}

Result<void> ContactSheet::finish() {
  if (tiles_.empty()) return Result<void>::success();
  const int tile_width = tiles_.front().width;
  const int tile_height = tiles_.front().height;
  const int strip = sheet_label_height(tile_height);
  const int scale = label_scale(tile_height);
  io::Image sheet(kSheetColumns * tile_width, kSheetRows * (tile_height + strip));
  fill_rows(sheet, 0, 0, sheet.width, sheet.height, kStripColor);
  for (std::size_t i = 0; i < tiles_.size(); ++i) {
    const int left = static_cast<int>(i % kSheetColumns) * tile_width;
    const int top = static_cast<int>(i / kSheetColumns) * (tile_height + strip);
    copy_into(sheet, tiles_[i], left, top);
    char label[40];
    std::snprintf(label, sizeof label, "t = %.2f s", static_cast<double>(frames_[i]) / fps_);
    const int label_left = left + (tile_width - io::pixel_text_width(label, scale)) / 2;
    io::draw_pixel_text(sheet, label_left, top + tile_height + 2 * scale, scale, label,
                        kLabelColor);
  }
  return io::write_png(path_, sheet, settings_);
}

}  // namespace tumble::pipeline
