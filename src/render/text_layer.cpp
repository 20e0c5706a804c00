#include "render/text_layer.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <optional>

namespace tumble::render {
namespace {

constexpr int kFirstAtlasSize = 512;  // texels per side: a few hundred glyphs of 720p captions
constexpr int kMaxAtlasSize = 8192;   // 64 MB: glyphs of any frame's texts, at any size

bool contains(const PixelBox& outer, const PixelBox& inner) {
  return inner.x >= outer.x && inner.y >= outer.y &&
         inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
}

// `box` cut to the frame; nothing when none of it is inside.
std::optional<PixelBox> clipped(const PixelBox& box, int width, int height) {
  const int x0 = std::max(box.x, 0), y0 = std::max(box.y, 0);
  const int x1 = std::min(box.x + box.width, width), y1 = std::min(box.y + box.height, height);
  if (x1 <= x0 || y1 <= y0) return std::nullopt;
  return PixelBox{x0, y0, x1 - x0, y1 - y0};
}

Eigen::Vector4f premultiply(const Rgba& color, double opacity) {
  const double alpha = std::clamp(color.w() * opacity, 0.0, 1.0);
  const Eigen::Vector3d rgb = color.head<3>().cwiseMax(0.0).cwiseMin(1.0) * alpha;
  return Eigen::Vector4f(static_cast<float>(rgb.x()), static_cast<float>(rgb.y()),
                         static_cast<float>(rgb.z()), static_cast<float>(alpha));
}

// In 0-255 units: out = colour × coverage + in × (1 - alpha × coverage), rounded. Channel 3 is
// the alpha itself: alpha × coverage + in × (1 - alpha × coverage), "over" for the alpha plane.
std::uint8_t blend_byte(const Eigen::Vector4f& color, int channel, float cover, std::uint8_t in) {
  const float keep = 1.0f - color.w() * cover;
  const float value = 255.0f * color[channel] * cover + static_cast<float>(in) * keep;
  return static_cast<std::uint8_t>(std::min(value, 255.0f) + 0.5f);
}

// An atlas texel of 255, as blend_byte receives it.
constexpr float kGlyphFullCover = 255 * (1.0f / 255.0f);

// blend_byte of every input byte, for one colour and one coverage.
class FullCoverTable {
 public:
  void prepare(const Eigen::Vector4f& color, float cover) {
    if (ready_ && color == color_ && cover == cover_) return;
    for (int c = 0; c < 4; ++c) {
      for (int in = 0; in < 256; ++in) {
        table_[c][in] = blend_byte(color, c, cover, static_cast<std::uint8_t>(in));
      }
    }
    color_ = color;
    cover_ = cover;
    ready_ = true;
  }
  void apply(std::uint8_t* pixel) const {
    for (int c = 0; c < 3; ++c) pixel[c] = table_[c][pixel[c]];
  }
  void apply_alpha(std::uint8_t& alpha) const { alpha = table_[3][alpha]; }

 private:
  std::array<std::array<std::uint8_t, 256>, 4> table_{};
  Eigen::Vector4f color_;
  float cover_ = 0.0f;
  bool ready_ = false;
};

}  // namespace

Result<std::unique_ptr<TextLayer>> TextLayer::create(int width, int height,
                                                     std::string_view font_family) {
  std::unique_ptr<TextLayer> out(new TextLayer());
  out->width_ = width;
  out->height_ = height;
  Result<std::unique_ptr<Font>> font = Font::open(font_family);
  if (!font) return Error{font.error()};
  out->font_ = std::move(font).value();
  out->atlas_ = GlyphAtlas(kFirstAtlasSize, kMaxAtlasSize);
  return out;
}

void TextLayer::add(const PixelBox& box, int texel_x, int texel_y, const Eigen::Vector4f& color) {
  const std::optional<PixelBox> inside = clipped(box, width_, height_);
  if (!inside) return;
  // The texel under the clipped box's top-left, as under the whole box's.
  const int dx = inside->x - box.x, dy = inside->y - box.y;
  pieces_.push_back(Piece{*inside, texel_x < 0 ? -1 : texel_x + dx, texel_y + dy, color});
}

std::vector<PixelBox> TextLayer::lay_out(const std::vector<Text>& texts) {
  pieces_.clear();
  std::vector<PixelBox> drawn_on;
  std::vector<PixelBox> labels;  // the boxes of the texts that keep apart, so far
  for (const Text& text : texts) {
    Result<TextLayout> layout = render::lay_out(*font_, text, width_, height_);
    assert(layout.ok() && "text must be checked with decode_utf8 before it is drawn");
    if (!layout) continue;
    if (text.keep_apart) {
      // A label's gap: a tenth of its em size, at least a pixel.
      const int gap = std::max(1, layout->pixel_height / 10);
      const PixelBox placed = place_apart(layout->box, labels, width_, height_, gap);
      for (PlacedGlyph& glyph : layout->glyphs) {
        glyph.x += placed.x - layout->box.x;
        glyph.y += placed.y - layout->box.y;
      }
      layout->box = placed;
      labels.push_back(placed);
    }
    std::vector<PixelBox> kept;
    const Eigen::Vector4f background =
        premultiply(text.background.value_or(Rgba::Zero()), text.opacity);
    const bool boxed = background.w() > 0.0f;
    if (boxed) {
      add(layout->box, -1, 0, background);
      kept.push_back(layout->box);
    }
    const Eigen::Vector4f color = premultiply(text.color, text.opacity);
    for (const PlacedGlyph& placed : layout->glyphs) {
      if (color.w() == 0.0f) break;
      const auto glyph = atlas_.find_or_add(*font_, placed.glyph, layout->pixel_height);
      assert(glyph && "a frame's glyphs fit in an atlas of kMaxAtlasSize");
      if (!glyph || glyph->width == 0) continue;  // a space has no bitmap
      const PixelBox box{placed.x + glyph->left, placed.y - glyph->top, glyph->width,
                         glyph->height};
      add(box, glyph->x, glyph->y, color);
      // Inside the background box already kept, unless it reaches past it (a deep descender).
      const PixelBox grown{box.x - 1, box.y - 1, box.width + 2, box.height + 2};
      if (!boxed || !contains(layout->box, grown)) kept.push_back(grown);
    }
    for (const PixelBox& box : kept) {
      if (const auto inside = clipped(box, width_, height_)) drawn_on.push_back(*inside);
    }
  }
  return drawn_on;
}

void TextLayer::draw(io::Image& image) const {
  const bool has_alpha = !image.alpha.empty();
  const std::vector<std::uint8_t>& texels = atlas_.texels();
  const std::size_t atlas_size = static_cast<std::size_t>(atlas_.size());
  // A box's pixels, and most of a glyph's (its stems), are fully covered: there the result
  // depends on the input byte alone, so it is looked up, worked out once per colour and
  // coverage by blend_byte itself (the same bytes as computing it per pixel).
  FullCoverTable full;
  for (const Piece& piece : pieces_) {
    const bool is_solid = piece.texel_x < 0;
    full.prepare(piece.color, is_solid ? 1.0f : kGlyphFullCover);
    for (int y = 0; y < piece.box.height; ++y) {
      std::uint8_t* out = image.row(piece.box.y + y) + 3 * piece.box.x;
      // The alpha plane's row, or a byte that is written and never read.
      std::uint8_t unused = 0;
      std::uint8_t* alpha =
          has_alpha ? image.alpha.data() + static_cast<std::size_t>(piece.box.y + y) * image.width +
                          piece.box.x
                    : &unused;
      const int alpha_step = has_alpha ? 1 : 0;
      if (is_solid) {
        for (int x = 0; x < piece.box.width; ++x, out += 3, alpha += alpha_step) {
          full.apply(out);
          full.apply_alpha(*alpha);
        }
        continue;
      }
      const std::uint8_t* coverage =
          &texels[static_cast<std::size_t>(piece.texel_y + y) * atlas_size +
                  static_cast<std::size_t>(piece.texel_x)];
      for (int x = 0; x < piece.box.width; ++x, out += 3, alpha += alpha_step) {
        if (coverage[x] == 0) continue;
        if (coverage[x] == 255) {
          full.apply(out);
          full.apply_alpha(*alpha);
          continue;
        }
        const float cover = coverage[x] * (1.0f / 255.0f);
        for (int c = 0; c < 3; ++c) out[c] = blend_byte(piece.color, c, cover, out[c]);
        *alpha = blend_byte(piece.color, 3, cover, *alpha);
      }
    }
  }
}

}  // namespace tumble::render
