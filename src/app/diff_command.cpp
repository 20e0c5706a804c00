#include "app/diff_command.hpp"

#include <algorithm>
#include <cmath>

#include "io/image.hpp"
#include "io/image_diff.hpp"
#include "io/png_io.hpp"

namespace tumble::app {
namespace {

std::string size_text(const io::Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// Three significant digits, never in exponent notation: 8.33%, 0.0244%, 0.000301%.
std::string percent_text(std::int64_t part, std::int64_t whole) {
  const double percent = 100.0 * static_cast<double>(part) / static_cast<double>(whole);
  const int decimals =
      percent > 0.0 ? std::max(0, 2 - static_cast<int>(std::floor(std::log10(percent)))) : 0;
  char text[64];
  std::snprintf(text, sizeof text, "%.*f%%", decimals, percent);
  return text;
}

bool read(const std::string& path, io::Image& image, std::FILE* err) {
  const std::string error = io::read_png(path, image);
  if (!error.empty()) std::fprintf(err, "tumble: %s\n", error.c_str());
  return error.empty();
}

}  // namespace

int run_diff(const DiffCommandOptions& options, std::FILE* out, std::FILE* err) {
  io::Image first;
  io::Image second;
  if (!read(options.first_path, first, err) || !read(options.second_path, second, err)) {
    return kExitBadInput;
  }
  if (first.width != second.width || first.height != second.height) {
    std::fprintf(err, "tumble: cannot compare images of different sizes: %s is %s, %s is %s\n",
                 options.first_path.c_str(), size_text(first).c_str(), options.second_path.c_str(),
                 size_text(second).c_str());
    return kExitBadInput;
  }

  const io::DiffResult result =
      io::compare_images(first, second, {options.threshold, options.max_pixels});
  const std::int64_t pixels = std::int64_t{first.width} * first.height;
  std::fprintf(
      out, "%s: %lld of %lld pixels differ (%s), largest channel difference %d, RMS %.4g\n",
      result.match ? "match" : "mismatch", static_cast<long long>(result.differing_pixels),
      static_cast<long long>(pixels), percent_text(result.differing_pixels, pixels).c_str(),
      result.max_channel_difference, result.rms);
  std::fflush(out);

  if (!options.out.empty()) {
    const io::Image picture = io::diff_image(first, second, options.threshold);
    if (const std::string error = io::write_png(options.out, picture); !error.empty()) {
      std::fprintf(err, "tumble: %s\n", error.c_str());
      return kExitBadInput;
    }
  }
  return result.match ? kExitOk : kExitMismatch;
}

}  // namespace tumble::app
