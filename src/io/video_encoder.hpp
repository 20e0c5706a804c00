// H.264 in MP4 from a sequence of Images: RGB is converted to BT.709 limited-range yuv420p by
// libswscale, encoded by libx264 through libavcodec and muxed by libavformat. The file is written
// under a temporary name beside the target and renamed into place by finish(), so the final path
// holds a whole video or nothing. FFmpeg stays out of this header.
#pragma once

#include <memory>
#include <string>

#include "io/image.hpp"

namespace tumble::io {

struct VideoSettings {
  int width = 0;   // pixels; must be even (yuv420p keeps one chroma sample per 2x2 pixels)
  int height = 0;  // pixels; must be even
  int fps = 0;     // frames per second; frame k is shown at t = k / fps (s), constant frame rate
  int crf = 18;    // x264 constant rate factor, 0 (lossless) .. 51 (worst); 18 looks transparent
  std::string preset = "veryfast";  // x264 speed/size trade-off, "ultrafast" .. "placebo"
  // Encoder threads: a fixed count, never "auto", so the bytes do not depend on the machine. One
  // by default because only that gave byte-identical files run after run: with 2, x264 (core 164)
  // wrote a different stream in up to 1 run in 4 for small frames fed back to back (not so with
  // its mb-tree lookahead off). More threads are faster but not repeatable.
  int threads = 1;
};

class VideoEncoder {
 public:
  // Creates "<path>.partial-<pid>.mp4" and sets up the encoder. Returns nullptr and sets `error`
  // (naming the path and the failing call) if the settings are invalid or FFmpeg refuses.
  static std::unique_ptr<VideoEncoder> open(const std::string& path, const VideoSettings& settings,
                                            std::string& error);

  ~VideoEncoder();  // removes the temporary file unless finish() succeeded
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Encodes the next frame (frame k is presented at pts k in a 1/fps time base). The image must
  // be settings.width x settings.height. Returns "" on success, else the error.
  std::string add_frame(const Image& image);

  // Drains the encoder, writes the MP4 index at the front of the file, then renames the file onto
  // the final path. Returns "" on success; on failure nothing is left at either name.
  std::string finish();

  int frames_added() const;
  const std::string& path() const;

 private:
  struct State;
  explicit VideoEncoder(std::unique_ptr<State> state);

  std::unique_ptr<State> state_;
};

}  // namespace tumble::io
