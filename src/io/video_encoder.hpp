// A video from a sequence of Images, in one of three formats:
// - MP4: RGB converted to BT.709 limited-range yuv420p by libswscale, H.264 by libx264 through
//   libavcodec, muxed by libavformat;
// - WebM: the same yuv420p, VP9 by libvpx through libavcodec, in libavformat's WebM muxer;
// - GIF: one palette for the whole video from libavfilter's palettegen over every frame, each
//   frame mapped onto it by paletteuse, FFmpeg's GIF encoder and muxer.
// The file is written under a temporary name beside the target and renamed into place by
// finish(), so the final path holds a whole video or nothing. FFmpeg stays out of this header.
#pragma once

#include <memory>
#include <string>

#include "common/result.hpp"
#include "common/video_format.hpp"
#include "io/image.hpp"

namespace tumble::io {

using common::kAllVideoFormats;
using common::video_format_name;
using common::VideoFormat;

// GIF times frames in whole centiseconds, and browsers show delays under 2 cs as 10 cs. So a GIF
// runs at 100/n frames per second, n = max(2, ceil(100 / fps)): every frame at 50, 25, 20 fps
// and below 100/n; from 60 fps 50 (n = 2), from 30 fps 25 (n = 4), from 24 fps 20 (n = 5). GIF
// frame j, at exactly j n / 100 s, shows the video frame nearest that time: each is then within
// half a video frame of its time, and the GIF's length is the video's.
int gif_delay_centiseconds(int fps);

struct VideoSettings {
  VideoFormat format = VideoFormat::mp4;
  // Pixels; even for MP4 and WebM (yuv420p keeps one chroma sample per 2x2 pixels), any for GIF.
  int width = 0;
  int height = 0;
  int fps = 0;   // frames per second; frame k is shown at t = k / fps (s), constant frame rate
  int crf = 18;  // MP4: x264 constant rate factor, 0 (lossless) .. 51 (worst); 18 looks transparent
  // WebM: libvpx's constant quality, 0 (best) .. 63 (worst), at no bitrate cap. Google's VP9 VOD
  // guide suggests 33 for 640x480 with a cap; 30 keeps the encoder test's moving pattern within
  // 2 levels RMS of its source (tests/io/video_encoder_test.cpp).
  int vp9_crf = 30;
  bool loop = true;  // GIF: play forever (else once)
  // GIF: its frames per second as asked (0: fps; more than fps: fps), then as
  // gif_delay_centiseconds allows; its palette's colours (2 to 256); how frames map onto it.
  int gif_fps = 0;
  int gif_colors = 256;
  common::GifDither gif_dither = common::GifDither::bayer;
  // WebM only: VP9 in yuva420p, its alpha plane from each Image's alpha (which must be there).
  // libvpx codes the alpha as a second stream that the WebM muxer stores in BlockAdditional
  // elements (alpha_mode 1); libavcodec's libvpx-vp9 decoder reads it back, its native vp9
  // decoder does not.
  bool alpha = false;
  // MP4 or WebM: a segment of a longer video, to be joined to the others by stream copy
  // (io/video_join.hpp): its first frame is frame `first_frame` of the whole, at first_frame /
  // fps s, and a key frame (x264's first frame is an IDR frame, libvpx's a key frame). x264
  // keeps its headers independent of the content (its `stitchable` option), so every segment of
  // the same settings carries the same SPS and PPS.
  bool segment = false;
  long long first_frame = 0;
  std::string preset = "veryfast";  // x264 speed/size trade-off, "ultrafast" .. "placebo"
  // Encoder threads: a fixed count, never "auto", so the bytes do not depend on the machine. One
  // by default because only that gave byte-identical files run after run: with 2, x264 (core 164)
  // wrote a different stream in up to 1 run in 4 for small frames fed back to back (not so with
  // its mb-tree lookahead off). More threads are faster but not repeatable.
  int threads = 1;
};

class VideoEncoder {
 public:
  // Creates "<path>.partial-<pid>.<format>" and sets up the encoder. The error names the path and
  // the failing call, when the settings are invalid or FFmpeg refuses.
  static Result<std::unique_ptr<VideoEncoder>> open(const std::string& path,
                                                    const VideoSettings& settings);

  ~VideoEncoder();  // removes the temporary file unless finish() succeeded
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Encodes the next frame (frame k is presented at pts k in a 1/fps time base). The image must
  // be settings.width x settings.height.
  Result<void> add_frame(const Image& image);

  // Drains the encoder (MP4: writes the index at the front of the file; GIF: maps and encodes
  // every frame now that the palette is known), then renames the file onto the final path.
  // On failure nothing is left at either name.
  Result<void> finish();

  int frames_added() const;
  const std::string& path() const;

 private:
  struct State;
  explicit VideoEncoder(std::unique_ptr<State> state);

  std::unique_ptr<State> state_;
};

}  // namespace tumble::io
