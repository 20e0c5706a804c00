#include "io/png_deflate.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>

namespace tumble::io {
namespace {

// RFC 1951 section 3.2.5: the length symbols 257 to 285 and the distance codes 0 to 29, each a
// base and a count of extra bits.
constexpr std::array<std::uint16_t, 29> kLengthBase = {3,  4,  5,  6,   7,   8,   9,   10,  11, 13,
                                                       15, 17, 19, 23,  27,  31,  35,  43,  51, 59,
                                                       67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<std::uint8_t, 29> kLengthExtra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                                       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr std::array<std::uint16_t, 30> kDistanceBase = {
    1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr std::array<std::uint8_t, 30> kDistanceExtra = {0, 0, 0,  0,  1,  1,  2,  2,  3,  3,
                                                         4, 4, 5,  5,  6,  6,  7,  7,  8,  8,
                                                         9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
// The order the code-length code's lengths are sent in (RFC 1951 section 3.2.7).
constexpr std::array<std::uint8_t, 19> kCodeLengthOrder = {16, 17, 18, 0, 8,  7, 9,  6, 10, 5,
                                                           11, 4,  12, 3, 13, 2, 14, 1, 15};
constexpr int kMaxMatch = 258;
constexpr std::size_t kMaxDistance = 32768;
// A match of three bytes costs about what three literals cost; from four on it saves.
constexpr int kMinMatch = 4;
// A block's Huffman codes are fitted to its own tokens: a new block every this many tokens (its
// header costs about 80 bytes).
constexpr std::size_t kBlockTokens = 1 << 15;
constexpr std::uint32_t kMatchFlag = 1u << 31;

// The length symbol (index into kLengthBase) of every match length 0 to 258.
constexpr std::array<std::uint8_t, kMaxMatch + 1> kLengthSymbol = [] {
  std::array<std::uint8_t, kMaxMatch + 1> table{};
  for (int length = 3; length <= kMaxMatch; ++length) {
    int symbol = 28;
    while (kLengthBase[static_cast<std::size_t>(symbol)] > length) --symbol;
    table[static_cast<std::size_t>(length)] = static_cast<std::uint8_t>(symbol);
  }
  return table;
}();

std::uint32_t distance_code(std::uint32_t distance) {
  std::uint32_t code = 29;
  while (kDistanceBase[static_cast<std::size_t>(code)] > distance) --code;
  return code;
}

// The number of equal bytes at a and b, at most `limit`.
int match_length(const std::uint8_t* a, const std::uint8_t* b, int limit) {
  int length = 0;
  while (length + 8 <= limit) {
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, a + length, 8);
    std::memcpy(&y, b + length, 8);
    if (x != y) return length + std::countr_zero(x ^ y) / 8;  // little-endian: first byte lowest
    length += 8;
  }
  while (length < limit && a[length] == b[length]) ++length;
  return length;
}

// PNG's Sub filter (filter type 1): each byte less the byte one pixel to its left. With the
// pixel's size a constant and the two rows apart, the compiler vectorises it.
template <std::size_t kBytesPerPixel>
void sub_filter(const std::uint8_t* __restrict pixels, std::uint8_t* __restrict out,
                std::size_t size) {
  for (std::size_t i = 0; i < kBytesPerPixel; ++i) out[i] = pixels[i];
  for (std::size_t i = kBytesPerPixel; i < size; ++i) {
    out[i] = static_cast<std::uint8_t>(pixels[i] - pixels[i - kBytesPerPixel]);
  }
}

// Canonical Huffman codes from their lengths (RFC 1951 section 3.2.2), bit-reversed: deflate sends
// a code's first bit first into a stream filled from the lowest bit.
std::vector<std::uint16_t> canonical_codes(const std::vector<std::uint8_t>& lengths) {
  std::array<std::uint16_t, 16> count{}, next{};
  for (std::uint8_t length : lengths) ++count[length];
  count[0] = 0;
  std::uint16_t code = 0;
  for (std::size_t bits = 1; bits < 16; ++bits) {
    code = static_cast<std::uint16_t>((code + count[bits - 1]) << 1);
    next[bits] = code;
  }
  std::vector<std::uint16_t> codes(lengths.size(), 0);
  for (std::size_t symbol = 0; symbol < lengths.size(); ++symbol) {
    const int length = lengths[symbol];
    if (length == 0) continue;
    const std::uint16_t forward = next[static_cast<std::size_t>(length)]++;
    std::uint16_t reversed = 0;
    for (int bit = 0; bit < length; ++bit) {
      reversed =
          static_cast<std::uint16_t>(reversed | (((forward >> bit) & 1u) << (length - 1 - bit)));
    }
    codes[symbol] = reversed;
  }
  return codes;
}

struct CodeLengthSymbol {
  std::uint8_t symbol;  // 0 to 18
  std::uint8_t extra;   // the repeat count's extra bits' value (16, 17, 18)
};

// The code lengths run-length coded with symbols 16 (repeat the last 3 to 6 times), 17 (3 to 10
// zeros) and 18 (11 to 138 zeros), RFC 1951 section 3.2.7.
std::vector<CodeLengthSymbol> run_length_code(const std::vector<std::uint8_t>& lengths) {
  std::vector<CodeLengthSymbol> out;
  std::size_t i = 0;
  while (i < lengths.size()) {
    const std::uint8_t value = lengths[i];
    std::size_t run = 1;
    while (i + run < lengths.size() && lengths[i + run] == value) ++run;
    i += run;
    if (value == 0) {
      while (run >= 11) {
        const std::size_t n = std::min<std::size_t>(run, 138);
        out.push_back({18, static_cast<std::uint8_t>(n - 11)});
        run -= n;
      }
      if (run >= 3) {
        out.push_back({17, static_cast<std::uint8_t>(run - 3)});
        run = 0;
      }
    } else {
      out.push_back({value, 0});
      --run;
      while (run >= 3) {
        const std::size_t n = std::min<std::size_t>(run, 6);
        out.push_back({16, static_cast<std::uint8_t>(n - 3)});
        run -= n;
      }
    }
    for (; run > 0; --run) out.push_back({value, 0});
  }
  return out;
}

}  // namespace

void adler32_update(const std::uint8_t* data, std::size_t size, std::uint32_t& a,
                    std::uint32_t& b) {
  constexpr std::uint32_t kModulus = 65521;
  // The most bytes after which b, taken below the modulus before, still fits in 32 bits
  // (RFC 1950's NMAX).
  constexpr std::size_t kRun = 5552;
  while (size > 0) {
    std::size_t n = std::min(size, kRun);
    size -= n;
    // In blocks of 32: b gains 32 a plus the bytes weighted 32, 31, ... 1, and a their sum,
    // the same sums as byte by byte. The weighted sum in 16-bit products, which the compiler
    // makes a vector multiply-add.
    for (; n >= 32; n -= 32, data += 32) {
      std::int32_t sum = 0, weighted = 0;
      for (int k = 0; k < 32; ++k) {
        const std::int16_t byte = data[k];
        sum += byte;
        weighted += byte * static_cast<std::int16_t>(32 - k);
      }
      b += 32 * a + static_cast<std::uint32_t>(weighted);
      a += static_cast<std::uint32_t>(sum);
    }
    for (; n > 0; --n) {
      a += *data++;
      b += a;
    }
    a %= kModulus;
    b %= kModulus;
  }
}

std::vector<std::uint8_t> limited_code_lengths(const std::vector<std::uint32_t>& counts,
                                               int limit) {
  assert(counts.size() >= 2 && counts.size() <= (std::size_t{1} << limit));
  std::vector<std::uint64_t> weight(counts.begin(), counts.end());
  std::size_t used = static_cast<std::size_t>(
      std::count_if(weight.begin(), weight.end(), [](std::uint64_t w) { return w > 0; }));
  for (std::size_t s = 0; s < weight.size() && used < 2; ++s) {
    if (weight[s] == 0) weight[s] = 1, ++used;
  }
  // The leaves, lightest first (ties by symbol: the same code every run).
  std::vector<std::uint16_t> leaves;
  for (std::size_t s = 0; s < weight.size(); ++s) {
    if (weight[s] > 0) leaves.push_back(static_cast<std::uint16_t>(s));
  }
  std::stable_sort(leaves.begin(), leaves.end(),
                   [&](std::uint16_t x, std::uint16_t y) { return weight[x] < weight[y]; });
  const std::size_t n = leaves.size();

  // Package-merge: list k holds the leaves merged with the pairs of list k - 1, lightest first
  // (a leaf before a pair of the same weight); list 0 is the leaves. Kept per list: each item's
  // weight and whether it is a leaf.
  std::vector<std::vector<std::uint64_t>> list_weight(static_cast<std::size_t>(limit));
  std::vector<std::vector<std::uint8_t>> list_leaf(static_cast<std::size_t>(limit));
  for (std::uint16_t s : leaves) list_weight[0].push_back(weight[s]);
  list_leaf[0].assign(n, 1);
  for (std::size_t k = 1; k < static_cast<std::size_t>(limit); ++k) {
    const std::vector<std::uint64_t>& below = list_weight[k - 1];
    std::size_t leaf = 0, pair = 0;
    const std::size_t pairs = below.size() / 2;
    while (leaf < n || pair < pairs) {
      const std::uint64_t pair_weight = pair < pairs ? below[2 * pair] + below[2 * pair + 1] : 0;
      if (leaf < n && (pair >= pairs || weight[leaves[leaf]] <= pair_weight)) {
        list_weight[k].push_back(weight[leaves[leaf++]]);
        list_leaf[k].push_back(1);
      } else {
        list_weight[k].push_back(pair_weight);
        list_leaf[k].push_back(0);
        ++pair;
      }
    }
  }
  // The first 2n - 2 items of the last list are the solution; a leaf's length is the number of
  // lists in which it is taken. The leaves taken from a list are its lightest, and its pairs
  // taken are made of the first items of the list below.
  std::vector<std::uint8_t> lengths(counts.size(), 0);
  std::size_t take = 2 * n - 2;
  for (std::size_t k = static_cast<std::size_t>(limit); k-- > 0;) {
    std::size_t taken_leaves = 0;
    for (std::size_t i = 0; i < take; ++i) taken_leaves += list_leaf[k][i];
    for (std::size_t i = 0; i < taken_leaves; ++i) ++lengths[leaves[i]];
    take = 2 * (take - taken_leaves);
  }
  return lengths;
}

ScanlineDeflater::ScanlineDeflater(std::size_t row_bytes, int bytes_per_pixel)
    : row_bytes_(row_bytes),
      stride_(row_bytes + 1),
      bytes_per_pixel_(static_cast<std::size_t>(bytes_per_pixel)),
      rows_(2 * (row_bytes + 1)),
      pixel_code_(distance_code(static_cast<std::uint32_t>(bytes_per_pixel))),
      row_code_(stride_ <= kMaxDistance ? distance_code(static_cast<std::uint32_t>(stride_)) : 0) {
  assert((bytes_per_pixel == 3 || bytes_per_pixel == 4) &&
         row_bytes >= static_cast<std::size_t>(bytes_per_pixel));
  // A row adds at most stride_ tokens after the last block was sent.
  tokens_.resize(kBlockTokens + stride_);
  // CMF: deflate with a 32 KiB window; FLG: the fastest level, no dictionary, and the check bits
  // that make CMF * 256 + FLG a multiple of 31.
  out_ = {0x78, 0x01};
  out_size_ = 2;
}

void ScanlineDeflater::add_row(const std::uint8_t* pixels) {
  std::uint8_t* previous = rows_.data();
  std::uint8_t* row = rows_.data() + stride_;
  if (!first_row_) std::memcpy(previous, row, stride_);
  row[0] = 1;  // the Sub filter
  const std::size_t bpp = bytes_per_pixel_;
  if (bpp == 3) {
    sub_filter<3>(pixels, row + 1, row_bytes_);
  } else {
    sub_filter<4>(pixels, row + 1, row_bytes_);
  }
  adler32_update(row, stride_, adler_a_, adler_b_);

  // Greedy matching against the two candidates: one pixel back in this row, one row back.
  const bool above = !first_row_ && stride_ <= kMaxDistance;
  const int end = static_cast<int>(stride_);
  int p = 0;
  while (p < end) {
    const int limit = std::min(kMaxMatch, end - p);
    int best = 0;
    std::uint32_t distance = 0;
    if (static_cast<std::size_t>(p) >= bpp) {
      best = match_length(row + p, row + p - bpp, limit);
      distance = static_cast<std::uint32_t>(bpp);
    }
    if (above && best < limit) {
      const int length = match_length(row + p, previous + p, limit);
      if (length > best) best = length, distance = static_cast<std::uint32_t>(stride_);
    }
    if (best >= kMinMatch) {
      const std::uint32_t code = distance == bpp ? pixel_code_ : row_code_;
      tokens_[token_count_++] =
          kMatchFlag | (code << 25) | (static_cast<std::uint32_t>(best) << 16) | (distance - 1);
      ++literal_counts_[257 + kLengthSymbol[static_cast<std::size_t>(best)]];
      ++distance_counts_[code];
      p += best;
    } else {
      // No match here: none either, nearly always, at the rest of this pixel's bytes (they
      // changed with it). Literals to the next pixel's first byte, without looking.
      const int next =
          std::min(end, p + 1 + static_cast<int>((bpp - static_cast<std::size_t>(p) % bpp) % bpp));
      for (; p < next; ++p) {
        tokens_[token_count_++] = row[p];
        ++literal_counts_[row[p]];
      }
    }
  }
  first_row_ = false;
  if (token_count_ >= kBlockTokens) emit_block(false);
}

void ScanlineDeflater::emit_block(bool last) {
  // Room for the block: its header and each token at most 48 bits, plus a word of slack for
  // the whole-word stores below.
  std::size_t size = out_size_;
  const std::size_t room = size + 1024 + 6 * token_count_ + 8;
  if (out_.size() < room) out_.resize(std::max(room, 2 * out_.size()));
  const auto put = [&](std::uint32_t value, int count) {
    bits_ |= static_cast<std::uint64_t>(value) << bit_count_;
    bit_count_ += count;
    if (bit_count_ >= 32) {
      const auto word = static_cast<std::uint32_t>(bits_);
      const std::uint8_t bytes[4] = {
          static_cast<std::uint8_t>(word), static_cast<std::uint8_t>(word >> 8),
          static_cast<std::uint8_t>(word >> 16), static_cast<std::uint8_t>(word >> 24)};
      std::memcpy(out_.data() + size, bytes, 4);
      size += 4;
      bits_ >>= 32;
      bit_count_ -= 32;
    }
  };
  literal_counts_[256] = 1;  // the end of the block
  const std::vector<std::uint8_t> literal_lengths =
      limited_code_lengths({literal_counts_.begin(), literal_counts_.end()}, 15);
  const std::vector<std::uint8_t> distance_lengths =
      limited_code_lengths({distance_counts_.begin(), distance_counts_.end()}, 15);
  const std::vector<std::uint16_t> literal_codes = canonical_codes(literal_lengths);
  const std::vector<std::uint16_t> distance_codes = canonical_codes(distance_lengths);

  // The header: both codes' lengths, as few as are used (at least 257 and 1), run-length coded
  // and sent in a third code.
  std::size_t literals_sent = 286, distances_sent = 30;
  while (literals_sent > 257 && literal_lengths[literals_sent - 1] == 0) --literals_sent;
  while (distances_sent > 1 && distance_lengths[distances_sent - 1] == 0) --distances_sent;
  std::vector<std::uint8_t> both(
      literal_lengths.begin(),
      literal_lengths.begin() + static_cast<std::ptrdiff_t>(literals_sent));
  both.insert(both.end(), distance_lengths.begin(),
              distance_lengths.begin() + static_cast<std::ptrdiff_t>(distances_sent));
  const std::vector<CodeLengthSymbol> runs = run_length_code(both);
  std::vector<std::uint32_t> run_counts(19, 0);
  for (const CodeLengthSymbol& run : runs) ++run_counts[run.symbol];
  const std::vector<std::uint8_t> run_lengths = limited_code_lengths(run_counts, 7);
  const std::vector<std::uint16_t> run_codes = canonical_codes(run_lengths);
  std::size_t run_lengths_sent = 19;
  while (run_lengths_sent > 4 && run_lengths[kCodeLengthOrder[run_lengths_sent - 1]] == 0) {
    --run_lengths_sent;
  }

  put(last ? 1 : 0, 1);
  put(2, 2);  // dynamic Huffman codes
  put(static_cast<std::uint32_t>(literals_sent - 257), 5);
  put(static_cast<std::uint32_t>(distances_sent - 1), 5);
  put(static_cast<std::uint32_t>(run_lengths_sent - 4), 4);
  for (std::size_t i = 0; i < run_lengths_sent; ++i) put(run_lengths[kCodeLengthOrder[i]], 3);
  constexpr std::array<int, 3> kRunExtra = {2, 3, 7};  // bits after symbols 16, 17, 18
  for (const CodeLengthSymbol& run : runs) {
    put(run_codes[run.symbol], run_lengths[run.symbol]);
    if (run.symbol >= 16) put(run.extra, kRunExtra[static_cast<std::size_t>(run.symbol - 16)]);
  }

  for (std::size_t t = 0; t < token_count_; ++t) {
    const std::uint32_t token = tokens_[t];
    if ((token & kMatchFlag) == 0) {
      put(literal_codes[token], literal_lengths[token]);
      continue;
    }
    const std::uint32_t length = (token >> 16) & 0x1ff;
    const std::uint32_t distance = (token & 0xffff) + 1;
    const std::size_t symbol = kLengthSymbol[length];
    put(literal_codes[257 + symbol] |
            ((length - kLengthBase[symbol]) << literal_lengths[257 + symbol]),
        literal_lengths[257 + symbol] + kLengthExtra[symbol]);
    const std::size_t code = (token >> 25) & 0x1f;
    put(distance_codes[code] | ((distance - kDistanceBase[code]) << distance_lengths[code]),
        distance_lengths[code] + kDistanceExtra[code]);
  }
  put(literal_codes[256], literal_lengths[256]);
  // Whole bytes out; fewer than eight bits stay for the next block.
  while (bit_count_ >= 8) {
    out_[size++] = static_cast<std::uint8_t>(bits_);
    bits_ >>= 8;
    bit_count_ -= 8;
  }
  out_size_ = size;

  token_count_ = 0;
  literal_counts_.fill(0);
  distance_counts_.fill(0);
}

std::vector<std::uint8_t> ScanlineDeflater::finish() {
  emit_block(true);
  out_.resize(out_size_);
  if (bit_count_ > 0) out_.push_back(static_cast<std::uint8_t>(bits_));
  bits_ = 0;
  bit_count_ = 0;
  const std::uint32_t adler = (adler_b_ << 16) | adler_a_;
  for (int shift = 24; shift >= 0; shift -= 8)
    out_.push_back(static_cast<std::uint8_t>(adler >> shift));
  return std::move(out_);
}

}  // namespace tumble::io
