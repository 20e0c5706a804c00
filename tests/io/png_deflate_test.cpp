#include "io/png_deflate.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <queue>
#include <random>
#include <vector>

namespace tumble::io {
namespace {

// Pixels like a rendered frame's: a flat background, a horizontal gradient, a vertical one, a
// rectangle, thin lines and a band of noise.
std::vector<std::uint8_t> frame_like(int width, int height, int channels) {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * channels);
  std::mt19937 random(7);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &pixels[(static_cast<std::size_t>(y) * width + x) * channels];
      int r = 120, g = 130, b = 140;
      if (y < height / 4) r = g = b = 40 + 150 * y / height;            // sky
      if (y >= height / 4 && y < height / 2) r = 60 + 100 * x / width;  // gradient across
      if (x % 37 == 0 || y % 29 == 0) r = g = b = 90;                   // grid lines
      if (x > width / 3 && x < width / 2 && y > height / 2) r = 230, g = 90, b = 40;  // a box
      if (y > 7 * height / 8) r = static_cast<int>(random() & 255);                   // noise
      p[0] = static_cast<std::uint8_t>(r);
      p[1] = static_cast<std::uint8_t>(g);
      p[2] = static_cast<std::uint8_t>(b);
      if (channels == 4) p[3] = static_cast<std::uint8_t>(x < width / 2 ? 255 : 128 + y % 7);
    }
  }
  return pixels;
}

std::vector<std::uint8_t> noise(int width, int height, int channels, unsigned seed) {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * channels);
  std::mt19937 random(seed);
  for (std::uint8_t& byte : pixels) byte = static_cast<std::uint8_t>(random());
  return pixels;
}

// Compresses the rows, inflates the stream with zlib (which checks the Adler-32 too) and undoes
// the Sub filter: the pixels must come back exactly. Returns the stream's size.
std::size_t expect_round_trip(const std::vector<std::uint8_t>& pixels, int width, int height,
                              int channels) {
  const std::size_t row_bytes = static_cast<std::size_t>(width) * channels;
  ScanlineDeflater deflater(row_bytes, channels);
  for (int y = 0; y < height; ++y) deflater.add_row(pixels.data() + y * row_bytes);
  const std::vector<std::uint8_t> stream = deflater.finish();

  std::vector<std::uint8_t> raw((row_bytes + 1) * height + 1);  // one byte more: none is left
  uLongf size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &size, stream.data(), stream.size()), Z_OK);
  EXPECT_EQ(size, (row_bytes + 1) * height);
  if (size != (row_bytes + 1) * height) return stream.size();
  std::size_t wrong = 0;
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* filtered = raw.data() + y * (row_bytes + 1);
    EXPECT_EQ(filtered[0], 1) << "row " << y << " is not Sub-filtered";
    const std::uint8_t* row = pixels.data() + y * row_bytes;
    for (std::size_t i = 0; i < row_bytes; ++i) {
      const auto left = i >= static_cast<std::size_t>(channels) ? row[i - channels] : 0;
      if (static_cast<std::uint8_t>(filtered[1 + i] + left) != row[i]) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0u);
  return stream.size();
}

TEST(ScanlineDeflater, FrameLikePicturesComeBackExactlyAndSmall) {
  for (int channels : {3, 4}) {
    SCOPED_TRACE(channels);
    const std::vector<std::uint8_t> pixels = frame_like(640, 360, channels);
    const std::size_t size = expect_round_trip(pixels, 640, 360, channels);
    // Flat and steady parts are matches: well under a tenth of the raw bytes.
    EXPECT_LT(size, pixels.size() / 10);
  }
}

TEST(ScanlineDeflater, NoiseComesBackInSeveralBlocksAndBarelyGrows) {
  // 300 x 300 RGB of noise: 270 000 literals, several blocks of their own Huffman codes.
  const std::vector<std::uint8_t> pixels = noise(300, 300, 3, 11);
  const std::size_t size = expect_round_trip(pixels, 300, 300, 3);
  // Incompressible: at most a few per cent over the raw bytes (8 bits a literal and headers).
  EXPECT_LT(size, pixels.size() + pixels.size() / 50);
}

TEST(ScanlineDeflater, TinyAndOddSizes) {
  for (const auto& [width, height] : {std::pair{1, 1}, {1, 5}, {5, 1}, {2, 3}, {17, 9}}) {
    for (int channels : {3, 4}) {
      SCOPED_TRACE(testing::Message() << width << "x" << height << "x" << channels);
      expect_round_trip(frame_like(width, height, channels), width, height, channels);
      expect_round_trip(noise(width, height, channels, 3), width, height, channels);
    }
  }
}

TEST(ScanlineDeflater, RowsWiderThanTheWindowMatchOnlyWithinTheRow) {
  // 11 000 RGB pixels a row: one row back is 33 001 bytes, beyond deflate's 32 768.
  const std::vector<std::uint8_t> pixels = frame_like(11000, 3, 3);
  expect_round_trip(pixels, 11000, 3, 3);
}

TEST(ScanlineDeflater, UniformPictureIsAlmostNothing) {
  const std::vector<std::uint8_t> grey(1280 * 720 * 3, 77);
  const std::size_t size = expect_round_trip(grey, 1280, 720, 3);
  // Each row: its filter byte, the first pixel, then matches of 258 bytes, about 2 bytes each.
  EXPECT_LT(size, 720u * 40u);
}

TEST(Adler32, MatchesZlibAcrossBlockAndRunBoundaries) {
  const std::vector<std::uint8_t> data = noise(1, 70000, 1, 5);
  for (std::size_t size : {0u, 1u, 31u, 32u, 33u, 5551u, 5552u, 5553u, 11104u, 70000u}) {
    std::uint32_t a = 1, b = 0;
    adler32_update(data.data(), size, a, b);
    const uLong expected = adler32(1L, data.data(), static_cast<uInt>(size));
    EXPECT_EQ((b << 16) | a, expected) << size << " bytes";
  }
  // Continued in uneven pieces, and over bytes of 255 (the largest sums).
  std::vector<std::uint8_t> high(20000, 255);
  std::uint32_t a = 1, b = 0;
  std::size_t at = 0;
  for (std::size_t piece : {7u, 5552u, 33u, 9000u, 5408u}) {
    adler32_update(high.data() + at, piece, a, b);
    at += piece;
  }
  ASSERT_EQ(at, high.size());
  EXPECT_EQ((b << 16) | a, adler32(1L, high.data(), static_cast<uInt>(high.size())));
}

// Kraft's sum of the lengths in units of 2^-limit: a complete code sums to exactly 2^limit.
std::uint64_t kraft(const std::vector<std::uint8_t>& lengths, int limit) {
  std::uint64_t sum = 0;
  for (std::uint8_t length : lengths) {
    if (length > 0) sum += std::uint64_t{1} << (limit - length);
  }
  return sum;
}

// The cost (sum of count x length) of an unlimited Huffman code, by the textbook merge.
std::uint64_t huffman_cost(const std::vector<std::uint32_t>& counts) {
  std::priority_queue<std::uint64_t, std::vector<std::uint64_t>, std::greater<>> heap;
  for (std::uint32_t count : counts) {
    if (count > 0) heap.push(count);
  }
  std::uint64_t cost = 0;
  while (heap.size() > 1) {
    const std::uint64_t a = heap.top();
    heap.pop();
    const std::uint64_t b = heap.top();
    heap.pop();
    cost += a + b;
    heap.push(a + b);
  }
  return cost;
}

// The least cost of a complete code of lengths at most `limit`, by dynamic programming over the
// counts in decreasing order (an optimal code gives commoner symbols no longer codes): at depth
// d with f free nodes and the first i symbols placed, place k more as leaves there and split the
// other f - k into twice as many one level deeper. Independent of package-merge.
std::uint64_t optimal_limited_cost(std::vector<std::uint32_t> counts, int limit) {
  std::erase(counts, 0u);
  std::sort(counts.begin(), counts.end(), std::greater<>());
  const std::size_t n = counts.size();
  constexpr std::uint64_t kNone = ~std::uint64_t{0};
  // best[i][f]: the least cost of placing symbols i.. given f free nodes at the current depth.
  std::vector<std::vector<std::uint64_t>> best(n + 1, std::vector<std::uint64_t>(n + 1, kNone));
  best[n][0] = 0;  // at the deepest level, every node must be used
  for (int depth = limit; depth >= 1; --depth) {
    std::vector<std::vector<std::uint64_t>> here(n + 1, std::vector<std::uint64_t>(n + 1, kNone));
    for (std::size_t i = 0; i <= n; ++i) {
      for (std::size_t f = 0; f + i <= n; ++f) {
        std::uint64_t placed = 0;
        for (std::size_t k = 0; k <= f; ++k) {
          if (k > 0) placed += std::uint64_t{counts[i + k - 1]} * depth;
          const std::size_t deeper = 2 * (f - k);
          if (i + k > n || i + k + deeper > n) continue;
          const std::uint64_t rest = best[i + k][deeper];
          if (rest != kNone) here[i][f] = std::min(here[i][f], placed + rest);
        }
      }
    }
    best = std::move(here);
  }
  return best[0][2];  // the root's two children, at depth 1
}

std::uint64_t cost(const std::vector<std::uint32_t>& counts,
                   const std::vector<std::uint8_t>& lengths) {
  std::uint64_t sum = 0;
  for (std::size_t s = 0; s < counts.size(); ++s) sum += std::uint64_t{counts[s]} * lengths[s];
  return sum;
}

TEST(LimitedCodeLengths, OptimalCompleteCodesOfRandomCounts) {
  std::mt19937 random(3);
  int bound = 0;
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<std::uint32_t> counts(286, 0);
    for (std::uint32_t& c : counts) c = random() % 3 == 0 ? 0 : random() % 1000;
    const std::vector<std::uint8_t> lengths = limited_code_lengths(counts, 15);
    EXPECT_EQ(kraft(lengths, 15), std::uint64_t{1} << 15);
    EXPECT_EQ(cost(counts, lengths), optimal_limited_cost(counts, 15));
    // Where the limit does not bind, that is Huffman's cost.
    if (*std::max_element(lengths.begin(), lengths.end()) < 15) {
      EXPECT_EQ(cost(counts, lengths), huffman_cost(counts));
    } else {
      ++bound;
    }
    for (std::size_t s = 0; s < counts.size(); ++s) EXPECT_EQ(lengths[s] > 0, counts[s] > 0);
  }
  EXPECT_GT(bound, 0);   // counts down to 1 beside hundreds: some codes hit the limit
  EXPECT_LT(bound, 10);  // and some do not
}

TEST(LimitedCodeLengths, FibonacciCountsAreHeldToTheLimitAndStayComplete) {
  // Counts 1, 1, 2, 3, 5, ... make an unlimited Huffman code as deep as there are symbols.
  std::vector<std::uint32_t> counts(19);
  counts[0] = counts[1] = 1;
  for (std::size_t i = 2; i < counts.size(); ++i) counts[i] = counts[i - 1] + counts[i - 2];
  const std::vector<std::uint8_t> lengths = limited_code_lengths(counts, 7);
  EXPECT_EQ(kraft(lengths, 7), std::uint64_t{1} << 7);
  for (std::uint8_t length : lengths) {
    EXPECT_GE(length, 1);
    EXPECT_LE(length, 7);
  }
  EXPECT_EQ(cost(counts, lengths), optimal_limited_cost(counts, 7));
  EXPECT_GT(cost(counts, lengths), huffman_cost(counts));  // the limit binds
  // The same with 30 symbols at the limit of 15 (a deflate code's).
  std::vector<std::uint32_t> many(30);
  many[0] = many[1] = 1;
  for (std::size_t i = 2; i < many.size(); ++i) many[i] = many[i - 1] + many[i - 2];
  const std::vector<std::uint8_t> limited = limited_code_lengths(many, 15);
  EXPECT_EQ(kraft(limited, 15), std::uint64_t{1} << 15);
  EXPECT_EQ(*std::max_element(limited.begin(), limited.end()), 15);
  EXPECT_EQ(cost(many, limited), optimal_limited_cost(many, 15));
}

TEST(LimitedCodeLengths, FewerThanTwoSymbolsGetTwoCodesOfOneBit) {
  std::vector<std::uint32_t> one(30, 0);
  one[7] = 12;
  const std::vector<std::uint8_t> lengths = limited_code_lengths(one, 15);
  EXPECT_EQ(lengths[7], 1);
  EXPECT_EQ(lengths[0], 1);  // the lowest-numbered uncounted symbol
  EXPECT_EQ(kraft(lengths, 15), std::uint64_t{1} << 15);
  const std::vector<std::uint8_t> none = limited_code_lengths(std::vector<std::uint32_t>(19, 0), 7);
  EXPECT_EQ(none[0], 1);
  EXPECT_EQ(none[1], 1);
  EXPECT_EQ(kraft(none, 7), std::uint64_t{1} << 7);
}

}  // namespace
}  // namespace tumble::io
