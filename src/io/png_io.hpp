// PNG files to and from Image (libpng). Errors come back as a complete message naming the path and
// what failed; an empty string means success.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "io/image.hpp"

namespace tumble::io {

// Defaults favour speed, since a PNG is written for every video frame: tumble's own encoder
// (io/png_deflate.hpp; on the default scene's 720p frames about twice zlib level 1's speed, files
// about a tenth larger), and otherwise libpng with zlib. libpng's adaptive filtering (trying all
// five row filters on every row) is most of its cost at fast zlib levels, and zlib's level 6
// most of the rest: on a rendered 1280x720 frame, level 1 unfiltered takes 12 ms for 230 kB;
// libpng's defaults (level 6, adaptive) 55 ms for 175 kB. For files that are kept, use
// own_encoder = false, filter = true and level 9.
struct PngSettings {
  bool own_encoder = true;    // true: tumble's own encoder; the two below are then unused
  int compression_level = 1;  // zlib level, 0 (store) to 9 (smallest)
  bool filter = false;        // false: PNG_FILTER_NONE on every row; true: adaptive filtering
};

// The named settings users choose from: "fast" (the default above: the own encoder), "default"
// (libpng's own: zlib 6, adaptive filtering) and "small" (zlib 9, adaptive filtering). Nothing
// for other names.
std::optional<PngSettings> png_settings_named(std::string_view name);

// Writes `image` as an 8-bit RGB, non-interlaced PNG (RGBA, straight alpha, when the image has
// an alpha plane). The file appears whole or not at all
// (temporary name beside `path`, then rename; not fsynced, see AtomicFile). No time chunk, so equal
// images give equal bytes.
Result<void> write_png(const std::string& path, const Image& image,
                       const PngSettings& settings = {});

// Reads any PNG libpng can decode (palette, grey, 1-16 bits per sample, alpha, interlaced) into
// 8-bit RGB. Samples are taken as stored (no gamma correction); 16-bit samples are rounded to 8
// bits; alpha is composited over black (premultiplied: c * a / 255, rounded), so a fully
// transparent pixel reads as black whatever colour it stores. Images over 100 megapixels are
// refused.
Result<Image> read_png(const std::string& path);

// The same from an open stream positioned at the PNG's first byte; `path` names it in messages.
Result<Image> read_png(std::FILE* file, const std::string& path);

}  // namespace tumble::io
