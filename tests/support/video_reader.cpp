#include "support/video_reader.hpp"

#include "io/av_handles.hpp"

#include <memory>

extern "C" {
#include <libavutil/error.h>
#include <libswscale/swscale.h>
}

namespace tumble::testing {
namespace {

double mean_plane(const AVFrame& frame, int plane, int width, int height) {
  double sum = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) sum += frame.data[plane][y * frame.linesize[plane] + x];
  }
  return sum / (static_cast<double>(width) * height);
}

// A picture that is not yuv420p (a GIF's, decoded to RGB with its palette) is converted as it
// is, with no colour matrix.
DecodedVideo::Picture take_picture(const AVFrame& frame, AVRational time_base,
                                   SwsContext* yuv_to_rgb) {
  DecodedVideo::Picture picture;
  picture.time = static_cast<double>(frame.best_effort_timestamp) * av_q2d(time_base);
  picture.pixel_format = static_cast<AVPixelFormat>(frame.format);
  picture.primaries = frame.color_primaries;
  picture.transfer = frame.color_trc;
  picture.space = frame.colorspace;
  picture.range = frame.color_range;
  picture.rgb = Image(frame.width, frame.height);
  std::uint8_t* const destination[] = {picture.rgb.rgb.data()};
  const int destination_stride[] = {static_cast<int>(picture.rgb.row_bytes())};
  if (frame.format != AV_PIX_FMT_YUV420P && frame.format != AV_PIX_FMT_YUVA420P) {
    io::av::Scaler as_is(sws_getContext(frame.width, frame.height, picture.pixel_format,
                                        frame.width, frame.height, AV_PIX_FMT_RGB24, SWS_POINT,
                                        nullptr, nullptr, nullptr));
    sws_scale(as_is.get(), frame.data, frame.linesize, 0, frame.height, destination,
              destination_stride);
    return picture;
  }
  picture.mean_yuv = {mean_plane(frame, 0, frame.width, frame.height),
                      mean_plane(frame, 1, frame.width / 2, frame.height / 2),
                      mean_plane(frame, 2, frame.width / 2, frame.height / 2)};
  sws_scale(yuv_to_rgb, frame.data, frame.linesize, 0, frame.height, destination,
            destination_stride);
  if (frame.format == AV_PIX_FMT_YUVA420P) {
    for (int y = 0; y < frame.height; ++y) {
      const std::uint8_t* row = frame.data[3] + y * frame.linesize[3];
      picture.rgb.alpha.insert(picture.rgb.alpha.end(), row, row + frame.width);
    }
  }
  return picture;
}

}  // namespace

DecodedVideo read_video(const std::string& path, const char* decoder_name) {
  DecodedVideo video;
  AVFormatContext* opened = nullptr;
  if (int code = avformat_open_input(&opened, path.c_str(), nullptr, nullptr); code < 0) {
    video.error = "avformat_open_input: " + io::av::error_text(code);
    return video;
  }
  std::unique_ptr<AVFormatContext, io::av::InputCloser> format(opened);
  if (int code = avformat_find_stream_info(format.get(), nullptr); code < 0) {
    video.error = "avformat_find_stream_info: " + io::av::error_text(code);
    return video;
  }
  const AVCodec* decoder = nullptr;
  const int index = av_find_best_stream(format.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (index < 0) {
    video.error = "av_find_best_stream: " + io::av::error_text(index);
    return video;
  }
  if (decoder_name) decoder = avcodec_find_decoder_by_name(decoder_name);
  if (!decoder) {
    video.error = std::string("no decoder ") + (decoder_name ? decoder_name : "");
    return video;
  }
  const AVStream& stream = *format->streams[index];
  const AVCodecParameters& parameters = *stream.codecpar;
  video.codec = parameters.codec_id;
  video.width = parameters.width;
  video.height = parameters.height;
  video.stream_pixel_format = static_cast<AVPixelFormat>(parameters.format);
  video.avg_frame_rate = stream.avg_frame_rate;
  video.r_frame_rate = stream.r_frame_rate;
  // A WebM (Matroska) gives its length for the file, not the stream.
  video.duration = stream.duration != AV_NOPTS_VALUE
                       ? static_cast<double>(stream.duration) * av_q2d(stream.time_base)
                       : static_cast<double>(format->duration) / AV_TIME_BASE;
  if (const AVDictionaryEntry* alpha = av_dict_get(stream.metadata, "alpha_mode", nullptr, 0)) {
    video.alpha_mode = alpha->value;
  }
  video.primaries = parameters.color_primaries;
  video.transfer = parameters.color_trc;
  video.space = parameters.color_space;
  video.range = parameters.color_range;

  io::av::CodecContext codec(avcodec_alloc_context3(decoder));
  avcodec_parameters_to_context(codec.get(), &parameters);
  codec->thread_count = 1;
  if (int code = avcodec_open2(codec.get(), decoder, nullptr); code < 0) {
    video.error = "avcodec_open2: " + io::av::error_text(code);
    return video;
  }
  // Chroma interpolated for every output pixel (FULL_CHR_H_INT): swscale's default upsampling
  // alone adds about 2 code values of error, which would hide the encoder's own.
  io::av::Scaler yuv_to_rgb(sws_getContext(parameters.width, parameters.height, AV_PIX_FMT_YUV420P,
                                           parameters.width, parameters.height, AV_PIX_FMT_RGB24,
                                           SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
                                           nullptr, nullptr, nullptr));
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);  // limited-range BT.709 in, full RGB out
  sws_setColorspaceDetails(yuv_to_rgb.get(), bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);

  io::av::Packet packet(av_packet_alloc());
  io::av::Frame frame(av_frame_alloc());
  auto drain = [&] {
    while (avcodec_receive_frame(codec.get(), frame.get()) == 0) {
      video.pictures.push_back(take_picture(*frame, stream.time_base, yuv_to_rgb.get()));
      av_frame_unref(frame.get());
    }
  };
  while (av_read_frame(format.get(), packet.get()) == 0) {
    if (packet->stream_index == index) avcodec_send_packet(codec.get(), packet.get());
    av_packet_unref(packet.get());
    drain();
  }
  avcodec_send_packet(codec.get(), nullptr);
  drain();
  return video;
}

}  // namespace tumble::testing
