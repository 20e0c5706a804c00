// Reads an MP4 back with libavformat/libavcodec for tests: container fields, bitstream fields and
// every decoded picture, converted back to RGB.
#pragma once

#include <array>
#include <string>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include "io/image.hpp"

namespace tumble::testing {

using io::Image;

// What a reader finds in the file: container fields, bitstream fields and the decoded pictures.
struct DecodedVideo {
  std::string error;
  AVCodecID codec = AV_CODEC_ID_NONE;
  int width = 0;
  int height = 0;
  AVPixelFormat stream_pixel_format = AV_PIX_FMT_NONE;
  AVRational avg_frame_rate{0, 1};
  AVRational r_frame_rate{0, 1};
  double duration = 0;     // s, from the stream (a WebM: the file)
  std::string alpha_mode;  // a WebM track's alpha_mode ("1": it carries alpha); "" if not said
  AVColorPrimaries primaries = AVCOL_PRI_UNSPECIFIED;  // as the container (colr box) says
  AVColorTransferCharacteristic transfer = AVCOL_TRC_UNSPECIFIED;
  AVColorSpace space = AVCOL_SPC_UNSPECIFIED;
  AVColorRange range = AVCOL_RANGE_UNSPECIFIED;

  struct Picture {
    double time = 0;  // s, presentation time
    AVPixelFormat pixel_format = AV_PIX_FMT_NONE;
    AVColorPrimaries primaries = AVCOL_PRI_UNSPECIFIED;  // as the H.264 VUI says
    AVColorTransferCharacteristic transfer = AVCOL_TRC_UNSPECIFIED;
    AVColorSpace space = AVCOL_SPC_UNSPECIFIED;
    AVColorRange range = AVCOL_RANGE_UNSPECIFIED;
    std::array<double, 3> mean_yuv{};  // mean code value of the Y, Cb and Cr planes
    Image rgb;  // back to full-range RGB with the BT.709 matrix; yuva420p's alpha plane too
  };
  std::vector<Picture> pictures;
};

// Decodes every frame of the first video stream, with the decoder named `decoder_name` (such as
// "libvpx-vp9", which reads a WebM's alpha) or else libavcodec's choice; on failure `error` says
// which call failed.
DecodedVideo read_video(const std::string& path, const char* decoder_name = nullptr);

}  // namespace tumble::testing
