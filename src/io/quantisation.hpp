// What an H.264 video's quantiser may have changed in the pictures it was encoded from, so that a
// comparison of the video with those pictures does not count it.
//
// H.264 codes each block's residual as transform coefficients rounded to multiples of a quantiser
// step Qstep(QP) (ITU-T H.264 §8.5.12; Richardson, "The H.264 Advanced Video Compression
// Standard", 2010, §7.2.3). The transform is orthonormal up to the scale folded into Qstep, so by
// Parseval a block whose coefficients are each rounded to the nearest multiple differs from its
// source by an RMS of at most Qstep / 2 per pixel. A 1-pixel shift of a sharp edge, by contrast,
// leaves an RMS of the edge's contrast times the shift over the pixels it crosses.
#pragma once

#include <cstdint>
#include <vector>

#include "io/image.hpp"

namespace tumble::io {

// Macroblocks are 16x16 luma pixels, from the top-left corner of the picture.
inline constexpr int kMacroblockSize = 16;

// How much a video's quantiser may change a picture. Steps in the video's Y'CbCr levels (limited
// range: Y' 16-235, Cb and Cr 16-240).
struct QuantisationAllowance {
  int qp = -1;               // the H.264 QP the steps are for; -1: no allowance
  double luma_step = 0.0;    // Qstep of the luma quantiser (levels)
  double chroma_step = 0.0;  // Qstep of the chroma quantiser (levels)
  double kr = 0.2126;        // the video's luma weights of red and blue (BT.709 here)
  double kb = 0.0722;
  bool full_range = false;  // Y'CbCr in 0-255 rather than limited range

  bool active() const { return qp >= 0; }
};

// H.264's quantiser step for QP 0-51 (levels): 0.625, 0.6875, 0.8125, 0.875, 1, 1.125 for QP
// 0-5, doubling with every 6 more (Richardson 2010, Table 7.2).
double h264_quantiser_step(int qp);

// The chroma QP for luma QP `qp` plus the stream's chroma_qp_index_offset (H.264 Table 8-15:
// equal below 30, 29 at 30 rising to 39 at 51).
int h264_chroma_qp(int qp, int chroma_qp_offset);

// The allowance of an H.264 stream whose coarsest macroblock QP is `qp`, with the matrix
// (swscale's SWS_CS_* number) and range of its Y'CbCr.
QuantisationAllowance h264_allowance(int qp, int chroma_qp_offset, int sws_matrix, bool full_range);

// For each macroblock (row by row, ceil(width / 16) per row): 1 when the RMS of the Y', Cb and Cr
// differences of a and b within it (from their RGB through the allowance's matrix) are each at
// most half their step, else 0. Precondition: equal sizes, allowance active.
std::vector<std::uint8_t> macroblocks_within(const Image& a, const Image& b,
                                             const QuantisationAllowance& allowance);

}  // namespace tumble::io
