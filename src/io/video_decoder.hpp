// Frames of a video file (anything libavformat opens and libavcodec decodes: MP4, WebM, GIF, …),
// one at a time in presentation order, as 8-bit RGB Images. FFmpeg stays out of this header.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "common/result.hpp"
#include "io/image.hpp"
#include "io/quantisation.hpp"

namespace tumble::io {

struct DecodedFrame {
  Image image;
  double time = 0.0;  // presentation time (s) from the stream's start
};

// How a video stores its pictures: FFmpeg's pixel format number (-1 when it is not YUV: a GIF's
// palette), and the matrix (swscale's SWS_CS_* number) and range of its YUV.
struct VideoPictureFormat {
  int yuv_format = -1;
  int matrix = 0;
  bool full_range = false;
};

// A VideoPictureFormat's matrix: its name and luma weights Kr, Kb (ITU-R BT.601, BT.709,
// SMPTE 240M, BT.2020; BT.709 for any other number).
struct YuvMatrix {
  const char* name;
  double kr, kb;
};
YuvMatrix yuv_matrix(int sws_matrix);

// "yuv420p BT.709 limited range": the pixel format, matrix and range, for reports.
std::string describe(const VideoPictureFormat& format);

// `image` converted into `format` and back to RGB, the way VideoEncoder and VideoDecoder convert:
// what a video in that format can hold of it before any compression (4:2:0 keeps one chroma
// sample per 2x2 pixels). Unchanged when the format is not YUV. Safe to call from any thread.
Image through_picture_format(const Image& image, const VideoPictureFormat& format);

class VideoDecoder {
 public:
  // Opens the first video stream of `path`. The error names the path and the failing call, when
  // the file cannot be read as a video.
  static Result<std::unique_ptr<VideoDecoder>> open(const std::string& path);

  ~VideoDecoder();
  VideoDecoder(const VideoDecoder&) = delete;
  VideoDecoder& operator=(const VideoDecoder&) = delete;

  // The next frame, nothing at the end of the video, or an error on a decoding error. YUV pictures
  // are converted with the matrix and range the stream declares, BT.709 limited range when it
  // declares none (what VideoEncoder writes); others (a GIF's palette) as they are.
  Result<std::optional<DecodedFrame>> next();

  const std::string& path() const;
  // The format of the last frame next() returned.
  VideoPictureFormat picture_format() const;
  // What H.264's quantiser may have changed in the frames returned so far: the allowance for the
  // coarsest macroblock QP among them. An error can reach a frame by prediction from any frame
  // decoded before it, so the coarsest step so far bounds it, not the frame's own (a skipped
  // macroblock keeps its reference's error whatever QP it is labelled with). Inactive for other
  // codecs.
  QuantisationAllowance quantisation_allowance() const;

 private:
  struct State;
  explicit VideoDecoder(std::unique_ptr<State> state);

  std::unique_ptr<State> state_;
};

}  // namespace tumble::io
