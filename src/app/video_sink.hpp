// A WebM or GIF video as a sink of the frame loop (the MP4 is Mp4Video, frame_sinks.hpp): one
// io::VideoEncoder fed every frame in order.
#pragma once

#include <memory>
#include <string>

#include "app/frame_sinks.hpp"

namespace tumble::app {

// Unless finished, its destructor removes the partial file.
class VideoSink final : public FrameSink {
 public:
  static Result<std::unique_ptr<FrameSink>> open(const std::string& path,
                                                 const io::VideoSettings& settings);
  // Its stage in report.json: the format's name ("webm", "gif").
  const char* stage() const override { return io::video_format_name(format_); }
  std::string write(std::int64_t frame, const io::Image& image) override;
  std::string finish() override;

 private:
  VideoSink(std::unique_ptr<io::VideoEncoder> encoder, io::VideoFormat format)
      : encoder_(std::move(encoder)), format_(format) {}
  std::unique_ptr<io::VideoEncoder> encoder_;
  io::VideoFormat format_;
};

}  // namespace tumble::app
