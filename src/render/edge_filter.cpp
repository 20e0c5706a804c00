#include "render/edge_filter.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <vector>

namespace tumble::render {
namespace {

// Below this luma contrast (of 255) among a pixel and its four neighbours nothing is filtered,
// nor below a quarter of the brightest of them (FXAA's threshold for its cheaper quality). The
// ground's grid lines, already smoothed by their shader, and the soft steps between faces of one
// colour stay below it; a sixth (FXAA's default) sends twice the pixels of a frame of many boxes
// through the edge walk for no difference to see.
constexpr int kContrastFloor = 16;
constexpr int kContrastRelative = 4;
// Pixels walked along an edge each way to find where its step ends: a staircase flatter than
// this many pixels per step is smoothed only near its steps.
constexpr int kEdgeSearch = 12;
// How far a pixel whose luma differs from its neighbourhood's mean (a sub-pixel feature) may be
// blended towards its neighbour (FXAA's sub-pixel term).
constexpr float kSubpixelStrength = 0.5f;

// Rec. 601 weights in 8.8 fixed point: green counts most, as for the eye.
int luma_of(const std::uint8_t* pixel) {
  return (77 * pixel[0] + 150 * pixel[1] + 29 * pixel[2] + 128) >> 8;
}

// Every pixel's luma (0 to 255), with a border of kEdgeSearch + 1 copies of the outermost
// pixels around the picture, so that no look-up near or along an edge needs a bounds check.
struct Luma {
  static constexpr int kBorder = kEdgeSearch + 1;
  std::vector<std::uint8_t> values;
  std::ptrdiff_t stride;  // values per row

  Luma(const std::uint8_t* rgba, int width, int height)
      : values(static_cast<std::size_t>(width + 2 * kBorder) * (height + 2 * kBorder)),
        stride(width + 2 * kBorder) {
    for (int y = 0; y < height; ++y) {
      std::uint8_t* row = at(0, y);
      const std::uint8_t* source = rgba + 4 * static_cast<std::size_t>(y) * width;
      for (int x = 0; x < width; ++x) row[x] = static_cast<std::uint8_t>(luma_of(source + 4 * x));
      std::fill(row - kBorder, row, row[0]);
      std::fill(row + width, row + width + kBorder, row[width - 1]);
    }
    for (int y = 1; y <= kBorder; ++y) {
      std::copy_n(at(-kBorder, 0), stride, at(-kBorder, -y));
      std::copy_n(at(-kBorder, height - 1), stride, at(-kBorder, height - 1 + y));
    }
  }
  std::uint8_t* at(int x, int y) { return values.data() + (y + kBorder) * stride + (x + kBorder); }
};

// The share (0 to 1) of the neighbour across the edge at `centre` to blend into the pixel, and
// which neighbour: FXAA's edge walk (Lottes 2009, "FXAA", NVIDIA white paper), on whole pixels.
struct Blend {
  float share = 0.0f;
  int dx = 0, dy = 0;  // the neighbour's offset (pixels)
};

Blend edge_blend(const std::uint8_t* centre, std::ptrdiff_t stride, int range) {
  const int m = centre[0];
  const int n = centre[-stride], s = centre[stride], w = centre[-1], e = centre[1];
  const int nw = centre[-stride - 1], ne = centre[-stride + 1];
  const int sw = centre[stride - 1], se = centre[stride + 1];

  // Second differences across rows (large on a horizontal edge) and across columns.
  const int across_rows =
      std::abs(nw + sw - 2 * w) + 2 * std::abs(n + s - 2 * m) + std::abs(ne + se - 2 * e);
  const int across_columns =
      std::abs(nw + ne - 2 * n) + 2 * std::abs(w + e - 2 * m) + std::abs(sw + se - 2 * s);
  const bool horizontal = across_rows >= across_columns;
  // The two neighbours across the edge; the one of the steeper step is the other side.
  const int before = horizontal ? n : w, after = horizontal ? s : e;
  const bool towards_after = std::abs(after - m) > std::abs(before - m);
  const int other = towards_after ? after : before;
  const int step = towards_after ? 1 : -1;
  const std::ptrdiff_t across = horizontal ? step * stride : step;
  const std::ptrdiff_t along = horizontal ? 1 : stride;

  // Walk along the edge (the pair of rows, or columns, either side of it) each way until the
  // pair's mean luma leaves the edge's by a quarter of the step across it: there the step of
  // the staircase ends. In twice-lumas, to stay in whole numbers.
  const int edge_sum = m + other;
  const int tolerance = std::abs(other - m);  // twice a quarter of the step, doubled
  const auto walk = [&](std::ptrdiff_t direction, int& end_difference) {
    const std::uint8_t* p = centre;
    for (int i = 1; i <= kEdgeSearch; ++i) {
      p += direction;
      end_difference = p[0] + p[across] - edge_sum;
      if (2 * std::abs(end_difference) >= tolerance) return i;
    }
    end_difference = 0;
    return kEdgeSearch + 1;
  };
  int end_back = 0, end_forward = 0;
  const int distance_back = walk(-along, end_back);
  const int distance_forward = walk(along, end_forward);
  const bool back_nearer = distance_back < distance_forward;
  const int nearest = std::min(distance_back, distance_forward);
  // The straightened edge crosses this pixel's row (column) by this share of a pixel, falling
  // from 1/2 next to the step's end to 0 halfway along the step.
  const float edge_share = 0.5f - (static_cast<float>(nearest) - 0.5f) /
                                      static_cast<float>(distance_back + distance_forward - 1);
  // Only on the side of the step where the edge moves into this pixel's colour: the pixel is
  // darker than the edge and the step's end is brighter, or the other way round.
  const int end_difference = back_nearer ? end_back : end_forward;
  const bool moves_in = end_difference != 0 && (end_difference < 0) != (2 * m < edge_sum);
  float share = moves_in ? std::max(edge_share, 0.0f) : 0.0f;

  // Sub-pixel features (a line thinner than a pixel) get a share from the local contrast.
  const float mean = static_cast<float>(2 * (n + s + w + e) + (nw + ne + sw + se)) / 12.0f;
  const float contrast =
      std::min(std::abs(mean - static_cast<float>(m)) / static_cast<float>(range), 1.0f);
  const float smooth = (3.0f - 2.0f * contrast) * contrast * contrast;  // smoothstep
  share = std::max(share, smooth * smooth * kSubpixelStrength);
  return Blend{share, horizontal ? 0 : step, horizontal ? step : 0};
}

// RGBA to RGB; the pixels on edges are overwritten afterwards. Four bytes at a time, each store's
// fourth byte (alpha) overwritten by the next pixel's red.
void copy_rgb(const std::uint8_t* rgba, std::size_t pixel_count, std::uint8_t* rgb) {
  if (pixel_count == 0) return;
  for (std::size_t i = 0; i + 1 < pixel_count; ++i) std::memcpy(rgb + 3 * i, rgba + 4 * i, 4);
  std::memcpy(rgb + 3 * (pixel_count - 1), rgba + 4 * (pixel_count - 1), 3);
}

// The rows of boxes to leave unfiltered, swept down the picture: a row meets only the boxes
// that span it (a frame's captions are a hundred glyph boxes, each a few dozen rows high).
class Unfiltered {
 public:
  explicit Unfiltered(const std::vector<PixelBox>& boxes) : by_top_(boxes) {
    std::sort(by_top_.begin(), by_top_.end(),
              [](const PixelBox& a, const PixelBox& b) { return a.y < b.y; });
  }

  // Marks the pixels of row `y` inside the boxes as not to filter. Called for rows in
  // increasing order. Precondition: boxes within the picture.
  void leave(int y, std::vector<std::uint8_t>& range) {
    while (next_ < by_top_.size() && by_top_[next_].y <= y) spanning_.push_back(by_top_[next_++]);
    std::erase_if(spanning_, [y](const PixelBox& box) { return box.y + box.height <= y; });
    for (const PixelBox& box : spanning_) {
      std::fill_n(range.begin() + box.x, box.width, std::uint8_t{0});
    }
  }

 private:
  std::vector<PixelBox> by_top_;
  std::size_t next_ = 0;
  std::vector<PixelBox> spanning_;
};

}  // namespace

void filter_edges(const std::uint8_t* rgba, int width, int height, io::Image& out,
                  const std::vector<PixelBox>& unfiltered, bool with_alpha) {
  if (out.width != width || out.height != height) out = io::Image(width, height);
  const std::size_t pixel_count = static_cast<std::size_t>(width) * height;
  copy_rgb(rgba, pixel_count, out.rgb.data());
  const int channels = with_alpha ? 4 : 3;
  if (with_alpha) {
    out.alpha.resize(pixel_count);
    for (std::size_t i = 0; i < pixel_count; ++i) out.alpha[i] = rgba[4 * i + 3];
  } else {
    out.alpha.clear();
  }
  Luma luma(rgba, width, height);
  std::vector<std::uint8_t> range(static_cast<std::size_t>(width));  // of a row's pixels
  Unfiltered text(unfiltered);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = luma.at(0, y);
    const std::uint8_t* up = row - luma.stride;
    const std::uint8_t* down = row + luma.stride;
    // First the contrast of every pixel of the row, without branches (the compiler vectorises
    // this loop), 0 where it is too low to filter; then the few pixels above it.
    for (int x = 0; x < width; ++x) {
      const int highest =
          std::max(std::max(std::max(row[x], up[x]), std::max(down[x], row[x - 1])), row[x + 1]);
      const int lowest =
          std::min(std::min(std::min(row[x], up[x]), std::min(down[x], row[x - 1])), row[x + 1]);
      const int contrast = highest - lowest;
      const bool filtered = contrast >= kContrastFloor && contrast * kContrastRelative >= highest;
      range[static_cast<std::size_t>(x)] = static_cast<std::uint8_t>(filtered ? contrast : 0);
    }
    text.leave(y, range);
    for (int x = 0; x < width; ++x) {
      if (range[static_cast<std::size_t>(x)] == 0) {
        // Most of a row is not on an edge: skip eight pixels at a time where none is.
        std::uint64_t eight = 0;
        while (x + 8 <= width &&
               (std::memcpy(&eight, &range[static_cast<std::size_t>(x)], 8), eight == 0)) {
          x += 8;
        }
        if (x >= width || range[static_cast<std::size_t>(x)] == 0) continue;
      }
      const std::uint8_t* centre = row + x;
      const Blend blend = edge_blend(centre, luma.stride, range[static_cast<std::size_t>(x)]);
      // Borders: the neighbour beyond the picture is the pixel itself, as the luma's border.
      const int nx = std::clamp(x + blend.dx, 0, width - 1);
      const int ny = std::clamp(y + blend.dy, 0, height - 1);
      const std::uint8_t* source = rgba + 4 * (static_cast<std::size_t>(y) * width + x);
      const std::uint8_t* neighbour = rgba + 4 * (static_cast<std::size_t>(ny) * width + nx);
      std::uint8_t* target = out.row(y) + 3 * x;
      for (int c = 0; c < channels; ++c) {
        const float mixed = source[c] + blend.share * static_cast<float>(neighbour[c] - source[c]);
        // Rounded; stays within 0..255.
        const auto value = static_cast<std::uint8_t>(mixed + 0.5f);
        if (c < 3) {
          target[c] = value;
        } else {
          out.alpha[static_cast<std::size_t>(y) * width + x] = value;
        }
      }
    }
  }
}

}  // namespace tumble::render
