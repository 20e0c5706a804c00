#include "io/video_encoder.hpp"

#include "io/av_handles.hpp"
#include "io/filter_graph.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

namespace tumble::io {
namespace {

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

// What the settings must satisfy before FFmpeg sees them; "" if they do.
std::string invalid_settings(const VideoSettings& settings) {
  const std::string size = size_text(settings.width, settings.height);
  if (settings.width <= 0 || settings.height <= 0) {
    return "width and height must be positive (got " + size + ")";
  }
  // yuv420p stores one chroma sample per 2x2 block of pixels, so H.264 and VP9 in 4:2:0 code
  // whole blocks only and libx264 refuses odd sizes. Padding or cropping here would silently
  // change the picture the caller rendered, so the caller picks an even size instead. A GIF's
  // palette indices have no chroma planes: any size.
  if (common::needs_even_size(settings.format) &&
      (settings.width % 2 != 0 || settings.height % 2 != 0)) {
    return std::string("width and height must be even for ") +
           (settings.format == VideoFormat::mp4 ? "H.264" : "VP9") + " yuv420p video (got " + size +
           ")";
  }
  if (settings.fps <= 0) return "fps must be positive (got " + std::to_string(settings.fps) + ")";
  if (settings.crf < 0 || settings.crf > 51) {
    return "crf must be in 0..51 (got " + std::to_string(settings.crf) + ")";
  }
  if (settings.vp9_crf < 0 || settings.vp9_crf > 63) {
    return "vp9_crf must be in 0..63 (got " + std::to_string(settings.vp9_crf) + ")";
  }
  if (settings.alpha && !common::carries_alpha(settings.format)) {
    return std::string("only WebM carries alpha (got ") + video_format_name(settings.format) + ")";
  }
  if (settings.segment && !common::joins_in_segments(settings.format)) {
    return std::string("only MP4 and WebM are written in segments to join (got ") +
           video_format_name(settings.format) + ")";
  }
  if (settings.first_frame < 0 || (settings.first_frame > 0 && !settings.segment)) {
    return "first_frame must be 0, or a segment's first frame (got " +
           std::to_string(settings.first_frame) + ")";
  }
  if (settings.gif_fps < 0 || settings.gif_colors < common::kMinGifColors ||
      settings.gif_colors > common::kMaxGifColors) {
    return "gif_fps must be 0 or more and gif_colors in 2..256 (got " +
           std::to_string(settings.gif_fps) + " and " + std::to_string(settings.gif_colors) + ")";
  }
  if (settings.threads < 1) {
    return "threads must be at least 1 (got " + std::to_string(settings.threads) + ")";
  }
  return {};
}

// The video frame nearest GIF frame j's time j n / 100 s, at `fps`: round(j n fps / 100).
long long nearest_video_frame(long long j, int n, int fps) {
  return (2 * j * n * fps + 100) / 200;
}

}  // namespace

int gif_delay_centiseconds(int fps) {
  return std::max(2, (100 + fps - 1) / fps);
}

struct VideoEncoder::State {
  std::string path;            // where the finished video appears
  std::string temporary_path;  // "<path>.partial-<pid>.<format>" beside it, until finish()
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

  // GIF only. The palette needs every frame before the first can be mapped onto it, so frames
  // go to palettegen as they come and wait, as raw RGB, in a file beside the video (not in
  // memory: 10 s at 720p and 25 fps is 700 MB), until finish() maps and encodes them.
  int gif_delay = 0;         // centiseconds per GIF frame
  long long gif_frames = 0;  // GIF frames taken so far
  av::FilterGraph palette_stats;
  av::Frame rgb;           // rgb24, reused for every GIF frame
  std::string spool_path;  // "<path>.partial-<pid>.frames"
  std::FILE* spool = nullptr;

  ~State() {
    close_file();
    avformat_free_context(format);
  }

  std::string fail(const std::string& call, int code) {
    if (error.empty()) error = path + ": " + call + ": " + av::error_text(code);
    return error;
  }

  void close_file() {
    if (format && format->pb) avio_closep(&format->pb);
    if (!finished) std::remove(temporary_path.c_str());
    if (spool) {
      std::fclose(spool);
      spool = nullptr;
      std::remove(spool_path.c_str());
    }
  }

  std::string set_up_codec();
  std::string set_up_conversion();
  std::string set_up_gif();
  std::string open_file();
  std::string encode(const AVFrame* input);
  std::string take_gif_frame(const Image& image);
  std::string max_colors_option() const;
  std::string dither_options() const;
  std::string encode_gif_frames();
};

std::string VideoEncoder::State::set_up_codec() {
  const VideoFormat kind = settings.format;
  const char* encoder_name = kind == VideoFormat::mp4    ? "libx264"
                             : kind == VideoFormat::webm ? "libvpx-vp9"
                                                         : "gif";
  const AVCodec* encoder = avcodec_find_encoder_by_name(encoder_name);
  if (!encoder) {
    return error =
               path + ": avcodec_find_encoder_by_name: FFmpeg has no " + encoder_name + " encoder";
  }
  // "file:" first: FFmpeg reads a path with a colon ("renders:day2/x.mp4", "pipe:1") as a
  // protocol name, which a file name must never become. The muxer reopens this URL to move the
  // index to the front, so it is spelt the same way here and in avio_open.
  int code = avformat_alloc_output_context2(&format, nullptr, video_format_name(kind),
                                            ("file:" + temporary_path).c_str());
  if (code < 0) return fail("avformat_alloc_output_context2", code);
  // No wall-clock creation time and no library version tag in the file: same frames, same bytes.
  format->flags |= AVFMT_FLAG_BITEXACT;
  stream = avformat_new_stream(format, nullptr);
  if (!stream) return fail("avformat_new_stream", AVERROR(ENOMEM));

  codec.reset(avcodec_alloc_context3(encoder));
  if (!codec) return fail("avcodec_alloc_context3", AVERROR(ENOMEM));
  codec->width = settings.width;
  codec->height = settings.height;
  codec->thread_count = settings.threads;
  codec->flags |= AV_CODEC_FLAG_BITEXACT;
  if (kind == VideoFormat::gif) {
    codec->pix_fmt = AV_PIX_FMT_PAL8;
    codec->time_base = AVRational{1, 100};  // GIF's own unit of delay
    gif_delay = gif_delay_centiseconds(
        settings.gif_fps > 0 ? std::min(settings.gif_fps, settings.fps) : settings.fps);
    codec->framerate = AVRational{100, gif_delay};
    code = avcodec_open2(codec.get(), encoder, nullptr);
    if (code < 0) return fail("avcodec_open2(gif)", code);
    code = avcodec_parameters_from_context(stream->codecpar, codec.get());
    if (code < 0) return fail("avcodec_parameters_from_context", code);
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = codec->framerate;
    return {};
  }
  codec->pix_fmt = settings.alpha ? AV_PIX_FMT_YUVA420P : AV_PIX_FMT_YUV420P;
  codec->time_base = AVRational{1, settings.fps};  // one tick per frame: constant frame rate
  codec->framerate = AVRational{settings.fps, 1};
  // BT.709 (HD) limited range is what players assume for untagged HD H.264; tag it as well so
  // that nothing has to guess, and set_up_conversion() converts with the same matrix.
  codec->color_primaries = AVCOL_PRI_BT709;
  codec->color_trc = AVCOL_TRC_BT709;
  codec->colorspace = AVCOL_SPC_BT709;
  codec->color_range = AVCOL_RANGE_MPEG;
  // (AV_CODEC_FLAG_BITEXACT above asks libavcodec encoders to leave out version strings; libx264
  // writes the same bytes either way: its own SEI names core 164 and its options, constant on one
  // machine.)
  // MP4 keeps SPS/PPS once in the sample description (avcC), not in front of every keyframe.
  if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if (kind == VideoFormat::mp4) {
    code = av_opt_set(codec->priv_data, "preset", settings.preset.c_str(), 0);
    if (code < 0) return fail("av_opt_set(preset=" + settings.preset + ")", code);
    code = av_opt_set_double(codec->priv_data, "crf", settings.crf, 0);
    if (code < 0) return fail("av_opt_set(crf)", code);
    if (settings.segment) {
      code = av_opt_set(codec->priv_data, "x264-params", "stitchable=1", 0);
      if (code < 0) return fail("av_opt_set(x264-params=stitchable=1)", code);
    }
  } else {
    // Constant quality with no bitrate cap (bit_rate 0), libvpx's "good" deadline at speed 5,
    // its fastest there (on a 720p test pattern 42 frames/s against speed 1's 21, the file 11%
    // larger), and no row threads: one thread, the same bytes every run.
    codec->bit_rate = 0;
    code = av_opt_set_int(codec->priv_data, "crf", settings.vp9_crf, 0);
    if (code >= 0) code = av_opt_set(codec->priv_data, "deadline", "good", 0);
    if (code >= 0) code = av_opt_set_int(codec->priv_data, "cpu-used", 5, 0);
    if (code >= 0) code = av_opt_set_int(codec->priv_data, "row-mt", 0, 0);
    if (code < 0) return fail("av_opt_set(libvpx-vp9 crf, deadline, cpu-used, row-mt)", code);
  }
  code = avcodec_open2(codec.get(), encoder, nullptr);
  if (code < 0) {
    const std::string quality =
        kind == VideoFormat::mp4
            ? "preset " + settings.preset + ", crf " + std::to_string(settings.crf)
            : "crf " + std::to_string(settings.vp9_crf);
    return fail(std::string("avcodec_open2(") + encoder_name + ", " + quality + ")", code);
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
  // With alpha the first three planes are the same yuv420p; the fourth is copied from the image.
  frame->format = settings.alpha ? AV_PIX_FMT_YUVA420P : AV_PIX_FMT_YUV420P;
  frame->width = width;
  frame->height = height;
  if (const int code = av_frame_get_buffer(frame.get(), 0); code < 0) {
    return fail("av_frame_get_buffer", code);
  }
  packet.reset(av_packet_alloc());
  if (!packet) return fail("av_packet_alloc", AVERROR(ENOMEM));
  return {};
}

std::string VideoEncoder::State::set_up_gif() {
  // One palette for the whole video, from every pixel of every frame: a palette per frame would
  // shift the colours of a still background from frame to frame.
  const std::string rgb_source = "video_size=" + size_text(settings.width, settings.height) +
                                 ":pix_fmt=rgb24:time_base=1/100:pixel_aspect=1/1";
  if (std::string failure = palette_stats.build(
          "[in0]palettegen=stats_mode=full" + max_colors_option() + "[out]", {rgb_source});
      !failure.empty()) {
    return error = path + ": " + failure;
  }
  rgb.reset(av_frame_alloc());
  if (!rgb) return fail("av_frame_alloc", AVERROR(ENOMEM));
  rgb->format = AV_PIX_FMT_RGB24;
  rgb->width = settings.width;
  rgb->height = settings.height;
  if (const int code = av_frame_get_buffer(rgb.get(), 0); code < 0) {
    return fail("av_frame_get_buffer", code);
  }
  packet.reset(av_packet_alloc());
  if (!packet) return fail("av_packet_alloc", AVERROR(ENOMEM));
  spool_path = path + ".partial-" + std::to_string(::getpid()) + ".frames";
  spool = std::fopen(spool_path.c_str(), "w+b");
  if (!spool) return fail("fopen(" + spool_path + ")", AVERROR(errno));
  return {};
}

std::string VideoEncoder::State::open_file() {
  int code = avio_open(&format->pb, format->url, AVIO_FLAG_WRITE);
  if (code < 0) return fail("avio_open(" + temporary_path + ")", code);
  AVDictionary* options = nullptr;
  if (settings.format == VideoFormat::mp4) {
    // faststart: after the last frame the muxer moves the index (moov) in front of the media
    // data (mdat), so a player or browser can start before it has the whole file.
    av_dict_set(&options, "movflags", "+faststart", 0);
  } else if (settings.format == VideoFormat::gif) {
    av_dict_set(&options, "loop", settings.loop ? "0" : "-1", 0);  // 0: forever; -1: once
  }
  code = avformat_write_header(format, &options);
  const int unused_options = av_dict_count(options);
  av_dict_free(&options);
  if (code < 0) return fail("avformat_write_header", code);
  if (unused_options != 0) return fail("avformat_write_header(options)", AVERROR_OPTION_NOT_FOUND);
  return {};
}

// The GIF frames this video frame stands for (none or one: a GIF runs no faster than the video):
// to palettegen, and to the spool until finish().
std::string VideoEncoder::State::take_gif_frame(const Image& image) {
  while (nearest_video_frame(gif_frames, gif_delay, settings.fps) == frames_added) {
    int code = av_frame_make_writable(rgb.get());
    if (code < 0) return fail("av_frame_make_writable", code);
    for (int y = 0; y < image.height; ++y) {
      std::memcpy(rgb->data[0] + static_cast<std::ptrdiff_t>(y) * rgb->linesize[0], image.row(y),
                  image.row_bytes());
    }
    rgb->pts = gif_frames * gif_delay;
    if (std::string failure = palette_stats.push(0, rgb.get()); !failure.empty()) {
      return error = path + ": " + failure;
    }
    if (std::fwrite(image.rgb.data(), 1, image.rgb.size(), spool) != image.rgb.size()) {
      return fail("fwrite(" + spool_path + ")", AVERROR(errno));
    }
    ++gif_frames;
  }
  return {};
}

// palettegen's colour count: none at 256, its default, so the filter text (and the bytes) of a
// scene without gif_colors stay as they were. palettegen keeps one of them for transparency.
std::string VideoEncoder::State::max_colors_option() const {
  if (settings.gif_colors == 256) return {};
  return ":max_colors=" + std::to_string(settings.gif_colors);
}

// Ordered (Bayer) dithering by default: a still area keeps its pattern from frame to frame,
// where error diffusion's patterns crawl whenever anything in the frame moves, and smooth
// gradients (the sky, a lit face) show no bands. Scale 3 of 0..5: a fine pattern that still
// breaks the bands.
std::string VideoEncoder::State::dither_options() const {
  const std::string name = common::gif_dither_name(settings.gif_dither);
  return "dither=" + name +
         (settings.gif_dither == common::GifDither::bayer ? ":bayer_scale=3" : "");
}

// Every spooled frame mapped onto the video's palette and encoded, in order.
std::string VideoEncoder::State::encode_gif_frames() {
  if (std::string failure = palette_stats.push(0, nullptr); !failure.empty()) {
    return error = path + ": " + failure;
  }
  av::Frame palette(av_frame_alloc());
  if (!palette) return fail("av_frame_alloc", AVERROR(ENOMEM));
  if (const int got = palette_stats.pull(palette.get()); got != 1) {
    return fail("av_buffersink_get_frame(palettegen)", got < 0 ? got : AVERROR_BUG);
  }
  // Only the changed rectangle of each frame is mapped again (diff_mode=rectangle).
  av::FilterGraph mapping;
  const std::string rgb_source = "video_size=" + size_text(settings.width, settings.height) +
                                 ":pix_fmt=rgb24:time_base=1/100:pixel_aspect=1/1";
  const std::string palette_source =
      "video_size=16x16:pix_fmt=" +
      std::string(av_get_pix_fmt_name(static_cast<AVPixelFormat>(palette->format))) +
      ":time_base=1/100:pixel_aspect=1/1";
  std::string failure =
      mapping.build("[in0][in1]paletteuse=" + dither_options() + ":diff_mode=rectangle[out]",
                    {rgb_source, palette_source});
  if (failure.empty()) failure = mapping.push(1, palette.get());
  if (failure.empty()) failure = mapping.push(1, nullptr);
  if (!failure.empty()) return error = path + ": " + failure;
  if (std::fflush(spool) != 0 || std::fseek(spool, 0, SEEK_SET) != 0) {
    return fail("fseek(" + spool_path + ")", AVERROR(errno));
  }
  av::Frame mapped(av_frame_alloc());
  if (!mapped) return fail("av_frame_alloc", AVERROR(ENOMEM));
  const auto drain = [&]() -> std::string {
    for (;;) {
      const int got = mapping.pull(mapped.get());
      if (got < 0) return fail("av_buffersink_get_frame(paletteuse)", got);
      if (got == 0) return {};
      std::string failure = encode(mapped.get());
      av_frame_unref(mapped.get());
      if (!failure.empty()) return failure;
    }
  };
  const std::size_t frame_bytes = static_cast<std::size_t>(settings.width) * settings.height * 3;
  std::vector<std::uint8_t> row_major(frame_bytes);
  for (long long j = 0; j < gif_frames; ++j) {
    if (std::fread(row_major.data(), 1, frame_bytes, spool) != frame_bytes) {
      return fail("fread(" + spool_path + ")", AVERROR(std::ferror(spool) ? errno : EIO));
    }
    int code = av_frame_make_writable(rgb.get());
    if (code < 0) return fail("av_frame_make_writable", code);
    const std::size_t row_bytes = static_cast<std::size_t>(settings.width) * 3;
    for (int y = 0; y < settings.height; ++y) {
      std::memcpy(rgb->data[0] + static_cast<std::ptrdiff_t>(y) * rgb->linesize[0],
                  row_major.data() + static_cast<std::size_t>(y) * row_bytes, row_bytes);
    }
    rgb->pts = j * gif_delay;
    if (failure = mapping.push(0, rgb.get()); !failure.empty())
      return error = path + ": " + failure;
    if (failure = drain(); !failure.empty()) return failure;
  }
  if (failure = mapping.push(0, nullptr); !failure.empty()) return error = path + ": " + failure;
  return drain();
}

std::string VideoEncoder::State::encode(const AVFrame* input) {
  int code = avcodec_send_frame(codec.get(), input);
  if (code < 0) return fail(input ? "avcodec_send_frame" : "avcodec_send_frame(flush)", code);
  for (;;) {
    code = avcodec_receive_packet(codec.get(), packet.get());
    if (code == AVERROR(EAGAIN) || code == AVERROR_EOF) return {};
    if (code < 0) return fail("avcodec_receive_packet", code);
    if (settings.format == VideoFormat::gif) packet->duration = gif_delay;  // the last one's too
    av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    code = av_interleaved_write_frame(format, packet.get());  // takes the packet's data
    if (code < 0) return fail("av_interleaved_write_frame", code);
  }
}

VideoEncoder::VideoEncoder(std::unique_ptr<State> state) : state_(std::move(state)) {}

VideoEncoder::~VideoEncoder() = default;

Result<std::unique_ptr<VideoEncoder>> VideoEncoder::open(const std::string& path,
                                                         const VideoSettings& settings) {
  std::string error = invalid_settings(settings);
  if (!error.empty()) return Error{path + ": " + error};
  av_log_set_level(AV_LOG_ERROR);  // libav and x264 chatter (stats, warnings) stays off stderr

  auto state = std::make_unique<State>();
  state->path = path;
  // Beside the target so the final rename stays on one file system; ends in the format's
  // extension for clarity.
  state->temporary_path =
      path + ".partial-" + std::to_string(::getpid()) + "." + video_format_name(settings.format);
  state->settings = settings;
  error = state->set_up_codec();
  if (error.empty()) {
    error = settings.format == VideoFormat::gif ? state->set_up_gif() : state->set_up_conversion();
  }
  if (error.empty()) error = state->open_file();
  if (!error.empty()) return Error{error};  // ~State removes anything written
  return std::unique_ptr<VideoEncoder>(new VideoEncoder(std::move(state)));
}

Result<void> VideoEncoder::add_frame(const Image& image) {
  State& state = *state_;
  if (!state.error.empty()) return Error{state.error};
  if (state.finished) return Error{state.path + ": add_frame after finish()"};
  const int width = state.settings.width;
  const int height = state.settings.height;
  if (image.width != width || image.height != height ||
      image.rgb.size() != static_cast<std::size_t>(width) * height * 3) {
    return Error{state.path + ": frame " + std::to_string(state.frames_added) + " is " +
                 size_text(image.width, image.height) + ", the video is " +
                 size_text(width, height)};
  }
  if (state.settings.format == VideoFormat::gif) {
    if (std::string failure = state.take_gif_frame(image); !failure.empty()) return Error{failure};
    ++state.frames_added;
    return Result<void>::success();
  }
  // The encoder may still hold a reference to the previous picture in this frame's buffers.
  int code = av_frame_make_writable(state.frame.get());
  if (code < 0) return Error{state.fail("av_frame_make_writable", code)};
  const std::uint8_t* const source[] = {image.rgb.data()};
  const int source_stride[] = {static_cast<int>(image.row_bytes())};
  code = sws_scale(state.rgb_to_yuv.get(), source, source_stride, 0, height, state.frame->data,
                   state.frame->linesize);
  if (code < 0) return Error{state.fail("sws_scale", code)};
  if (state.settings.alpha) {
    if (image.alpha.size() != static_cast<std::size_t>(width) * height) {
      return Error{state.path + ": frame " + std::to_string(state.frames_added) +
                   " has no alpha, and the video was opened for alpha"};
    }
    for (int y = 0; y < height; ++y) {
      std::copy_n(image.alpha.data() + static_cast<std::size_t>(y) * width, width,
                  state.frame->data[3] + static_cast<std::ptrdiff_t>(y) * state.frame->linesize[3]);
    }
  }
  state.frame->pts = state.settings.first_frame + state.frames_added;  // codec->time_base: 1/fps
  if (std::string failure = state.encode(state.frame.get()); !failure.empty())
    return Error{failure};
  ++state.frames_added;
  return Result<void>::success();
}

Result<void> VideoEncoder::finish() {
  State& state = *state_;
  if (state.finished) return Result<void>::success();
  std::string failure = state.error;
  if (failure.empty() && state.frames_added == 0) {
    failure = state.error = state.path + ": no frames were added";
  }
  if (failure.empty() && state.settings.format == VideoFormat::gif) {
    failure = state.encode_gif_frames();
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
    if (const int errno_value = av::sync_to_disk(state.temporary_path); errno_value != 0) {
      failure = state.fail("fsync(" + state.temporary_path + ")", AVERROR(errno_value));
    }
  }
  if (failure.empty() && std::rename(state.temporary_path.c_str(), state.path.c_str()) != 0) {
    failure = state.fail("rename(" + state.temporary_path + ")", AVERROR(errno));
  }
  if (!failure.empty()) {
    state.close_file();
    return Error{failure};
  }
  state.finished = true;
  return Result<void>::success();
}

int VideoEncoder::frames_added() const {
  return state_->frames_added;
}

const std::string& VideoEncoder::path() const {
  return state_->path;
}

}  // namespace tumble::io
