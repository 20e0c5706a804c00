#include "io/video_decoder.hpp"

#include "io/av_handles.hpp"

extern "C" {
#include <libavutil/log.h>
#include <libavutil/pixdesc.h>
#include <libavutil/video_enc_params.h>
}

#include <algorithm>

namespace tumble::io {
namespace {

bool is_yuv(AVPixelFormat format) {
  const AVPixFmtDescriptor* descriptor = av_pix_fmt_desc_get(format);
  return descriptor && !(descriptor->flags & AV_PIX_FMT_FLAG_RGB) &&
         !(descriptor->flags & AV_PIX_FMT_FLAG_PAL) && descriptor->nb_components >= 3;
}

// swscale's name for the matrix a frame declares; BT.709 when unspecified.
int sws_matrix(AVColorSpace space) {
  switch (space) {
    case AVCOL_SPC_BT470BG:
    case AVCOL_SPC_SMPTE170M:
      return SWS_CS_ITU601;
    case AVCOL_SPC_SMPTE240M:
      return SWS_CS_SMPTE240M;
    case AVCOL_SPC_BT2020_NCL:
    case AVCOL_SPC_BT2020_CL:
      return SWS_CS_BT2020;
    default:
      return SWS_CS_ITU709;
  }
}

// Chroma interpolated for every output pixel (FULL_CHR_H_INT) and accurate rounding, so that
// decoding adds as little as it can to what the encoder lost.
constexpr int kToRgbFlags = SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT;

}  // namespace

YuvMatrix yuv_matrix(int sws_matrix) {
  switch (sws_matrix) {
    case SWS_CS_ITU601:
      return {"BT.601", 0.299, 0.114};
    case SWS_CS_SMPTE240M:
      return {"SMPTE 240M", 0.212, 0.087};
    case SWS_CS_BT2020:
      return {"BT.2020", 0.2627, 0.0593};
    default:
      return {"BT.709", 0.2126, 0.0722};
  }
}

std::string describe(const VideoPictureFormat& format) {
  if (format.yuv_format < 0) return "RGB";
  const char* name = av_get_pix_fmt_name(static_cast<AVPixelFormat>(format.yuv_format));
  return std::string(name ? name : "YUV") + " " + yuv_matrix(format.matrix).name +
         (format.full_range ? " full range" : " limited range");
}

Image through_picture_format(const Image& image, const VideoPictureFormat& format) {
  if (format.yuv_format < 0 || image.rgb.empty()) return image;
  const auto yuv = static_cast<AVPixelFormat>(format.yuv_format);
  const int* matrix = sws_getCoefficients(format.matrix);
  const int range = format.full_range ? 1 : 0;
  // The flags VideoEncoder converts with.
  av::Scaler to_yuv(
      sws_getContext(image.width, image.height, AV_PIX_FMT_RGB24, image.width, image.height, yuv,
                     SWS_BICUBIC | SWS_FULL_CHR_H_INP | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr,
                     nullptr, nullptr));
  av::Scaler to_rgb(sws_getContext(image.width, image.height, yuv, image.width, image.height,
                                   AV_PIX_FMT_RGB24, kToRgbFlags, nullptr, nullptr, nullptr));
  av::Frame planes(av_frame_alloc());
  if (!to_yuv || !to_rgb || !planes) return image;
  planes->format = yuv;
  planes->width = image.width;
  planes->height = image.height;
  if (av_frame_get_buffer(planes.get(), 0) < 0) return image;
  sws_setColorspaceDetails(to_yuv.get(), matrix, 1, matrix, range, 0, 1 << 16, 1 << 16);
  sws_setColorspaceDetails(to_rgb.get(), matrix, range, matrix, 1, 0, 1 << 16, 1 << 16);
  const std::uint8_t* const source[] = {image.rgb.data()};
  const int stride[] = {static_cast<int>(image.row_bytes())};
  sws_scale(to_yuv.get(), source, stride, 0, image.height, planes->data, planes->linesize);
  Image out(image.width, image.height);
  std::uint8_t* const destination[] = {out.rgb.data()};
  sws_scale(to_rgb.get(), planes->data, planes->linesize, 0, image.height, destination, stride);
  return out;
}

struct VideoDecoder::State {
  std::string path;
  std::unique_ptr<AVFormatContext, av::InputCloser> format;
  av::CodecContext codec;
  av::Packet packet{av_packet_alloc()};
  av::Frame frame{av_frame_alloc()};
  SwsContext* scaler = nullptr;  // cached by sws_getCachedContext, freed with the state
  int stream_index = -1;
  AVRational time_base{1, 1};
  bool input_ended = false;           // every packet sent, and the flush packet too
  VideoPictureFormat picture_format;  // of the last frame
  int coarsest_qp = -1;               // H.264: the largest macroblock QP so far; else -1
  int chroma_qp_offset = 0;           // H.264: the picture parameter set's chroma_qp_index_offset

  ~State() { sws_freeContext(scaler); }

  std::string fail(const std::string& call, int code) const {
    return path + ": cannot decode video: " + call + ": " + av::error_text(code);
  }
  Result<Image> to_rgb();
  void note_quantisers();
  // Sends packets until the decoder has a frame: true, or false at the end.
  Result<bool> receive();
};

Result<Image> VideoDecoder::State::to_rgb() {
  const auto pixel_format = static_cast<AVPixelFormat>(frame->format);
  scaler =
      sws_getCachedContext(scaler, frame->width, frame->height, pixel_format, frame->width,
                           frame->height, AV_PIX_FMT_RGB24, kToRgbFlags, nullptr, nullptr, nullptr);
  if (!scaler) {
    return Error{path + ": cannot convert " + av_get_pix_fmt_name(pixel_format) +
                 " pictures to RGB"};
  }
  picture_format = {};
  if (is_yuv(pixel_format)) {
    picture_format = {pixel_format, sws_matrix(frame->colorspace),
                      frame->color_range == AVCOL_RANGE_JPEG};
    const int* matrix = sws_getCoefficients(picture_format.matrix);
    sws_setColorspaceDetails(scaler, matrix, picture_format.full_range ? 1 : 0, matrix, 1, 0,
                             1 << 16, 1 << 16);
  }
  Image image(frame->width, frame->height);
  std::uint8_t* const destination[] = {image.rgb.data()};
  const int destination_stride[] = {static_cast<int>(image.row_bytes())};
  sws_scale(scaler, frame->data, frame->linesize, 0, frame->height, destination,
            destination_stride);
  return image;
}

// Reads the macroblock QPs libavcodec exports with an H.264 frame (AV_CODEC_EXPORT_DATA_
// VIDEO_ENC_PARAMS: the picture's base QP plus each macroblock's delta).
void VideoDecoder::State::note_quantisers() {
  const AVFrameSideData* side = av_frame_get_side_data(frame.get(), AV_FRAME_DATA_VIDEO_ENC_PARAMS);
  if (!side) return;
  const auto* params = reinterpret_cast<const AVVideoEncParams*>(side->data);
  if (params->type != AV_VIDEO_ENC_PARAMS_H264) return;
  chroma_qp_offset = std::max(params->delta_qp[1][0], params->delta_qp[2][0]);  // Cb, Cr
  for (unsigned n = 0; n < params->nb_blocks; ++n) {
    const AVVideoBlockParams* block =
        av_video_enc_params_block(const_cast<AVVideoEncParams*>(params), n);
    coarsest_qp = std::max(coarsest_qp, params->qp + block->delta_qp);
  }
}

Result<bool> VideoDecoder::State::receive() {
  for (;;) {
    const int received = avcodec_receive_frame(codec.get(), frame.get());
    if (received != AVERROR(EAGAIN)) {
      if (received < 0 && received != AVERROR_EOF) {
        return Error{fail("avcodec_receive_frame", received)};
      }
      return received >= 0;
    }
    if (input_ended) return false;
    const int read = av_read_frame(format.get(), packet.get());
    if (read < 0 && read != AVERROR_EOF) return Error{fail("av_read_frame", read)};
    if (read == AVERROR_EOF) input_ended = true;
    if (read == 0 && packet->stream_index != stream_index) {
      av_packet_unref(packet.get());
      continue;
    }
    const int sent = avcodec_send_packet(codec.get(), input_ended ? nullptr : packet.get());
    av_packet_unref(packet.get());
    if (sent < 0 && sent != AVERROR_EOF) return Error{fail("avcodec_send_packet", sent)};
  }
}

Result<std::unique_ptr<VideoDecoder>> VideoDecoder::open(const std::string& path) {
  // FFmpeg's own lines ("moov atom not found") would come before ours, which say the same with
  // the path: every failure is returned as a message instead.
  av_log_set_level(AV_LOG_FATAL);
  auto state = std::make_unique<State>();
  state->path = path;
  AVFormatContext* opened = nullptr;
  if (const int code = avformat_open_input(&opened, path.c_str(), nullptr, nullptr); code < 0) {
    return Error{path + ": cannot read as a video: " + av::error_text(code)};
  }
  state->format.reset(opened);
  if (const int code = avformat_find_stream_info(opened, nullptr); code < 0) {
    return Error{state->fail("avformat_find_stream_info", code)};
  }
  const AVCodec* decoder = nullptr;
  state->stream_index = av_find_best_stream(opened, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (state->stream_index < 0) {
    return Error{path + ": holds no video stream FFmpeg can decode"};
  }
  const AVStream& stream = *opened->streams[state->stream_index];
  state->time_base = stream.time_base;
  state->codec.reset(avcodec_alloc_context3(decoder));
  if (!state->codec || !state->packet || !state->frame) {
    return Error{path + ": cannot decode video: FFmpeg could not allocate its state"};
  }
  if (const int code = avcodec_parameters_to_context(state->codec.get(), stream.codecpar);
      code < 0) {
    return Error{state->fail("avcodec_parameters_to_context", code)};
  }
  // Decoded pictures do not depend on the thread count; two keep up with the comparison.
  state->codec->thread_count = 2;
  state->codec->export_side_data |= AV_CODEC_EXPORT_DATA_VIDEO_ENC_PARAMS;
  if (const int code = avcodec_open2(state->codec.get(), decoder, nullptr); code < 0) {
    return Error{state->fail("avcodec_open2", code)};
  }
  return std::unique_ptr<VideoDecoder>(new VideoDecoder(std::move(state)));
}

VideoDecoder::VideoDecoder(std::unique_ptr<State> state) : state_(std::move(state)) {}
VideoDecoder::~VideoDecoder() = default;

Result<std::optional<DecodedFrame>> VideoDecoder::next() {
  State& state = *state_;
  const Result<bool> received = state.receive();
  if (!received) return Error{received.error()};
  if (!*received) return std::optional<DecodedFrame>();  // the end
  DecodedFrame decoded;
  const std::int64_t timestamp = state.frame->best_effort_timestamp;
  decoded.time =
      timestamp == AV_NOPTS_VALUE ? 0.0 : static_cast<double>(timestamp) * av_q2d(state.time_base);
  Result<Image> image = state.to_rgb();
  state.note_quantisers();
  av_frame_unref(state.frame.get());
  if (!image) return Error{image.error()};
  decoded.image = std::move(*image);
  return std::optional<DecodedFrame>(std::move(decoded));
}

VideoPictureFormat VideoDecoder::picture_format() const {
  return state_->picture_format;
}

QuantisationAllowance VideoDecoder::quantisation_allowance() const {
  const State& state = *state_;
  if (state.coarsest_qp < 0 || state.picture_format.yuv_format < 0) return {};
  return h264_allowance(state.coarsest_qp, state.chroma_qp_offset, state.picture_format.matrix,
                        state.picture_format.full_range);
}

const std::string& VideoDecoder::path() const {
  return state_->path;
}

}  // namespace tumble::io
