// poster.png: one frame of the render kept as a still, for a page or a video player's poster.
#pragma once

#include <memory>
#include <string>

#include "pipeline/frame_sinks.hpp"

namespace tumble::pipeline {

// Writes frame `frame` (scene::poster_frame) to `path` as PNG, the same bytes as that frame's
// frame_NNNNN.png with the same settings; writes nothing when the frame is not rendered.
class PosterSink final : public FrameSink {
 public:
  PosterSink(std::string path, std::int64_t frame, const io::PngSettings& settings)
      : path_(std::move(path)), frame_(frame), settings_(settings) {}
  const char* stage() const override { return "poster"; }
  Result<void> write(std::int64_t frame, const io::Image& image) override {
    if (frame != frame_) return Result<void>::success();
    return io::write_png(path_, image, settings_);
  }

 private:
  std::string path_;
  std::int64_t frame_;
  io::PngSettings settings_;
};

}  // namespace tumble::pipeline
