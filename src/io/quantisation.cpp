#include "io/quantisation.hpp"

#include <algorithm>
#include <cassert>

#include "io/video_decoder.hpp"

namespace tumble::io {
namespace {

// Sums of squared Y', Cb and Cr differences over one macroblock, and its pixel count.
struct BlockSums {
  double luma = 0.0, blue = 0.0, red = 0.0;
  int pixels = 0;
};

}  // namespace

double h264_quantiser_step(int qp) {
  static const double kFirstSix[] = {0.625, 0.6875, 0.8125, 0.875, 1.0, 1.125};
  const int clamped = std::clamp(qp, 0, 51);
  return kFirstSix[clamped % 6] * static_cast<double>(1 << (clamped / 6));
}

int h264_chroma_qp(int qp, int chroma_qp_offset) {
  static const int kAbove29[] = {29, 30, 31, 32, 32, 33, 34, 34, 35, 35, 36,
                                 36, 37, 37, 37, 38, 38, 38, 39, 39, 39, 39};
  const int index = std::clamp(qp + chroma_qp_offset, 0, 51);
  return index < 30 ? index : kAbove29[index - 30];
}

QuantisationAllowance h264_allowance(int qp, int chroma_qp_offset, int sws_matrix,
                                     bool full_range) {
  const YuvMatrix weights = yuv_matrix(sws_matrix);
  return {qp,
          h264_quantiser_step(qp),
          h264_quantiser_step(h264_chroma_qp(qp, chroma_qp_offset)),
          weights.kr,
          weights.kb,
          full_range};
}

std::vector<std::uint8_t> macroblocks_within(const Image& a, const Image& b,
                                             const QuantisationAllowance& allowance) {
  assert(a.width == b.width && a.height == b.height && allowance.active());
  const int columns = (a.width + kMacroblockSize - 1) / kMacroblockSize;
  const int rows = (a.height + kMacroblockSize - 1) / kMacroblockSize;
  std::vector<BlockSums> sums(static_cast<std::size_t>(columns) * rows);
  const double kr = allowance.kr, kb = allowance.kb, kg = 1.0 - kr - kb;
  // RGB levels (0-255) to Y' and Cb/Cr levels of the video's range.
  const double luma_scale = allowance.full_range ? 1.0 : 219.0 / 255.0;
  const double chroma_scale = allowance.full_range ? 1.0 : 224.0 / 255.0;
  for (int y = 0; y < a.height; ++y) {
    const std::uint8_t* pa = a.row(y);
    const std::uint8_t* pb = b.row(y);
    BlockSums* row = &sums[static_cast<std::size_t>(y / kMacroblockSize) * columns];
    for (int x = 0; x < a.width; ++x, pa += 3, pb += 3) {
      const double red = pa[0] - pb[0], green = pa[1] - pb[1], blue = pa[2] - pb[2];
      const double luma = kr * red + kg * green + kb * blue;
      const double cb = (blue - luma) / (2.0 * (1.0 - kb)) * chroma_scale;  // BT.709 eq. 3.4
      const double cr = (red - luma) / (2.0 * (1.0 - kr)) * chroma_scale;
      BlockSums& block = row[x / kMacroblockSize];
      block.luma += luma * luma * luma_scale * luma_scale;
      block.blue += cb * cb;
      block.red += cr * cr;
      ++block.pixels;
    }
  }
  // RMS <= step / 2  <=>  sum of squares <= pixels · step² / 4.
  const double luma_limit = allowance.luma_step * allowance.luma_step / 4.0;
  const double chroma_limit = allowance.chroma_step * allowance.chroma_step / 4.0;
  std::vector<std::uint8_t> within(sums.size());
  for (std::size_t n = 0; n < sums.size(); ++n) {
    const BlockSums& block = sums[n];
    within[n] = block.luma <= block.pixels * luma_limit &&
                block.blue <= block.pixels * chroma_limit &&
                block.red <= block.pixels * chroma_limit;
  }
  return within;
}

}  // namespace tumble::io
