#include "app/video_sink.hpp"

namespace tumble::app {

Result<std::unique_ptr<FrameSink>> VideoSink::open(const std::string& path,
                                                   const io::VideoSettings& settings) {
  std::string error;
  std::unique_ptr<io::VideoEncoder> encoder = io::VideoEncoder::open(path, settings, error);
  if (!encoder) return Error{error};
  return std::unique_ptr<FrameSink>(new VideoSink(std::move(encoder), settings.format));
}

// The encoder numbers frames itself, in the order they come (the loop's order).
std::string VideoSink::write(std::int64_t, const io::Image& image) {
  return encoder_->add_frame(image);
}

std::string VideoSink::finish() {
  return encoder_->finish();
}

}  // namespace tumble::app
