// Where finished frames go: each output of a render is a sink on the frame loop
// (app/frame_pipeline.hpp), a small object of its own. A new format (WebM, GIF, a contact sheet)
// is one more sink; the loop does not change.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "common/result.hpp"
#include "io/image.hpp"
#include "io/png_io.hpp"
#include "io/video_encoder.hpp"

namespace tumble::pipeline {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Its stage in report.json ("png", "video").
  virtual const char* stage() const = 0;
  // Takes frame `frame`. Frames come in increasing order, all from one thread (not necessarily
  // the one that made the sink). An error (a complete message) stops the render.
  virtual Result<void> write(std::int64_t frame, const io::Image& image) = 0;
  // After the last frame: success once the output is complete, else why it is not.
  virtual Result<void> finish() { return Result<void>::success(); }
};

// The file name of frame `frame` in a render's frames/ folder: "frame_00042.png".
std::string png_frame_name(std::int64_t frame);

// frame_00000.png ... in a folder, which it creates.
class PngFrames final : public FrameSink {
 public:
  static Result<std::unique_ptr<FrameSink>> open(const std::string& folder,
                                                 const io::PngSettings& settings);
  const char* stage() const override { return "png"; }
  Result<void> write(std::int64_t frame, const io::Image& image) override;

 private:
  PngFrames(std::string folder, const io::PngSettings& settings)
      : folder_(std::move(folder)), settings_(settings) {}
  std::string folder_;
  io::PngSettings settings_;
};

// A video of any format (io::VideoFormat: MP4, WebM, GIF), one io::VideoEncoder fed every frame
// in order; unless finished, its destructor removes the partial file.
class VideoSink final : public FrameSink {
 public:
  static Result<std::unique_ptr<FrameSink>> open(const std::string& path,
                                                 const io::VideoSettings& settings);
  // Its stage in report.json: "video" for the MP4 (as before other formats), else the format's
  // name ("webm", "gif").
  const char* stage() const override {
    return format_ == io::VideoFormat::mp4 ? "video" : io::video_format_name(format_);
  }
  Result<void> write(std::int64_t frame, const io::Image& image) override;
  Result<void> finish() override;

 private:
  VideoSink(std::unique_ptr<io::VideoEncoder> encoder, io::VideoFormat format)
      : encoder_(std::move(encoder)), format_(format) {}
  std::unique_ptr<io::VideoEncoder> encoder_;
  io::VideoFormat format_;
};

}  // namespace tumble::pipeline
