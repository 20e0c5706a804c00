// libFuzzer target: any bytes as the PNG file `tumble diff` reads. The reader must return an
// image or an error naming the file; it must never crash, leak or read out of bounds.
//
// libpng rejects a chunk whose CRC is wrong, and nearly every mutation breaks one, so the input's
// chunk CRCs are recomputed first: that lets mutations reach the header checks, the
// decompression and the pixel conversions, which is where tumble's own code is.
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/png_io.hpp"

namespace {

std::uint32_t read_be32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
}

// Walks the chunks after the 8-byte signature and writes each one's correct CRC.
void fix_chunk_crcs(std::vector<std::uint8_t>& png) {
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const std::uint32_t length = read_be32(&png[at]);
    if (length > png.size() - at - 12) return;
    const std::uint8_t* type_and_data = &png[at + 4];
    const std::uint32_t crc =
        static_cast<std::uint32_t>(crc32(0L, type_and_data, static_cast<uInt>(length) + 4));
    std::uint8_t* out = &png[at + 8 + length];
    out[0] = static_cast<std::uint8_t>(crc >> 24);
    out[1] = static_cast<std::uint8_t>(crc >> 16);
    out[2] = static_cast<std::uint8_t>(crc >> 8);
    out[3] = static_cast<std::uint8_t>(crc);
    at += 12 + length;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;  // fmemopen wants at least one byte
  std::vector<std::uint8_t> png(data, data + size);
  fix_chunk_crcs(png);
  std::FILE* file = fmemopen(png.data(), png.size(), "rb");
  if (!file) return 0;
  const tumble::Result<tumble::io::Image> image = tumble::io::read_png(file, "fuzz.png");
  std::fclose(file);
  if (!image && image.error().rfind("fuzz.png: ", 0) != 0) std::abort();
  if (image && image->rgb.size() != static_cast<std::size_t>(image->width) * image->height * 3) {
    std::abort();  // a decoded image holds exactly its pixels
  }
  return 0;
}
