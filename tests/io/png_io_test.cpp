// PNG writing and reading: bit-exact round trips, every setting, conversions from the PNG types
// tumble never writes (written here with libpng directly), and errors that name the path.
#include "io/png_io.hpp"
#include "support/result_text.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace tumble::io {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Every byte a different-looking value (a 32-bit LCG), so no row or channel mix-up goes unseen.
Image noise(int width, int height, std::uint32_t seed) {
  Image image(width, height);
  for (std::uint8_t& byte : image.rgb) {
    seed = seed * 1664525u + 1013904223u;
    byte = static_cast<std::uint8_t>(seed >> 24);
  }
  return image;
}

// Neighbouring pixels differ by at most one level: what filters exist to compress.
Image smooth_gradient(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* pixel = image.row(y) + 3 * x;
      pixel[0] = static_cast<std::uint8_t>(x);
      pixel[1] = static_cast<std::uint8_t>(y);
      pixel[2] = static_cast<std::uint8_t>((x + y) / 2);
    }
  }
  return image;
}

// A PNG as stored: rows of packed samples (16-bit samples big-endian), for writing with libpng.
struct RawPng {
  int width = 0;
  int height = 0;
  int bit_depth = 8;
  int color_type = PNG_COLOR_TYPE_RGB;
  int interlace = PNG_INTERLACE_NONE;
  std::vector<std::uint8_t> rows;       // height rows of equal length
  std::vector<png_color> palette;       // PLTE, for PNG_COLOR_TYPE_PALETTE
  std::vector<png_byte> palette_alpha;  // tRNS: alpha of the first palette entries
};

// libpng's default error handler longjmps here; locals are trivial so nothing is skipped.
bool write_raw_guarded(png_structp png, png_infop info, std::FILE* file, const RawPng& raw,
                       png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, raw.width, raw.height, raw.bit_depth, raw.color_type, raw.interlace,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!raw.palette.empty()) {
    png_set_PLTE(png, info, raw.palette.data(), static_cast<int>(raw.palette.size()));
  }
  if (!raw.palette_alpha.empty()) {
    png_set_tRNS(png, info, raw.palette_alpha.data(), static_cast<int>(raw.palette_alpha.size()),
                 nullptr);
  }
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

bool write_raw_png(const fs::path& path, const RawPng& raw) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  std::vector<png_bytep> rows;
  const std::size_t row_bytes = raw.rows.size() / raw.height;
  for (int y = 0; y < raw.height; ++y) {
    rows.push_back(const_cast<png_bytep>(raw.rows.data()) + y * row_bytes);
  }
  const bool ok = write_raw_guarded(png, info, file, raw, rows.data());
  png_destroy_write_struct(&png, &info);
  return std::fclose(file) == 0 && ok;
}

// Signature and IHDR of a width x height RGB image, then the start of an IDAT chunk: enough for
// a reader to learn the size, nowhere near enough pixels.
bool write_header_only_guarded(png_structp png, png_infop info, std::FILE* file, png_uint_32 width,
                               png_uint_32 height) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_flush(png);
  return true;
}

bool write_header_only(const fs::path& path, png_uint_32 width, png_uint_32 height) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  bool ok = write_header_only_guarded(png, info, file, width, height);
  png_destroy_write_struct(&png, &info);
  const unsigned char idat_start[] = {0, 0, 0, 100, 'I', 'D', 'A', 'T'};
  ok = std::fwrite(idat_start, 1, sizeof idat_start, file) == sizeof idat_start && ok;
  return std::fclose(file) == 0 && ok;
}

class PngIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("tumble_png_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::size_t files_in_dir() const {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }

  // Reads `path`, failing the test on error.
  Image read_ok(const fs::path& path) {
    Image image;
    const std::string error = ::tumble::testing::take(read_png(path.string()), image);
    EXPECT_EQ(error, "");
    return image;
  }

  fs::path dir_;
};

TEST_F(PngIo, RoundTripIsBitExactForManySizes) {
  const int sizes[][2] = {{1, 1}, {1, 7}, {2, 3}, {3, 2}, {7, 5}, {33, 17}, {64, 64}, {257, 3}};
  std::uint32_t seed = 1;
  for (const auto& size : sizes) {
    const Image original = noise(size[0], size[1], seed++);
    const fs::path path = dir_ / "image.png";
    ASSERT_EQ(::tumble::testing::error_text(write_png(path.string(), original)), "");
    const Image read = read_ok(path);
    EXPECT_EQ(read.width, size[0]);
    EXPECT_EQ(read.height, size[1]);
    EXPECT_EQ(read.rgb, original.rgb) << size[0] << "x" << size[1];
  }
}

TEST_F(PngIo, EveryCompressionLevelAndFilterSettingRoundTrips) {
  const Image original = noise(31, 9, 42);
  for (int level = 0; level <= 9; ++level) {
    for (const bool filter : {false, true}) {
      const fs::path path = dir_ / "image.png";
      ASSERT_EQ(
          ::tumble::testing::error_text(write_png(
              path.string(), original,
              PngSettings{.own_encoder = false, .compression_level = level, .filter = filter})),
          "");
      EXPECT_EQ(read_ok(path).rgb, original.rgb) << "level " << level << " filter " << filter;
    }
  }
}

TEST_F(PngIo, WritesEightBitRgbNonInterlacedWithIdenticalBytesEachTime) {
  const Image image = smooth_gradient(40, 30);
  ASSERT_EQ(::tumble::testing::error_text(write_png((dir_ / "a.png").string(), image)), "");
  ASSERT_EQ(::tumble::testing::error_text(write_png((dir_ / "b.png").string(), image)), "");
  const std::string bytes = read_bytes(dir_ / "a.png");
  EXPECT_EQ(bytes, read_bytes(dir_ / "b.png"));
  EXPECT_EQ(bytes.find("tIME"), std::string::npos);
  // Signature (8) + IHDR length (4) + "IHDR" (4) + width (4) + height (4), then the fields.
  ASSERT_GT(bytes.size(), 29u);
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(static_cast<unsigned char>(bytes[19]), 40u);  // width, big-endian low byte
  EXPECT_EQ(static_cast<unsigned char>(bytes[23]), 30u);  // height
  EXPECT_EQ(bytes[24], 8);                                // bits per sample
  EXPECT_EQ(bytes[25], PNG_COLOR_TYPE_RGB);
  EXPECT_EQ(bytes[28], PNG_INTERLACE_NONE);
}

TEST_F(PngIo, DefaultIsTheOwnEncoderWhichFiltersLikeLevelNineAndUnfilteredZlibDoesNot) {
  const Image gradient = smooth_gradient(256, 256);
  const auto write = [&](const char* name, const PngSettings& settings) {
    EXPECT_EQ(::tumble::testing::error_text(write_png((dir_ / name).string(), gradient, settings)),
              "");
    EXPECT_EQ(read_ok(dir_ / name).rgb, gradient.rgb) << name;
    return fs::file_size(dir_ / name);
  };
  write("default.png", PngSettings{});
  const auto own_size = write("own.png", *png_settings_named("fast"));
  const auto level_one_size =
      write("level1.png", PngSettings{.own_encoder = false, .compression_level = 1});
  const auto small_size = write("small.png", *png_settings_named("small"));
  EXPECT_EQ(read_bytes(dir_ / "default.png"), read_bytes(dir_ / "own.png"));
  // On a gradient a row filter predicts almost every byte: unfiltered zlib is ten times larger
  // than level 9 with filters. The own encoder's Sub filter leaves a pattern two pixels long
  // here ((x + y) / 2 steps every other pixel), which its matches (one pixel or one row back)
  // do not find: smaller than unfiltered zlib, far larger than level 9.
  EXPECT_LT(small_size * 10, level_one_size) << small_size << " vs " << level_one_size;
  EXPECT_LT(own_size, level_one_size) << own_size << " vs " << level_one_size;
}

TEST_F(PngIo, OwnEncoderWritesRgbaWithStraightAlpha) {
  Image image = smooth_gradient(33, 17);
  image.alpha.resize(33 * 17);
  for (std::size_t i = 0; i < image.alpha.size(); ++i) {
    image.alpha[i] = static_cast<std::uint8_t>(i % 5 == 0 ? 255 : 37 * i);
  }
  const fs::path path = dir_ / "alpha.png";
  ASSERT_EQ(::tumble::testing::error_text(write_png(path.string(), image)), "");
  const std::string bytes = read_bytes(path);
  ASSERT_GT(bytes.size(), 29u);
  EXPECT_EQ(bytes[25], PNG_COLOR_TYPE_RGBA);
  // read_png composites over black: c a / 255, rounded.
  const Image read = read_ok(path);
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < image.alpha.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const unsigned expected = (image.rgb[3 * i + c] * image.alpha[i] + 127u) / 255u;
      if (read.rgb[3 * i + c] != expected) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0u);
}

TEST_F(PngIo, LevelZeroStoresEveryByteAndLevelOneCompresses) {
  Image flat(256, 64);  // one colour, like a frame's background
  for (std::size_t i = 0; i < flat.rgb.size(); ++i)
    flat.rgb[i] = static_cast<std::uint8_t>(40 * (i % 3 + 1));
  const auto raw_bytes = flat.rgb.size() + flat.height;  // plus one filter byte per row
  ASSERT_EQ(::tumble::testing::error_text(
                write_png((dir_ / "stored.png").string(), flat,
                          PngSettings{.own_encoder = false, .compression_level = 0})),
            "");
  ASSERT_EQ(::tumble::testing::error_text(
                write_png((dir_ / "fast.png").string(), flat,
                          PngSettings{.own_encoder = false, .compression_level = 1})),
            "");
  EXPECT_GT(fs::file_size(dir_ / "stored.png"), raw_bytes);
  EXPECT_LT(fs::file_size(dir_ / "fast.png") * 2, raw_bytes);
}

TEST_F(PngIo, AMissingFolderIsAnErrorNamingThePathAndLeavesNothing) {
  const fs::path path = dir_ / "no" / "such" / "image.png";
  const std::string error = ::tumble::testing::error_text(write_png(path.string(), noise(4, 4, 1)));
  EXPECT_NE(error.find(path.string()), std::string::npos) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(PngIo, AFolderAtThePathIsAnErrorAndNothingIsLeftBehind) {
  const fs::path path = dir_ / "taken";  // a non-empty folder: nothing can be written over it
  fs::create_directories(path / "inside");
  const std::string error = ::tumble::testing::error_text(write_png(path.string(), noise(4, 4, 1)));
  EXPECT_EQ(error, path.string() + ": cannot create: Is a directory");
  EXPECT_EQ(files_in_dir(), 1u);  // just the folder
  EXPECT_TRUE(fs::is_directory(path / "inside"));
}

TEST_F(PngIo, InvalidSettingsOrImagesAreRefusedBeforeAnythingIsWritten) {
  const fs::path path = dir_ / "image.png";
  std::string error = ::tumble::testing::error_text(write_png(
      path.string(), noise(4, 4, 1), PngSettings{.own_encoder = false, .compression_level = 10}));
  EXPECT_NE(error.find(path.string() + ": PNG compression level must be 0 to 9, got 10"),
            std::string::npos)
      << error;
  EXPECT_NE(::tumble::testing::error_text(
                write_png(path.string(), noise(4, 4, 1),
                          PngSettings{.own_encoder = false, .compression_level = -1})),
            "");

  Image short_of_bytes = noise(4, 4, 1);
  short_of_bytes.rgb.pop_back();
  error = ::tumble::testing::error_text(write_png(path.string(), short_of_bytes));
  EXPECT_NE(error.find("cannot write a 4x4 image holding 47 bytes"), std::string::npos) << error;
  EXPECT_NE(::tumble::testing::error_text(write_png(path.string(), Image())), "");
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(PngIo, AMissingFileIsAnErrorNamingThePath) {
  const fs::path path = dir_ / "absent.png";
  Image image;
  const std::string error = ::tumble::testing::take(read_png(path.string()), image);
  EXPECT_EQ(error, path.string() + ": cannot open: No such file or directory");
}

TEST_F(PngIo, AFileThatIsNotAPngIsAnErrorNamingThePath) {
  const fs::path path = dir_ / "scene.toml";
  write_bytes(path, "duration = 1.0\n[physics]\ndt = 0.01\n");
  Image image(2, 2);
  const std::string error = ::tumble::testing::take(read_png(path.string()), image);
  EXPECT_EQ(error, path.string() + ": not a PNG file (it does not start with the PNG signature)");
  EXPECT_EQ(image.width, 2);  // untouched
}

TEST_F(PngIo, EveryTruncationIsAnErrorNamingThePathAndLeavesTheOutputUntouched) {
  const fs::path whole = dir_ / "whole.png";
  ASSERT_EQ(::tumble::testing::error_text(write_png(
                whole.string(), noise(9, 7, 3),
                PngSettings{.own_encoder = false, .compression_level = 9, .filter = true})),
            "");
  const std::string bytes = read_bytes(whole);
  const Image untouched = noise(2, 2, 5);
  const fs::path cut = dir_ / "cut.png";
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    write_bytes(cut, bytes.substr(0, length));
    Image image = untouched;
    const std::string error = ::tumble::testing::take(read_png(cut.string()), image);
    ASSERT_EQ(error.rfind(cut.string() + ": ", 0), 0u) << "length " << length << ": " << error;
    EXPECT_EQ(image.rgb, untouched.rgb);
    if (length >= 8) {
      EXPECT_NE(error.find("cannot decode PNG"), std::string::npos) << error;
    }
  }
  // Cut inside the pixel data, the message says why.
  write_bytes(cut, bytes.substr(0, bytes.size() / 2));
  Image image;
  EXPECT_EQ(::tumble::testing::take(read_png(cut.string()), image),
            cut.string() + ": cannot decode PNG: file ends early (truncated)");
}

TEST_F(PngIo, CorruptPixelDataIsAnErrorNamingThePath) {
  const fs::path path = dir_ / "corrupt.png";
  ASSERT_EQ(::tumble::testing::error_text(write_png(path.string(), noise(16, 16, 7))), "");
  const std::string bytes = read_bytes(path);
  const std::size_t idat = bytes.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  std::size_t length = 0;  // the 4 big-endian bytes before the chunk type
  for (std::size_t i = idat - 4; i < idat; ++i) length = length * 256 + std::uint8_t(bytes[i]);
  Image image;

  std::string damaged = bytes;
  damaged[idat + 4 + length] ^= 0x55;  // the chunk's CRC
  write_bytes(path, damaged);
  EXPECT_EQ(::tumble::testing::take(read_png(path.string()), image),
            path.string() + ": cannot decode PNG: IDAT: CRC error");

  // With the data damaged instead, zlib or libpng fails before the chunk's CRC is reached (which
  // check fails first depends on the stream: zlib's on the data, or libpng's on a row's filter
  // type decoded wrong).
  damaged = bytes;
  damaged[idat + 4 + length / 2] ^= 0x55;
  write_bytes(path, damaged);
  const std::string error = ::tumble::testing::take(read_png(path.string()), image);
  EXPECT_EQ(error.rfind(path.string() + ": cannot decode PNG: ", 0), 0u) << error;
  EXPECT_EQ(image.width, 0);
}

TEST_F(PngIo, ImagesOverOneHundredMegapixelsAreRefused) {
  const fs::path path = dir_ / "huge.png";
  ASSERT_TRUE(write_header_only(path, 20000, 5001));
  Image image;
  EXPECT_EQ(::tumble::testing::take(read_png(path.string()), image),
            path.string() + ": image is 20000x5001, more than the 100 megapixels tumble will read");
  // A header of a sane size is accepted, and this read fails later, on the missing pixels.
  ASSERT_TRUE(write_header_only(path, 200, 100));
  EXPECT_EQ(::tumble::testing::take(read_png(path.string()), image),
            path.string() + ": cannot decode PNG: file ends early (truncated)");
}

TEST_F(PngIo, FourBitGreyExpandsToRgb) {
  RawPng raw;
  raw.width = 4;
  raw.height = 1;
  raw.bit_depth = 4;
  raw.color_type = PNG_COLOR_TYPE_GRAY;
  raw.rows = {0x05, 0xAF};  // grey levels 0, 5, 10, 15 of 15
  const fs::path path = dir_ / "grey.png";
  ASSERT_TRUE(write_raw_png(path, raw));
  const Image image = read_ok(path);
  ASSERT_EQ(image.width, 4);
  ASSERT_EQ(image.height, 1);
  EXPECT_EQ(image.rgb, (std::vector<std::uint8_t>{0, 0, 0, 85, 85, 85, 170, 170, 170, 255, 255,
                                                  255}));  // level * 255 / 15
}

TEST_F(PngIo, GreyWithAlphaIsCompositedOverBlack) {
  RawPng raw;
  raw.width = 3;
  raw.height = 1;
  raw.color_type = PNG_COLOR_TYPE_GRAY_ALPHA;
  raw.rows = {100, 255, 100, 0, 255, 51};  // (grey, alpha) pairs
  const fs::path path = dir_ / "grey_alpha.png";
  ASSERT_TRUE(write_raw_png(path, raw));
  EXPECT_EQ(read_ok(path).rgb, (std::vector<std::uint8_t>{100, 100, 100, 0, 0, 0, 51, 51, 51}));
}

TEST_F(PngIo, TwoBitPaletteWithTransparencyConvertsToRgb) {
  RawPng raw;
  raw.width = 4;
  raw.height = 2;
  raw.bit_depth = 2;
  raw.color_type = PNG_COLOR_TYPE_PALETTE;
  raw.palette = {{255, 0, 0}, {0, 128, 255}, {10, 20, 30}, {200, 100, 50}};
  raw.palette_alpha = {255, 0, 51};  // entry 3 has no tRNS entry, so it is opaque
  raw.rows = {0b00'01'10'11, 0b11'10'01'00};
  const fs::path path = dir_ / "palette.png";
  ASSERT_TRUE(write_raw_png(path, raw));
  const Image image = read_ok(path);
  ASSERT_EQ(image.width, 4);
  ASSERT_EQ(image.height, 2);
  const std::vector<std::uint8_t> row0 = {255, 0, 0, 0, 0, 0, 2, 4, 6, 200, 100, 50};
  const std::vector<std::uint8_t> row1 = {200, 100, 50, 2, 4, 6, 0, 0, 0, 255, 0, 0};
  EXPECT_EQ(std::vector<std::uint8_t>(image.row(0), image.row(0) + 12), row0);
  EXPECT_EQ(std::vector<std::uint8_t>(image.row(1), image.row(1) + 12), row1);
}

TEST_F(PngIo, SixteenBitRgbaIsRoundedToEightBitsAndCompositedOverBlack) {
  RawPng raw;
  raw.width = 4;
  raw.height = 1;
  raw.bit_depth = 16;
  raw.color_type = PNG_COLOR_TYPE_RGB_ALPHA;
  const std::uint16_t samples[] = {
      257 * 200, 257 * 100, 257 * 50, 65535,     // opaque: 200, 100, 50
      65535,     65535,     65535,    0,         // transparent white: black
      257 * 200, 257 * 100, 257 * 50, 257 * 51,  // 20% alpha: 40, 20, 10
      0x12FF,    0,         65535,    65535,     // 0x12FF = 18.92 * 257: rounds to 19, not 0x12
  };
  for (const std::uint16_t sample : samples) {
    raw.rows.push_back(static_cast<std::uint8_t>(sample >> 8));
    raw.rows.push_back(static_cast<std::uint8_t>(sample & 0xFF));
  }
  const fs::path path = dir_ / "rgba16.png";
  ASSERT_TRUE(write_raw_png(path, raw));
  EXPECT_EQ(read_ok(path).rgb,
            (std::vector<std::uint8_t>{200, 100, 50, 0, 0, 0, 40, 20, 10, 19, 0, 255}));
}

TEST_F(PngIo, InterlacedImagesReadLikeTheirPixels) {
  const Image original = noise(13, 11, 9);
  RawPng raw;
  raw.width = original.width;
  raw.height = original.height;
  raw.interlace = PNG_INTERLACE_ADAM7;
  raw.rows = original.rgb;
  const fs::path path = dir_ / "interlaced.png";
  ASSERT_TRUE(write_raw_png(path, raw));
  ASSERT_EQ(read_bytes(path)[28], PNG_INTERLACE_ADAM7);
  EXPECT_EQ(read_ok(path).rgb, original.rgb);
}

// The fuzzer's PNG seeds (tests/fuzz/corpus/png/) are valid files of the kinds tumble never
// writes (1-bit grey, 2-bit palette with transparency, 16-bit RGBA, interlaced grey + alpha): each
// must decode, from a file and from a memory stream, to the size its header gives.
TEST(PngFuzzSeeds, EachDecodesToTheSizeInItsHeader) {
  const fs::path seeds = fs::path(TUMBLE_SOURCE_DIR) / "tests/fuzz/corpus/png";
  int count = 0;
  for (const auto& entry : fs::directory_iterator(seeds)) {
    const std::string bytes = read_bytes(entry.path());
    ASSERT_GE(bytes.size(), 24u);
    const auto be32 = [&](std::size_t at) {
      return static_cast<int>(static_cast<std::uint8_t>(bytes[at]) << 24 |
                              static_cast<std::uint8_t>(bytes[at + 1]) << 16 |
                              static_cast<std::uint8_t>(bytes[at + 2]) << 8 |
                              static_cast<std::uint8_t>(bytes[at + 3]));
    };
    Image from_file;
    ASSERT_EQ(::tumble::testing::take(read_png(entry.path().string()), from_file), "")
        << entry.path();
    EXPECT_EQ(from_file.width, be32(16)) << entry.path();
    EXPECT_EQ(from_file.height, be32(20)) << entry.path();
    std::FILE* memory = fmemopen(const_cast<char*>(bytes.data()), bytes.size(), "rb");
    ASSERT_NE(memory, nullptr);
    Image from_memory;
    EXPECT_EQ(::tumble::testing::take(read_png(memory, "seed"), from_memory), "");
    std::fclose(memory);
    EXPECT_EQ(from_memory.rgb, from_file.rgb) << entry.path();
    ++count;
  }
  EXPECT_EQ(count, 5);
}

}  // namespace
}  // namespace tumble::io
