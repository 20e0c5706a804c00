#include "pipeline/frame_sinks.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace tumble::pipeline {

namespace fs = std::filesystem;

Result<std::unique_ptr<FrameSink>> PngFrames::open(const std::string& folder,
                                                   const io::PngSettings& settings) {
  std::error_code error;
  fs::create_directory(folder, error);
  if (error) return Error{"cannot create " + folder + ": " + error.message()};
  return std::unique_ptr<FrameSink>(new PngFrames(folder, settings));
}

std::string png_frame_name(std::int64_t frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05lld.png", static_cast<long long>(frame));
  return name;
}

Result<void> PngFrames::write(std::int64_t frame, const io::Image& image) {
  return io::write_png((fs::path(folder_) / png_frame_name(frame)).string(), image, settings_);
}

Result<std::unique_ptr<FrameSink>> VideoSink::open(const std::string& path,
                                                   const io::VideoSettings& settings) {
  Result<std::unique_ptr<io::VideoEncoder>> encoder = io::VideoEncoder::open(path, settings);
  if (!encoder) return Error{encoder.error()};
  return std::unique_ptr<FrameSink>(new VideoSink(std::move(encoder).value(), settings.format));
}

// The encoder numbers frames itself, in the order they come (the loop's order).
Result<void> VideoSink::write(std::int64_t, const io::Image& image) {
  return encoder_->add_frame(image);
}

Result<void> VideoSink::finish() {
  return encoder_->finish();
}

}  // namespace tumble::pipeline
