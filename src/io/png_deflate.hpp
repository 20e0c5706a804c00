// A PNG's image data (the zlib stream of its filtered scanlines, PNG specification 10.1) from
// tumble's own deflate encoder, made for rendered frames and for speed: every row gets the Sub
// filter, and the only matches looked for are the bytes one pixel back and one row back, which
// is where a rendered picture repeats itself (flat colour, a steady gradient, a row like the one
// above). No hash table and no search: on the default scene's 720p frames 1.9 times zlib level
// 1's speed, in files a tenth larger (docs/performance.md has the figures). Standards followed: RFC 1950 (zlib
// stream), RFC 1951 (deflate, dynamic Huffman blocks), Huffman code lengths limited to 15 (7 for
// the code-length code) by the package-merge algorithm (Larmore and Hirschberg 1990), which
// gives the optimal limited code.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tumble::io {

class ScanlineDeflater {
 public:
  // Rows of `row_bytes` bytes of `bytes_per_pixel`-byte pixels: 3 (RGB) or 4 (RGBA).
  ScanlineDeflater(std::size_t row_bytes, int bytes_per_pixel);

  // Filters the next row (top row first) and compresses it.
  void add_row(const std::uint8_t* pixels);

  // The zlib stream of every row added, ending the deflate data and adding its Adler-32. Call
  // once, after the last row.
  std::vector<std::uint8_t> finish();

 private:
  void emit_block(bool last);

  std::size_t row_bytes_;
  std::size_t stride_;  // a filtered row: its filter type byte and its bytes
  std::size_t bytes_per_pixel_;
  // The previous filtered row, then this one: matches one row back read the first half.
  std::vector<std::uint8_t> rows_;
  std::uint32_t pixel_code_, row_code_;  // the distance codes of one pixel back and one row back
  bool first_row_ = true;
  std::vector<std::uint32_t> tokens_;  // literals, and matches (length, distance)
  std::size_t token_count_ = 0;
  std::array<std::uint32_t, 286> literal_counts_{};
  std::array<std::uint32_t, 30> distance_counts_{};
  std::uint32_t adler_a_ = 1, adler_b_ = 0;
  std::vector<std::uint8_t> out_;  // the stream so far: its first out_size_ bytes
  std::size_t out_size_ = 0;
  std::uint64_t bits_ = 0;  // fewer than 8 bits not yet in out_, lowest first
  int bit_count_ = 0;
};

// Adler-32 (RFC 1950 section 8.2) of `size` bytes continued from the running sums a (starts at
// 1) and b (starts at 0).
void adler32_update(const std::uint8_t* data, std::size_t size, std::uint32_t& a, std::uint32_t& b);

// The lengths, at most `limit` bits, of an optimal prefix code for symbols of these counts (0: the
// symbol is not coded, length 0). Two symbols at least get a length, so that the code is complete
// (RFC 1951's decoders refuse an incomplete one): if fewer are counted, the lowest-numbered
// uncounted ones are added as if counted once. Precondition: 2 <= counts.size() <= 2^limit.
std::vector<std::uint8_t> limited_code_lengths(const std::vector<std::uint32_t>& counts, int limit);

}  // namespace tumble::io
