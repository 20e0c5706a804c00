#include "io/video_join.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>

#include "io/av_handles.hpp"

extern "C" {
#include <libavutil/error.h>
#include <libavutil/log.h>
}

namespace tumble::io {
namespace {

using Input = std::unique_ptr<AVFormatContext, av::InputCloser>;

// Opens `path` and finds its one video stream, its index into `stream`.
Result<Input> open_input(const std::string& path, int& stream) {
  AVFormatContext* opened = nullptr;
  // "file:" first, as VideoEncoder writes: a path is never a protocol.
  if (const int code = avformat_open_input(&opened, ("file:" + path).c_str(), nullptr, nullptr);
      code < 0) {
    return Error{path + ": avformat_open_input: " + av::error_text(code)};
  }
  Input input(opened);
  if (const int code = avformat_find_stream_info(input.get(), nullptr); code < 0) {
    return Error{path + ": avformat_find_stream_info: " + av::error_text(code)};
  }
  stream = av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (stream < 0 || input->nb_streams != 1) {
    return Error{path + ": not a video of one stream"};
  }
  return input;
}

// A timestamp in the stream's time base as a frame number at `fps`.
long long frame_of(std::int64_t timestamp, AVRational time_base, int fps) {
  return av_rescale_q_rnd(timestamp, time_base, AVRational{1, fps},
                          static_cast<AVRounding>(AV_ROUND_NEAR_INF | AV_ROUND_PASS_MINMAX));
}

int whole_fps(const AVStream& stream) {
  const AVRational rate = stream.avg_frame_rate;
  return rate.den > 0 && rate.num % rate.den == 0 ? rate.num / rate.den : 0;
}

std::string codec_name(const AVCodecParameters& parameters) {
  return parameters.codec_id == AV_CODEC_ID_H264  ? "H.264"
         : parameters.codec_id == AV_CODEC_ID_VP9 ? "VP9"
                                                  : avcodec_get_name(parameters.codec_id);
}

// The output video, removed unless finished.
struct Output {
  std::string temporary;
  AVFormatContext* format = nullptr;
  bool finished = false;
  ~Output() {
    if (format && format->pb) avio_closep(&format->pb);
    avformat_free_context(format);
    if (!finished) std::remove(temporary.c_str());
  }
};

}  // namespace

Result<VideoSegmentInfo> read_segment_info(const std::string& path) {
  VideoSegmentInfo info;
  int index = 0;
  const Result<Input> opened = open_input(path, index);
  if (!opened) return Error{opened.error()};
  const Input& input = *opened;
  const AVStream& stream = *input->streams[index];
  info.width = stream.codecpar->width;
  info.height = stream.codecpar->height;
  info.fps = whole_fps(stream);
  if (info.fps == 0) return Error{path + ": not a whole number of frames per second"};
  av::Packet packet(av_packet_alloc());
  long long lowest = std::numeric_limits<long long>::max();
  long long highest = std::numeric_limits<long long>::min();
  long long first_decoded = 0;
  int code = 0;
  while ((code = av_read_frame(input.get(), packet.get())) == 0) {
    const long long frame = frame_of(packet->pts, stream.time_base, info.fps);
    if (info.frames == 0) first_decoded = frame_of(packet->dts, stream.time_base, info.fps);
    lowest = std::min(lowest, frame);
    highest = std::max(highest, frame);
    ++info.frames;
    av_packet_unref(packet.get());
  }
  if (code != AVERROR_EOF) return Error{path + ": av_read_frame: " + av::error_text(code)};
  if (info.frames == 0) return Error{path + ": holds no frames"};
  if (stream.nb_frames != 0 && stream.nb_frames != info.frames) {
    return Error{path + ": its index lists " + std::to_string(stream.nb_frames) +
                 " frames but the file holds " + std::to_string(info.frames) +
                 " (a truncated copy?)"};
  }
  if (highest - lowest + 1 != info.frames) {
    return Error{path + ": its frames are not one run of consecutive frames"};
  }
  info.first_frame = lowest;
  info.reorder_delay = info.first_frame - first_decoded;
  return info;
}

Result<void> join_videos(const std::vector<std::string>& segments, const std::string& path) {
  if (segments.empty()) return Error{path + ": no segments to join"};
  // libav's notes (the muxer's second pass, a truncated file's warnings) stay off stderr: every
  // failure comes back as a message naming the segment.
  av_log_set_level(AV_LOG_FATAL);
  // Every segment read whole and checked before anything is written.
  std::vector<VideoSegmentInfo> infos;
  for (const std::string& segment : segments) {
    Result<VideoSegmentInfo> info = read_segment_info(segment);
    if (!info) return Error{info.error()};
    infos.push_back(std::move(info).value());
  }
  std::vector<Input> inputs;
  std::vector<int> streams;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    int stream = 0;
    Result<Input> input = open_input(segments[i], stream);
    if (!input) return Error{input.error()};
    inputs.push_back(std::move(input).value());
    streams.push_back(stream);
    const AVCodecParameters& first = *inputs[0]->streams[streams[0]]->codecpar;
    const AVCodecParameters& each = *inputs[i]->streams[stream]->codecpar;
    if (each.codec_id != AV_CODEC_ID_H264 && each.codec_id != AV_CODEC_ID_VP9) {
      return Error{segments[i] + ": neither H.264 nor VP9"};
    }
    if (each.codec_id != first.codec_id) {
      return Error{segments[i] + ": is " + codec_name(each) + ", " + segments[0] + " " +
                   codec_name(first)};
    }
    if (each.width != first.width || each.height != first.height || infos[i].fps != infos[0].fps) {
      return Error{segments[i] + ": is " + std::to_string(each.width) + "x" +
                   std::to_string(each.height) + " at " + std::to_string(infos[i].fps) + " fps, " +
                   segments[0] + " " + std::to_string(first.width) + "x" +
                   std::to_string(first.height) + " at " + std::to_string(infos[0].fps) + " fps"};
    }
    // The stream headers (H.264's avcC: SPS and PPS; VP9's codec private data) must be byte for
    // byte the first segment's, or the joined file's one header would describe some of its frames
    // wrongly.
    if (each.extradata_size != first.extradata_size ||
        (first.extradata_size > 0 &&
         std::memcmp(each.extradata, first.extradata,
                     static_cast<std::size_t>(first.extradata_size)) != 0)) {
      return Error{segments[i] + ": its " + codec_name(each) + " stream headers differ from " +
                   segments[0] + "'s (other encoder settings, or not written as a segment)"};
    }
    const long long expected = i == 0 ? 0 : infos[i - 1].first_frame + infos[i - 1].frames;
    if (infos[i].first_frame != expected) {
      return Error{segments[i] + ": starts at frame " + std::to_string(infos[i].first_frame) +
                   ", where frame " + std::to_string(expected) + " comes next" +
                   (infos[i].first_frame > expected
                        ? " (frames " + std::to_string(expected) + " to " +
                              std::to_string(infos[i].first_frame - 1) + " are missing)"
                        : " (frames overlap)")};
    }
  }

  const AVStream& model = *inputs[0]->streams[streams[0]];
  const bool mp4 = model.codecpar->codec_id == AV_CODEC_ID_H264;
  const char* muxer = mp4 ? "mp4" : "webm";
  Output out;
  out.temporary = path + ".partial-" + std::to_string(::getpid()) + "." + muxer;
  const auto fail = [&](const std::string& call, int code) {
    return Error{path + ": " + call + ": " + av::error_text(code)};
  };
  int code = avformat_alloc_output_context2(&out.format, nullptr, muxer,
                                            ("file:" + out.temporary).c_str());
  if (code < 0) return Error{fail("avformat_alloc_output_context2", code)};
  out.format->flags |= AVFMT_FLAG_BITEXACT;  // as VideoEncoder: same input, same bytes
  AVStream* stream = avformat_new_stream(out.format, nullptr);
  if (!stream) return Error{fail("avformat_new_stream", AVERROR(ENOMEM))};
  code = avcodec_parameters_copy(stream->codecpar, model.codecpar);
  if (code < 0) return Error{fail("avcodec_parameters_copy", code)};
  stream->codecpar->codec_tag = 0;
  stream->time_base = AVRational{1, infos[0].fps};
  stream->avg_frame_rate = model.avg_frame_rate;
  code = avio_open(&out.format->pb, out.format->url, AVIO_FLAG_WRITE);
  if (code < 0) return Error{fail("avio_open(" + out.temporary + ")", code)};
  // A WebM with alpha says so in its track (alpha_mode 1), as VideoEncoder writes it.
  if (const AVDictionaryEntry* alpha = av_dict_get(model.metadata, "alpha_mode", nullptr, 0)) {
    av_dict_set(&stream->metadata, "alpha_mode", alpha->value, 0);
  }
  AVDictionary* options = nullptr;
  if (mp4) av_dict_set(&options, "movflags", "+faststart", 0);
  code = avformat_write_header(out.format, &options);
  av_dict_free(&options);
  if (code < 0) return Error{fail("avformat_write_header", code)};

  // Decode times: one per packet in order, led by the longest lead of any segment, so that no
  // packet is decoded after it is shown.
  long long lead = 0;
  for (const VideoSegmentInfo& info : infos) lead = std::max(lead, info.reorder_delay);
  long long decoded = -lead;  // frame times
  av::Packet packet(av_packet_alloc());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const AVStream& in = *inputs[i]->streams[streams[i]];
    while ((code = av_read_frame(inputs[i].get(), packet.get())) == 0) {
      // Presentation at its frame's exact time (a one-frame segment's edit list reads back a few
      // ticks early), decoding in one run for the whole.
      const AVRational frame_time{1, infos[0].fps};
      packet->pts = av_rescale_q(frame_of(packet->pts, in.time_base, infos[0].fps), frame_time,
                                 stream->time_base);
      packet->duration = av_rescale_q(1, frame_time, stream->time_base);
      packet->dts = av_rescale_q(decoded++, frame_time, stream->time_base);
      packet->stream_index = stream->index;
      packet->pos = -1;
      code = av_interleaved_write_frame(out.format, packet.get());
      if (code < 0) return Error{segments[i] + ": joining its packets: " + av::error_text(code)};
    }
    if (code != AVERROR_EOF) return Error{segments[i] + ": av_read_frame: " + av::error_text(code)};
  }
  if ((code = av_write_trailer(out.format)) < 0) return Error{fail("av_write_trailer", code)};
  if ((code = avio_closep(&out.format->pb)) < 0) return Error{fail("avio_closep", code)};
  if (const int errno_value = av::sync_to_disk(out.temporary); errno_value != 0) {
    return Error{fail("fsync(" + out.temporary + ")", AVERROR(errno_value))};
  }
  if (std::rename(out.temporary.c_str(), path.c_str()) != 0) {
    return Error{fail("rename(" + out.temporary + ")", AVERROR(errno))};
  }
  out.finished = true;
  return Result<void>::success();
}

}  // namespace tumble::io
