#include "io/png_io.hpp"

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/png_deflate.hpp"

// libpng reports errors by calling an error function that must not return; it longjmps back to a
// setjmp. A longjmp that skips a frame holding objects with non-trivial destructors is undefined
// behaviour in C++, so every libpng call that can fail happens inside one of the small
// *_guarded functions below, whose locals are all trivial and which set the jump target
// themselves. Everything that owns memory (libpng's structs, buffers, the file) lives in the
// caller, which the jump never crosses.

namespace tumble::io {
namespace {

constexpr std::size_t kSignatureBytes = 8;
// 100 megapixels is ~12x an 8K frame: larger headers are corrupt or hostile, and decoding them
// would need gigabytes.
constexpr std::uint64_t kMaxReadPixels = 100'000'000;

// Where the error function leaves libpng's message before it jumps. Plain data.
struct PngFailure {
  char message[256];
};

[[noreturn]] void record_error_and_jump(png_structp png, png_const_charp message) {
  auto* failure = static_cast<PngFailure*>(png_get_error_ptr(png));
  std::snprintf(failure->message, sizeof failure->message, "%s", message);
  png_longjmp(png, 1);
}

// Warnings (a damaged ancillary chunk, which libpng then skips) don't stop a read, and libpng's
// default would print them to stderr.
void ignore_warning(png_structp, png_const_charp) {}

void write_to_file(png_structp png, png_bytep data, std::size_t length) {
  auto* file = static_cast<std::FILE*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, length, file) == length) return;
  char message[128];
  std::snprintf(message, sizeof message, "write failed: %s", std::strerror(errno));
  png_error(png, message);
}

// AtomicFile::commit flushes once at the end.
void flush_nothing(png_structp) {}

void read_from_file(png_structp png, png_bytep data, std::size_t length) {
  auto* file = static_cast<std::FILE*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, file) == length) return;
  if (!std::ferror(file)) png_error(png, "file ends early (truncated)");
  char message[128];
  std::snprintf(message, sizeof message, "read failed: %s", std::strerror(errno));
  png_error(png, message);
}

// Owns a png_struct, for reading or for writing, and its png_info.
class PngStructs {
 public:
  enum class Side { read, write };

  PngStructs(Side side, PngFailure* failure)
      : side_(side),
        png_(side == Side::write ? png_create_write_struct(PNG_LIBPNG_VER_STRING, failure,
                                                           record_error_and_jump, ignore_warning)
                                 : png_create_read_struct(PNG_LIBPNG_VER_STRING, failure,
                                                          record_error_and_jump, ignore_warning)) {
    if (png_) info_ = png_create_info_struct(png_);
  }
  ~PngStructs() {
    if (side_ == Side::write) {
      png_destroy_write_struct(&png_, &info_);
    } else {
      png_destroy_read_struct(&png_, &info_, nullptr);
    }
  }
  PngStructs(const PngStructs&) = delete;
  PngStructs& operator=(const PngStructs&) = delete;

  bool allocated() const { return info_ != nullptr; }
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  Side side_;
  png_structp png_;
  png_infop info_ = nullptr;
};

// Row y of `image` as RGBA: its RGB with its alpha as the fourth byte of each pixel.
void interleave_alpha(const Image& image, int y, png_byte* out) {
  const std::uint8_t* rgb = image.row(y);
  const std::uint8_t* alpha = image.alpha.data() + static_cast<std::size_t>(y) * image.width;
  for (int x = 0; x < image.width; ++x) {
    out[4 * x + 0] = rgb[3 * x + 0];
    out[4 * x + 1] = rgb[3 * x + 1];
    out[4 * x + 2] = rgb[3 * x + 2];
    out[4 * x + 3] = alpha[x];
  }
}

bool encode_guarded(png_structp png, png_infop info, std::FILE* file, const Image& image,
                    const PngSettings& settings) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, file, write_to_file, flush_nothing);
  const bool alpha = !image.alpha.empty();
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8,
               alpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, settings.compression_level);
  // PNG_ALL_FILTERS is libpng's own default for 8-bit RGB: per row, it keeps the filter whose
  // output bytes, read as signed, have the smallest sum of magnitudes.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, settings.filter ? PNG_ALL_FILTERS : PNG_FILTER_NONE);
  png_write_info(png, info);
  if (!alpha) {
    for (int y = 0; y < image.height; ++y) png_write_row(png, image.row(y));
  } else {
    std::vector<png_byte> rgba(static_cast<std::size_t>(image.width) * 4);
    for (int y = 0; y < image.height; ++y) {
      interleave_alpha(image, y, rgba.data());
      png_write_row(png, rgba.data());
    }
  }
  png_write_end(png, nullptr);
  return true;
}

// PNG's integers are big-endian (PNG specification 7.1).
std::array<std::uint8_t, 4> big_endian(std::uint32_t value) {
  return {static_cast<std::uint8_t>(value >> 24), static_cast<std::uint8_t>(value >> 16),
          static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
}

// A PNG chunk (PNG specification 5.3): length, type, data, and the CRC-32 of type and data.
bool write_chunk(std::FILE* file, const char (&type)[5], const std::uint8_t* data,
                 std::size_t size) {
  const auto* type_bytes = reinterpret_cast<const Bytef*>(type);
  uLong crc = crc32(0L, type_bytes, 4);
  if (size > 0) crc = crc32_z(crc, data, size);  // zlib answers 0 for no data
  const std::array<std::uint8_t, 4> length = big_endian(static_cast<std::uint32_t>(size));
  const std::array<std::uint8_t, 4> check = big_endian(static_cast<std::uint32_t>(crc));
  return std::fwrite(length.data(), 1, 4, file) == 4 && std::fwrite(type, 1, 4, file) == 4 &&
         (size == 0 || std::fwrite(data, 1, size, file) == size) &&
         std::fwrite(check.data(), 1, 4, file) == 4;
}

// The PNG through tumble's own deflate encoder (png_deflate.hpp): the same chunks as libpng
// writes (IHDR, IDAT, IEND), the image data in one IDAT.
bool encode_own(std::FILE* file, const Image& image) {
  const bool alpha = !image.alpha.empty();
  const int channels = alpha ? 4 : 3;
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * channels;
  ScanlineDeflater deflater(row_bytes, channels);
  std::vector<std::uint8_t> rgba(alpha ? row_bytes : 0);
  for (int y = 0; y < image.height; ++y) {
    if (!alpha) {
      deflater.add_row(image.row(y));
    } else {
      interleave_alpha(image, y, rgba.data());
      deflater.add_row(rgba.data());
    }
  }
  const std::vector<std::uint8_t> data = deflater.finish();
  std::array<std::uint8_t, 13> header{};
  const std::array<std::uint8_t, 4> width = big_endian(static_cast<std::uint32_t>(image.width));
  const std::array<std::uint8_t, 4> height = big_endian(static_cast<std::uint32_t>(image.height));
  std::copy(width.begin(), width.end(), header.begin());
  std::copy(height.begin(), height.end(), header.begin() + 4);
  header[8] = 8;                             // bits per sample
  header[9] = alpha ? 6 : 2;                 // colour type: RGBA or RGB
  header[10] = header[11] = header[12] = 0;  // deflate, adaptive filters, no interlace
  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (std::fwrite(kSignature, 1, 8, file) != 8 ||
      !write_chunk(file, "IHDR", header.data(), header.size())) {
    return false;
  }
  // A chunk's length has 31 bits: the data of an image of gigabytes goes in several.
  constexpr std::size_t kMaxChunk = std::size_t{1} << 30;
  for (std::size_t at = 0; at < data.size(); at += kMaxChunk) {
    if (!write_chunk(file, "IDAT", data.data() + at, std::min(kMaxChunk, data.size() - at))) {
      return false;
    }
  }
  return write_chunk(file, "IEND", nullptr, 0);
}

bool read_header_guarded(png_structp png, png_infop info, std::FILE* file, png_uint_32* width,
                         png_uint_32* height) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, file, read_from_file);
  png_set_sig_bytes(png, kSignatureBytes);
  png_read_info(png, info);
  *width = png_get_image_width(png, info);
  *height = png_get_image_height(png, info);
  return true;
}

// Asks libpng for 8 bits per sample, RGB or RGBA, whatever the file stores.
bool request_rgb8_guarded(png_structp png, png_infop info, int* channels, std::size_t* row_bytes) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_expand(png);    // palette -> RGB, grey below 8 bits -> 8 bits, tRNS -> alpha channel
  png_set_scale_16(png);  // 16 -> 8 bits rounded to nearest (png_set_strip_16 would truncate)
  png_set_gray_to_rgb(png);
  png_set_interlace_handling(png);  // png_read_image then assembles Adam7 passes
  png_read_update_info(png, info);
  *channels = png_get_channels(png, info);
  *row_bytes = png_get_rowbytes(png, info);
  return true;
}

bool read_pixels_guarded(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, nullptr);  // through IEND, so a file cut short after the pixels is an error
  return true;
}

// (c a + 127) / 255 is c a / 255 rounded to nearest; it is never exactly halfway since 255 is odd.
void composite_over_black(const std::vector<png_byte>& rgba, Image& out) {
  const std::size_t pixels = out.rgb.size() / 3;
  for (std::size_t i = 0; i < pixels; ++i) {
    const unsigned alpha = rgba[4 * i + 3];
    for (std::size_t c = 0; c < 3; ++c) {
      out.rgb[3 * i + c] = static_cast<std::uint8_t>((rgba[4 * i + c] * alpha + 127) / 255);
    }
  }
}

std::string size_text(std::int64_t width, std::int64_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

Result<void> write_png(const std::string& path, const Image& image, const PngSettings& settings) {
  if (settings.compression_level < 0 || settings.compression_level > 9) {
    return Error{path + ": PNG compression level must be 0 to 9, got " +
                 std::to_string(settings.compression_level)};
  }
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    return Error{path + ": cannot write a " + size_text(image.width, image.height) +
                 " image holding " + std::to_string(image.rgb.size()) + " bytes as PNG"};
  }
  if (!image.alpha.empty() &&
      image.alpha.size() != static_cast<std::size_t>(image.width) * image.height) {
    return Error{path + ": cannot write a " + size_text(image.width, image.height) +
                 " image with an alpha plane of " + std::to_string(image.alpha.size()) +
                 " bytes as PNG"};
  }
  // Unsynced: PNGs are mostly video frames, written by the hundred (see AtomicFile::Durability).
  Result<AtomicFile> file = AtomicFile::open(path, AtomicFile::Durability::unsynced);
  if (!file) return Error{file.error()};
  if (settings.own_encoder) {
    if (!encode_own(file->stream(), image)) {
      return Error{path + ": cannot write PNG: write failed: " + std::strerror(errno)};
    }
    return file->commit();
  }
  PngFailure failure{};
  PngStructs structs(PngStructs::Side::write, &failure);
  if (!structs.allocated())
    return Error{path + ": cannot write PNG: libpng could not allocate its state"};
  if (!encode_guarded(structs.png(), structs.info(), file->stream(), image, settings)) {
    return Error{path + ": cannot write PNG: " + failure.message};
  }
  return file->commit();
}

Result<Image> read_png(const std::string& path) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) return Error{path + ": cannot open: " + std::strerror(errno)};
  return read_png(file.get(), path);
}

Result<Image> read_png(std::FILE* file, const std::string& path) {
  png_byte signature[kSignatureBytes];
  if (std::fread(signature, 1, kSignatureBytes, file) != kSignatureBytes ||
      png_sig_cmp(signature, 0, kSignatureBytes) != 0) {
    if (std::ferror(file)) return Error{path + ": cannot read: " + std::strerror(errno)};
    return Error{path + ": not a PNG file (it does not start with the PNG signature)"};
  }

  PngFailure failure{};
  PngStructs structs(PngStructs::Side::read, &failure);
  if (!structs.allocated())
    return Error{path + ": cannot read PNG: libpng could not allocate its state"};
  const std::string cannot_decode = path + ": cannot decode PNG: ";
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  if (!read_header_guarded(structs.png(), structs.info(), file, &width, &height)) {
    return Error{cannot_decode + failure.message};
  }
  if (std::uint64_t{width} * height > kMaxReadPixels) {
    return Error{path + ": image is " + size_text(width, height) +
                 ", more than the 100 megapixels tumble will read"};
  }
  int channels = 0;
  std::size_t row_bytes = 0;
  if (!request_rgb8_guarded(structs.png(), structs.info(), &channels, &row_bytes)) {
    return Error{cannot_decode + failure.message};
  }
  if ((channels != 3 && channels != 4) || row_bytes != std::size_t{width} * channels) {
    return Error{cannot_decode + "unexpected pixel layout after conversion (" +
                 std::to_string(channels) + " channels)"};
  }

  try {
    // libpng's default limit of 1,000,000 per side keeps both within int.
    Image image(static_cast<int>(width), static_cast<int>(height));
    std::vector<png_byte> rgba(channels == 4 ? row_bytes * height : 0);
    png_byte* pixels = channels == 4 ? rgba.data() : image.rgb.data();
    std::vector<png_bytep> rows(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = pixels + y * row_bytes;
    if (!read_pixels_guarded(structs.png(), rows.data()))
      return Error{cannot_decode + failure.message};
    if (channels == 4) composite_over_black(rgba, image);
    return image;
  } catch (const std::bad_alloc&) {
    return Error{path + ": not enough memory to read a " + size_text(width, height) + " image"};
  }
}

std::optional<PngSettings> png_settings_named(std::string_view name) {
  if (name == "fast") return PngSettings{};
  if (name == "default") {
    return PngSettings{.own_encoder = false, .compression_level = 6, .filter = true};
  }
  if (name == "small") {
    return PngSettings{.own_encoder = false, .compression_level = 9, .filter = true};
  }
  return std::nullopt;
}

}  // namespace tumble::io
