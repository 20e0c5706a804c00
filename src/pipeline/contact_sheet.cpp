#include "pipeline/contact_sheet.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "render/text_layout.hpp"

namespace tumble::pipeline {
namespace {

constexpr std::array<std::uint8_t, 3> kStripColor = {38, 40, 44};  // gaps and strips
constexpr std::array<std::uint8_t, 3> kLabelColor = {235, 235, 235};

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

// Blends `label` in kLabelColor onto `sheet` by FreeType's coverage, "over" in sRGB-encoded
// values as the frames' text (render/text_layer.hpp): centred on column `centre_x`, its digits
// centred on row `centre_y`.
void draw_label(io::Image& sheet, render::Font& font, std::string_view label, int pixel_height,
                int centre_x, int centre_y) {
  // Laid out as the frames' text is (render::lay_out), at exactly `pixel_height` (a Text's
  // height is given at 720 rows), then its box centred on `centre_x`.
  const Result<render::TextLayout> placed = render::lay_out(
      font, render::Text{.text = std::string(label), .height = static_cast<double>(pixel_height)},
      sheet.width, render::kTextReferenceHeight);
  if (!placed) return;  // the label is ASCII: it always decodes
  const render::GlyphBitmap digit = font.rasterize(font.glyph_index(U'0'), pixel_height);
  const int shift_x = centre_x - (placed->box.x + placed->box.width / 2);
  for (const render::PlacedGlyph& glyph : placed->glyphs) {
    const render::GlyphBitmap bitmap = font.rasterize(glyph.glyph, pixel_height);
    const int baseline = centre_y + digit.top / 2;  // the digits centred on centre_y
    for (int y = 0; y < bitmap.height; ++y) {
      const int row = baseline - bitmap.top + y;
      if (row < 0 || row >= sheet.height) continue;
      for (int x = 0; x < bitmap.width; ++x) {
        const int column = glyph.x + shift_x + bitmap.left + x;
        const int cover = bitmap.coverage[static_cast<std::size_t>(y) * bitmap.width + x];
        if (column < 0 || column >= sheet.width || cover == 0) continue;
        std::uint8_t* pixel = sheet.row(row) + 3 * static_cast<std::size_t>(column);
        for (int c = 0; c < 3; ++c) {
          pixel[c] = static_cast<std::uint8_t>(
              (kLabelColor[c] * cover + pixel[c] * (255 - cover) + 127) / 255);
        }
      }
    }
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
  // Big enough for the digits to read (their height is about 0.73 of the em size, the strip's
  // height), a fifth or less of the pixel font's strip this replaced (11 × tile_height / 45).
  return std::max(8, tile_height / 22);
}

int sheet_gap(int tile_height) {
  return std::max(2, tile_height / 30);
}

std::array<int, 2> sheet_tile_origin(int index, int tile_width, int tile_height) {
  const int gap = sheet_gap(tile_height);
  const int column = index % kSheetColumns, row = index / kSheetColumns;
  return {gap + column * (tile_width + gap),
          gap + row * (tile_height + sheet_label_height(tile_height) + gap)};
}

Result<std::unique_ptr<ContactSheet>> ContactSheet::open(std::string path, std::int64_t first,
                                                         std::int64_t end, int fps,
                                                         const io::PngSettings& settings,
                                                         std::string_view font_family) {
  Result<std::unique_ptr<render::Font>> font = render::Font::open(font_family);
  if (!font) return Error{path + ": its labels' font: " + font.error()};
  std::unique_ptr<ContactSheet> out(new ContactSheet());
  out->path_ = std::move(path);
  out->fps_ = fps;
  out->settings_ = settings;
  out->font_ = std::move(*font);
  out->frames_ = contact_sheet_frames(first, end);
  return out;
}

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
  const int gap = sheet_gap(tile_height);
  io::Image sheet(gap + kSheetColumns * (tile_width + gap),
                  gap + kSheetRows * (tile_height + strip + gap));
  fill_rows(sheet, 0, 0, sheet.width, sheet.height, kStripColor);
  for (std::size_t i = 0; i < tiles_.size(); ++i) {
    const auto [left, top] = sheet_tile_origin(static_cast<int>(i), tile_width, tile_height);
    copy_into(sheet, tiles_[i], left, top);
    char label[40];
    std::snprintf(label, sizeof label, "t = %.2f s", static_cast<double>(frames_[i]) / fps_);
    draw_label(sheet, *font_, label, strip, left + tile_width / 2, top + tile_height + strip / 2);
  }
  return io::write_png(path_, sheet, settings_);
}

}  // namespace tumble::pipeline
