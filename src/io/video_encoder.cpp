#include "io/video_encoder.hpp"

#include "io/av_handles.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace tumble::io {
namespace {

std::string av_error_text(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

// What the settings must satisfy before FFmpeg sees them; "" if they do.
std::string invalid_settings(const VideoSettings& settings) {
  const std::string size = size_text(settings.width, settings.height);
  if (settings.width <= 0 || settings.height <= 0) {
    return "width and height must be positive (got " + size + ")";
  }
  // yuv420p stores one chroma sample per 2x2 block of pixels, so H.264 in 4:2:0 codes whole
  // blocks only and libx264 refuses odd sizes. Padding or cropping here would silently change
  // the picture the caller rendered, so the caller picks an even size instead.
  if (settings.width % 2 != 0 || settings.height % 2 != 0) {
    return "width and height must be even for H.264 yuv420p video (got " + size + ")";
  }
  if (settings.fps <= 0) return "fps must be positive (got " + std::to_string(settings.fps) + ")";
  if (settings.crf < 0 || settings.crf > 51) {
    return "crf must be in 0..51 (got " + std::to_string(settings.crf) + ")";
  }
  if (settings.threads < 1) {
    return "threads must be at least 1 (got " + std::to_string(settings.threads) + ")";
  }
  return {};
}

// Flushes the file's data to disk before the rename publishes it, as AtomicFile does. Returns 0 or
// the errno of the failing call.
int sync_to_disk(const std::string& path) {
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (descriptor < 0) return errno;
  const int failure = ::fsync(descriptor) == 0 ? 0 : errno;
  ::close(descriptor);
  return failure;
}

}  // namespace

struct VideoEncoder::State {
  std::string path;            // where the finished video appears
  std::string temporary_path;  // "<path>.partial-<pid>.mp4" beside it, until finish()
  VideoSettings settings;

  AVFormatContext* format = nullptr;  // the MP4 muxer; owns `stream` and, once open, `format->pb`
  AVStream* stream = nullptr;
  av::CodecContext codec;
  av::Scaler rgb_to_yuv;
  av::Frame frame;  // yuv420p, reused for every input image
  av::Packet packet;

  int frames_added = 0;
  bool finished = false;  // the file is at `path`
  std::string error;      // the first libav failure; the encoder is unusable after one

  ~State() {
    close_file();
    avformat_free_context(format);
  }

  std::string fail(const std::string& call, int code) {
    if (error.empty()) error = path + ": " + call + ": " + av_error_text(code);
    return error;
  }

  void close_file() {
    if (format && format->pb) avio_closep(&format->pb);
    if (!finished) std::remove(temporary_path.c_str());
  }

  std::string set_up_codec();
  std::string set_up_conversion();
  std::string open_file();
  std::string encode(const AVFrame* input);
};

std::string VideoEncoder::State::set_up_codec() {
  const AVCodec* x264 = avcodec_find_encoder_by_name("libx264");
  if (!x264) return error = path + ": avcodec_find_encoder_by_name: FFmpeg has no libx264 encoder";
  // "file:" first: FFmpeg reads a path with a colon ("renders:day2/x.mp4", "pipe:1") as a
  // protocol name, which a file name must never become. The muxer reopens this URL to move the
  // index to the front, so it is spelt the same way here and in avio_open.
  int code =
      avformat_alloc_output_context2(&format, nullptr, "mp4", ("file:" + temporary_path).c_str());
  if (code < 0) return fail("avformat_alloc_output_context2", code);
  // No wall-clock creation time and no library version tag in the file: same frames, same bytes.
  format->flags |= AVFMT_FLAG_BITEXACT;
  stream = avformat_new_stream(format, nullptr);
  if (!stream) return fail("avformat_new_stream", AVERROR(ENOMEM));

  codec.reset(avcodec_alloc_context3(x264));
  if (!codec) return fail("avcodec_alloc_context3", AVERROR(ENOMEM));
  codec->width = settings.width;
  codec->height = settings.height;
  codec->pix_fmt = AV_PIX_FMT_YUV420P;
  codec->time_base = AVRational{1, settings.fps};  // one tick per frame: constant frame rate
  codec->framerate = AVRational{settings.fps, 1};
  // BT.709 (HD) limited range is what players assume for untagged HD H.264; tag it as well so
  // that nothing has to guess, and set_up_conversion() converts with the same matrix.
  codec->color_primaries = AVCOL_PRI_BT709;
  codec->color_trc = AVCOL_TRC_BT709;
  codec->colorspace = AVCOL_SPC_BT709;
  codec->color_range = AVCOL_RANGE_MPEG;
  codec->thread_count = settings.threads;
  // Asks libavcodec encoders to leave out version strings; libx264 writes the same bytes either
  // way (its own SEI names core 164 and its options, constant on one machine).
  codec->flags |= AV_CODEC_FLAG_BITEXACT;
  // MP4 keeps SPS/PPS once in the sample description (avcC), not in front of every keyframe.
  if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  code = av_opt_set(codec->priv_data, "preset", settings.preset.c_str(), 0);
  if (code < 0) return fail("av_opt_set(preset=" + settings.preset + ")", code);
  code = av_opt_set_double(codec->priv_data, "crf", settings.crf, 0);
  if (code < 0) return fail("av_opt_set(crf)", code);
  code = avcodec_open2(codec.get(), x264, nullptr);
  if (code < 0) {
    return fail("avcodec_open2(libx264, preset " + settings.preset + ", crf " +
                    std::to_string(settings.crf) + ")",
                code);
  }

  code = avcodec_parameters_from_context(stream->codecpar, codec.get());
  if (code < 0) return fail("avcodec_parameters_from_context", code);
  stream->time_base = codec->time_base;  // a hint; the muxer picks its own timescale
  stream->avg_frame_rate = codec->framerate;
  stream->r_frame_rate = codec->framerate;
  return {};
}

std::string VideoEncoder::State::set_up_conversion() {
  const int width = settings.width;
  const int height = settings.height;
  // Bicubic chroma downsampling from every input pixel (full horizontal chroma input), with exact
  // rounding and the C code path so the result does not depend on the CPU's SIMD extensions.
  const int flags = SWS_BICUBIC | SWS_FULL_CHR_H_INP | SWS_ACCURATE_RND | SWS_BITEXACT;
  rgb_to_yuv.reset(sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height,
                                  AV_PIX_FMT_YUV420P, flags, nullptr, nullptr, nullptr));
  if (!rgb_to_yuv) return fail("sws_getContext(rgb24 -> yuv420p)", AVERROR(EINVAL));
  // Kr = 0.2126, Kb = 0.0722 (ITU-R BT.709); source RGB is full range (1), output limited (0):
  // Y in 16..235, Cb/Cr in 16..240. swscale's default would be BT.601, mismatching the tags.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  const int unity = 1 << 16;  // 16.16 fixed point: brightness 0, contrast 1, saturation 1
  if (sws_setColorspaceDetails(rgb_to_yuv.get(), bt709, 1, bt709, 0, 0, unity, unity) < 0) {
    return fail("sws_setColorspaceDetails(BT.709, full -> limited range)", AVERROR(ENOSYS));
  }

  frame.reset(av_frame_alloc());
  if (!frame) return fail("av_frame_alloc", AVERROR(ENOMEM));
  frame->format = AV_PIX_FMT_YUV420P;
  frame->width = width;
  frame->height = height;
  if (const int code = av_frame_get_buffer(frame.get(), 0); code < 0) {
    return fail("av_frame_get_buffer", code);
  }
  packet.reset(av_packet_alloc());
  if (!packet) return fail("av_packet_alloc", AVERROR(ENOMEM));
  return {};
}

std::string VideoEncoder::State::open_file() {
  int code = avio_open(&format->pb, format->url, AVIO_FLAG_WRITE);
  if (code < 0) return fail("avio_open(" + temporary_path + ")", code);
  // faststart: after the last frame the muxer moves the index (moov) in front of the media data
  // (mdat), so a player or browser can start before it has the whole file.
  AVDictionary* options = nullptr;
  av_dict_set(&options, "movflags", "+faststart", 0);
  code = avformat_write_header(format, &options);
  const int unused_options = av_dict_count(options);
  av_dict_free(&options);
  if (code < 0) return fail("avformat_write_header", code);
  if (unused_options != 0) return fail("avformat_write_header(movflags)", AVERROR_OPTION_NOT_FOUND);
  return {};
}

std::string VideoEncoder::State::encode(const AVFrame* input) {
  int code = avcodec_send_frame(codec.get(), input);
  if (code < 0) return fail(input ? "avcodec_send_frame" : "avcodec_send_frame(flush)", code);
  for (;;) {
    code = avcodec_receive_packet(codec.get(), packet.get());
    if (code == AVERROR(EAGAIN) || code == AVERROR_EOF) return {};
    if (code < 0) return fail("avcodec_receive_packet", code);
    av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    code = av_interleaved_write_frame(format, packet.get());  // takes the packet's data
    if (code < 0) return fail("av_interleaved_write_frame", code);
  }
}

VideoEncoder::VideoEncoder(std::unique_ptr<State> state) : state_(std::move(state)) {}

VideoEncoder::~VideoEncoder() = default;

std::unique_ptr<VideoEncoder> VideoEncoder::open(const std::string& path,
                                                 const VideoSettings& settings,
                                                 std::string& error) {
  error = invalid_settings(settings);
  if (!error.empty()) {
    error = path + ": " + error;
    return nullptr;
  }
  av_log_set_level(AV_LOG_ERROR);  // libav and x264 chatter (stats, warnings) stays off stderr

  auto state = std::make_unique<State>();
  state->path = path;
  // Beside the target so the final rename stays on one file system; ends in .mp4 for clarity.
  state->temporary_path = path + ".partial-" + std::to_string(::getpid()) + ".mp4";
  state->settings = settings;
  error = state->set_up_codec();
  if (error.empty()) error = state->set_up_conversion();
  if (error.empty()) error = state->open_file();
  if (!error.empty()) return nullptr;  // ~State removes anything written
  return std::unique_ptr<VideoEncoder>(new VideoEncoder(std::move(state)));
}

std::string VideoEncoder::add_frame(const Image& image) {
  State& state = *state_;
  if (!state.error.empty()) return state.error;
  if (state.finished) return state.path + ": add_frame after finish()";
  const int width = state.settings.width;
  const int height = state.settings.height;
  if (image.width != width || image.height != height ||
      image.rgb.size() != static_cast<std::size_t>(width) * height * 3) {
    return state.path + ": frame " + std::to_string(state.frames_added) + " is " +
           size_text(image.width, image.height) + ", the video is " + size_text(width, height);
  }
  // The encoder may still hold a reference to the previous picture in this frame's buffers.
  int code = av_frame_make_writable(state.frame.get());
  if (code < 0) return state.fail("av_frame_make_writable", code);
  const std::uint8_t* const source[] = {image.rgb.data()};
  const int source_stride[] = {static_cast<int>(image.row_bytes())};
  code = sws_scale(state.rgb_to_yuv.get(), source, source_stride, 0, height, state.frame->data,
                   state.frame->linesize);
  if (code < 0) return state.fail("sws_scale", code);
  state.frame->pts = state.frames_added;  // in codec->time_base = 1/fps
  if (std::string failure = state.encode(state.frame.get()); !failure.empty()) return failure;
  ++state.frames_added;
  return {};
}

std::string VideoEncoder::finish() {
  State& state = *state_;
  if (state.finished) return {};
  std::string failure = state.error;
  if (failure.empty() && state.frames_added == 0) {
    failure = state.error = state.path + ": no frames were added";
  }
  if (failure.empty()) failure = state.encode(nullptr);
  if (failure.empty()) {
    if (const int code = av_write_trailer(state.format); code < 0) {
      failure = state.fail("av_write_trailer", code);
    }
  }
  if (failure.empty()) {
    if (const int code = avio_closep(&state.format->pb); code < 0) {
      failure = state.fail("avio_closep(" + state.temporary_path + ")", code);
    }
  }
  if (failure.empty()) {
    if (const int errno_value = sync_to_disk(state.temporary_path); errno_value != 0) {
      failure = state.fail("fsync(" + state.temporary_path + ")", AVERROR(errno_value));
    }
  }
  if (failure.empty() && std::rename(state.temporary_path.c_str(), state.path.c_str()) != 0) {
    failure = state.fail("rename(" + state.temporary_path + ")", AVERROR(errno));
  }
  if (!failure.empty()) {
    state.close_file();
    return failure;
  }
  state.finished = true;
  return {};
}

int VideoEncoder::frames_added() const {
  return state_->frames_added;
}

const std::string& VideoEncoder::path() const {
  return state_->path;
}

}  // namespace tumble::io
