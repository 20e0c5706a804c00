// A font found through fontconfig by family name and read with FreeType: which characters it
// has, the metrics text is laid out with, and anti-aliased glyph bitmaps. Free of GL.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"

struct FT_LibraryRec_;  // FreeType's handles (FT_Library, FT_Face), kept out of this header
struct FT_FaceRec_;

namespace tumble::render {

// The documented default of `[render] font` (Debian: fonts-dejavu-core): it has the Greek
// letters and the physics symbols (ω τ θ Δ ² · → ≈ °) documentation videos show.
inline constexpr std::string_view kDefaultFontFamily = "DejaVu Sans";

// A font file as fontconfig names it.
struct FontFile {
  std::string path;
  int face_index = 0;  // of the face within the file (a .ttc holds several)
};

// The regular face of `family` (case-insensitive). Fontconfig always answers with some font; one
// that does not have `family` among its family names is an error naming the family and what
// fontconfig offered instead.
Result<FontFile> find_font(std::string_view family);

// Vertical metrics at a pixel height, rounded outwards to whole pixels.
struct LineMetrics {
  int ascender = 0;     // from the baseline up to the top of the tallest glyphs (px)
  int descender = 0;    // from the baseline down to the bottom of the lowest glyphs (px, >= 0)
  int line_height = 0;  // from one baseline to the next (px)
};

// A glyph's coverage, as FreeType's anti-aliasing rasteriser draws it.
struct GlyphBitmap {
  int width = 0;   // px
  int height = 0;  // px
  int left = 0;    // from the pen position to the bitmap's left column, rightwards (px)
  int top = 0;     // from the baseline to the bitmap's top row, upwards (px)
  std::vector<std::uint8_t> coverage;  // width × height, top row first: 0 = none, 255 = full
};

class Font {
 public:
  // find_font(family), then load().
  static Result<std::unique_ptr<Font>> open(std::string_view family);
  // Reads the file with FreeType; an error names the path and FreeType's error.
  static Result<std::unique_ptr<Font>> load(const FontFile& file);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  const FontFile& file() const { return file_; }

  // The font's glyph for `code_point`; 0 (the missing-glyph box, .notdef) when it has none.
  std::uint32_t glyph_index(char32_t code_point) const;
  // The characters of `text` the font has no glyph for, each once, in the order they first
  // appear ('\n' separates lines and needs none), for the caller to warn naming each
  // (describe_character in render/utf8.hpp).
  std::vector<char32_t> missing_characters(std::u32string_view text) const;

  // Metrics at `pixel_height`, the em size in pixels (what FreeType calls the pixel size).
  LineMetrics line_metrics(int pixel_height) const;
  // The pen's advance after `glyph` (1/64 px): unhinted, so that text scales with its height.
  // Kept once found: a live value lays out the same glyphs every frame.
  std::int32_t advance(std::uint32_t glyph, int pixel_height);
  // The kerning between `left` and `right` added to the pen (1/64 px), 0 when the font has no
  // kerning table.
  std::int32_t kerning(std::uint32_t left, std::uint32_t right, int pixel_height);
  // The glyph rasterised anti-aliased (FT_RENDER_MODE_NORMAL) without hinting: the same bitmap
  // on every run, from the outline alone.
  GlyphBitmap rasterize(std::uint32_t glyph, int pixel_height);

 private:
  Font(FT_LibraryRec_* library, FT_FaceRec_* face, FontFile file);
  // Sets the face to `pixel_height` unless it is there; false if FreeType fails.
  bool use_size(int pixel_height);
  // Loads `glyph` at `pixel_height` into the face's glyph slot; false if FreeType fails.
  bool load_glyph(std::uint32_t glyph, int pixel_height);

  FT_LibraryRec_* library_;
  FT_FaceRec_* face_;
  FontFile file_;
  int pixel_height_ = 0;  // the size the face is set to, 0 = none yet
  std::map<std::pair<std::uint32_t, int>, std::int32_t> advances_;  // by (glyph, pixel height)
};

}  // namespace tumble::render
