#include "render/font.hpp"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cassert>
#include <cstring>

namespace tumble::render {
namespace {

// Unhinted outlines (hinting bends them to the pixel grid differently at each size) without
// embedded bitmaps (a font's bitmap strikes would replace the outline at some sizes only).
constexpr FT_Int32 kLoadFlags = FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP;

const FcChar8* fc_text(std::string_view text, std::string& storage) {
  storage.assign(text);
  return reinterpret_cast<const FcChar8*>(storage.c_str());
}

// The family names of a fontconfig pattern, "A, B".
std::string family_names(FcPattern* pattern) {
  std::string out;
  FcChar8* name = nullptr;
  for (int n = 0; FcPatternGetString(pattern, FC_FAMILY, n, &name) == FcResultMatch; ++n) {
    out += (out.empty() ? "" : ", ") + std::string(reinterpret_cast<const char*>(name));
  }
  return out;
}

bool has_family(FcPattern* pattern, const FcChar8* family) {
  FcChar8* name = nullptr;
  for (int n = 0; FcPatternGetString(pattern, FC_FAMILY, n, &name) == FcResultMatch; ++n) {
    if (FcStrCmpIgnoreCase(name, family) == 0) return true;
  }
  return false;
}

// Fontconfig's best match for `family` in `config`, checked to have that family.
Result<FontFile> match_in(FcConfig* config, std::string_view family) {
  std::string storage;
  const FcChar8* wanted = fc_text(family, storage);
  FcPattern* pattern = FcPatternCreate();
  FcPatternAddString(pattern, FC_FAMILY, wanted);
  FcPatternAddBool(pattern, FC_SCALABLE, FcTrue);  // outlines, to draw at any height
  FcConfigSubstitute(config, pattern, FcMatchPattern);
  FcDefaultSubstitute(pattern);  // regular weight, upright
  FcResult result = FcResultNoMatch;
  FcPattern* match = FcFontMatch(config, pattern, &result);
  FcPatternDestroy(pattern);
  const std::string quoted = "font family \"" + std::string(family) + "\"";
  if (!match) return Error{quoted + ": fontconfig finds no font at all (is fontconfig set up?)"};
  Result<FontFile> out = Error{quoted + " is not installed (fontconfig offers " +
                               family_names(match) + " instead; `fc-list : family` lists them)"};
  FcChar8* path = nullptr;
  int index = 0;
  if (has_family(match, wanted) && FcPatternGetString(match, FC_FILE, 0, &path) == FcResultMatch) {
    FcPatternGetInteger(match, FC_INDEX, 0, &index);
    out = FontFile{reinterpret_cast<const char*>(path), index};
  }
  FcPatternDestroy(match);
  return out;
}

}  // namespace

Result<FontFile> find_font(std::string_view family) {
  // A configuration of our own, destroyed after the match: nothing of fontconfig outlives the
  // call (the process-wide one would, and the sanitizer build counts it as a leak).
  FcConfig* config = FcInitLoadConfigAndFonts();
  if (!config) return Error{"fontconfig cannot load its configuration"};
  Result<FontFile> out = match_in(config, family);
  FcConfigDestroy(config);
  return out;
}

Result<std::unique_ptr<Font>> Font::open(std::string_view family) {
  const Result<FontFile> file = find_font(family);
  if (!file) return Error{file.error()};
  return load(*file);
}

Result<std::unique_ptr<Font>> Font::load(const FontFile& file) {
  FT_Library library = nullptr;
  if (const FT_Error code = FT_Init_FreeType(&library)) {
    return Error{"FreeType cannot start (error " + std::to_string(code) + ")"};
  }
  FT_Face face = nullptr;
  if (const FT_Error code = FT_New_Face(library, file.path.c_str(), file.face_index, &face)) {
    const char* why = FT_Error_String(code);  // null unless FreeType keeps its messages
    FT_Done_FreeType(library);
    return Error{file.path + ": FreeType cannot read the font (" +
                 (why ? std::string(why) : "error " + std::to_string(code)) + ")"};
  }
  if (!FT_IS_SCALABLE(face)) {
    FT_Done_Face(face);
    FT_Done_FreeType(library);
    return Error{file.path + ": not an outline font (text is drawn at any height)"};
  }
  return std::unique_ptr<Font>(new Font(library, face, file));
}

Font::Font(FT_LibraryRec_* library, FT_FaceRec_* face, FontFile file)
    : library_(library), face_(face), file_(std::move(file)) {}

Font::~Font() {
  FT_Done_Face(face_);
  FT_Done_FreeType(library_);
}

std::uint32_t Font::glyph_index(char32_t code_point) const {
  return FT_Get_Char_Index(face_, code_point);
}

std::vector<char32_t> Font::missing_characters(std::u32string_view text) const {
  std::vector<char32_t> out;
  for (const char32_t c : text) {
    if (c == U'\n' || glyph_index(c) != 0) continue;
    if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  }
  return out;
}

LineMetrics Font::line_metrics(int pixel_height) const {
  // From the font's design units (FT_Face's ascender, descender, height), rounded outwards, in
  // integers: the same pixels on every machine.
  const long units = face_->units_per_EM;
  const auto ceil_scaled = [&](long value) {
    return static_cast<int>((value * pixel_height + units - 1) / units);
  };
  LineMetrics out;
  out.ascender = ceil_scaled(face_->ascender);
  out.descender = ceil_scaled(-static_cast<long>(face_->descender));
  out.line_height = std::max(ceil_scaled(face_->height), out.ascender + out.descender);
  return out;
}

bool Font::use_size(int pixel_height) {
  if (pixel_height == pixel_height_) return true;
  if (FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(pixel_height)) != 0) return false;
  pixel_height_ = pixel_height;
  return true;
}

bool Font::load_glyph(std::uint32_t glyph, int pixel_height) {
  return use_size(pixel_height) && FT_Load_Glyph(face_, glyph, kLoadFlags) == 0;
}

std::int32_t Font::advance(std::uint32_t glyph, int pixel_height) {
  const auto key = std::make_pair(glyph, pixel_height);
  if (const auto found = advances_.find(key); found != advances_.end()) return found->second;
  if (!load_glyph(glyph, pixel_height)) return 0;
  const auto advance = static_cast<std::int32_t>(face_->glyph->advance.x);
  advances_.emplace(key, advance);
  return advance;
}

std::int32_t Font::kerning(std::uint32_t left, std::uint32_t right, int pixel_height) {
  if (!FT_HAS_KERNING(face_) || left == 0 || right == 0) return 0;
  if (!use_size(pixel_height)) return 0;
  FT_Vector delta{0, 0};
  // Unfitted: in 1/64 px as designed, not rounded to the grid, like the unhinted advances.
  if (FT_Get_Kerning(face_, left, right, FT_KERNING_UNFITTED, &delta) != 0) return 0;
  return static_cast<std::int32_t>(delta.x);
}

GlyphBitmap Font::rasterize(std::uint32_t glyph, int pixel_height) {
  GlyphBitmap out;
  if (!load_glyph(glyph, pixel_height)) return out;
  FT_GlyphSlot slot = face_->glyph;
  if (FT_Render_Glyph(slot, FT_RENDER_MODE_NORMAL) != 0) return out;
  const FT_Bitmap& bitmap = slot->bitmap;
  assert(bitmap.pixel_mode == FT_PIXEL_MODE_GRAY || bitmap.width == 0);
  assert(bitmap.pitch >= 0);  // the smooth rasteriser writes rows top first
  out.width = static_cast<int>(bitmap.width);
  out.height = static_cast<int>(bitmap.rows);
  out.left = slot->bitmap_left;
  out.top = slot->bitmap_top;
  out.coverage.resize(static_cast<std::size_t>(out.width) * out.height);
  for (int y = 0; y < out.height; ++y) {
    const unsigned char* row = bitmap.buffer + static_cast<std::ptrdiff_t>(y) * bitmap.pitch;
    std::memcpy(out.coverage.data() + static_cast<std::size_t>(y) * out.width, row,
                static_cast<std::size_t>(out.width));
  }
  return out;
}

}  // namespace tumble::render
