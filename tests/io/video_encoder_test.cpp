#include "io/video_encoder.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include "support/result_text.hpp"
#include "support/test_frames.hpp"
#include "support/video_reader.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libswscale/swscale.h>
}

namespace tumble::io {
namespace {

using testing::DecodedVideo;
using testing::moving_pattern;
using testing::read_video;
using testing::rms_difference;

namespace fs = std::filesystem;

constexpr int kWidth = 160;
constexpr int kHeight = 120;
constexpr int kFps = 30;
constexpr int kFrames = 30;  // one second

Image solid(int width, int height, std::array<std::uint8_t, 3> colour) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = colour[i % 3];
  return image;
}

VideoSettings small_settings() {
  return {.width = kWidth, .height = kHeight, .fps = kFps};
}

// Encodes `frames` in order; returns the first error, "" on success.
std::string encode(const std::string& path, const VideoSettings& settings,
                   const std::vector<Image>& frames) {
  std::string error;
  std::unique_ptr<VideoEncoder> encoder =
      ::tumble::testing::value_or_empty(VideoEncoder::open(path, settings), error);
  if (!encoder) return error;
  for (const Image& frame : frames) {
    error = ::tumble::testing::error_text(encoder->add_frame(frame));
    if (!error.empty()) return error;
  }
  return ::tumble::testing::error_text(encoder->finish());
}

std::vector<Image> moving_frames() {
  std::vector<Image> frames;
  for (int k = 0; k < kFrames; ++k) frames.push_back(moving_pattern(kWidth, kHeight, k));
  return frames;
}

std::vector<char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Mp4Box {
  std::string type;
  std::uint64_t offset = 0;  // bytes from the start of the file
  std::uint64_t size = 0;    // bytes, header included
};

// Top-level ISO BMFF boxes: 4-byte big-endian size (1 = 64-bit size follows, 0 = to end of file)
// then a 4-character type. Stops at the first box that does not fit the file.
std::vector<Mp4Box> top_level_boxes(const std::vector<char>& bytes) {
  auto big_endian = [&](std::uint64_t at, int count) {
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i) value = (value << 8) | static_cast<std::uint8_t>(bytes[at + i]);
    return value;
  };
  std::vector<Mp4Box> boxes;
  std::uint64_t offset = 0;
  while (offset + 8 <= bytes.size()) {
    Mp4Box box{.type = std::string(bytes.data() + offset + 4, 4), .offset = offset};
    box.size = big_endian(offset, 4);
    if (box.size == 1 && offset + 16 <= bytes.size()) box.size = big_endian(offset + 8, 8);
    if (box.size == 0) box.size = bytes.size() - offset;
    if (box.size < 8 || offset + box.size > bytes.size()) break;
    boxes.push_back(box);
    offset += box.size;
  }
  return boxes;
}

// Mean absolute difference per channel (code values 0..255).
std::array<double, 3> mean_absolute_error(const Image& a, const Image& b) {
  std::array<double, 3> sum{};
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum[i % 3] += std::abs(a.rgb[i] - b.rgb[i]);
  const double pixels = static_cast<double>(a.width) * a.height;
  return {sum[0] / pixels, sum[1] / pixels, sum[2] / pixels};
}

// BT.709 limited-range code values of a full-range RGB colour (ITU-R BT.709-6, items 3.2-3.5).
std::array<double, 3> bt709_limited_yuv(std::array<std::uint8_t, 3> rgb) {
  const double kr = 0.2126, kb = 0.0722;
  const double r = rgb[0] / 255.0, g = rgb[1] / 255.0, b = rgb[2] / 255.0;
  const double luma = kr * r + (1 - kr - kb) * g + kb * b;
  return {16 + 219 * luma, 128 + 224 * (b - luma) / (2 * (1 - kb)),
          128 + 224 * (r - luma) / (2 * (1 - kr))};
}

class VideoEncoderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    directory_ =
        fs::temp_directory_path() / ("tumble-video-" + std::to_string(::getpid()) + "-" + test);
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  std::string path(const std::string& name) const { return (directory_ / name).string(); }

  std::vector<std::string> directory_listing() const {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory_)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

  fs::path directory_;
};

TEST_F(VideoEncoderTest, WritesH264Yuv420pAtTheRequestedSizeRateAndDuration) {
  const std::string out = path("moving.mp4");
  ASSERT_EQ(encode(out, small_settings(), moving_frames()), "");
  const DecodedVideo video = read_video(out);
  ASSERT_EQ(video.error, "");
  EXPECT_EQ(video.codec, AV_CODEC_ID_H264);
  EXPECT_EQ(video.stream_pixel_format, AV_PIX_FMT_YUV420P);
  EXPECT_EQ(video.width, kWidth);
  EXPECT_EQ(video.height, kHeight);
  EXPECT_EQ(av_cmp_q(video.avg_frame_rate, AVRational{kFps, 1}), 0)
      << video.avg_frame_rate.num << "/" << video.avg_frame_rate.den;
  EXPECT_EQ(av_cmp_q(video.r_frame_rate, AVRational{kFps, 1}), 0)
      << video.r_frame_rate.num << "/" << video.r_frame_rate.den;
  // Half a frame: a last frame without a duration would show as 29/30 s.
  EXPECT_NEAR(video.duration, 1.0, 0.5 / kFps);
  EXPECT_EQ(directory_listing(), std::vector<std::string>{"moving.mp4"});  // no temporary left
}

// FFmpeg reads a relative path whose first part has a colon as protocol:rest ("renders:" would
// be unknown, "pipe:1" would write to standard output): to tumble a path is always a file.
TEST_F(VideoEncoderTest, ARelativePathWithAColonIsAFile) {
  fs::create_directories(directory_ / "renders:day2");
  const fs::path before = fs::current_path();
  fs::current_path(directory_);
  const std::string error = encode("renders:day2/moving.mp4", small_settings(), moving_frames());
  fs::current_path(before);
  ASSERT_EQ(error, "");
  EXPECT_EQ(read_video(path("renders:day2/moving.mp4")).error, "");
}

TEST_F(VideoEncoderTest, DecodesOneFramePerAddedFrameAtTimeKOverFps) {
  const std::string out = path("moving.mp4");
  ASSERT_EQ(encode(out, small_settings(), moving_frames()), "");
  const DecodedVideo video = read_video(out);
  ASSERT_EQ(video.error, "");
  ASSERT_EQ(video.pictures.size(), static_cast<std::size_t>(kFrames));
  for (int k = 0; k < kFrames; ++k) {
    EXPECT_NEAR(video.pictures[k].time, static_cast<double>(k) / kFps, 1e-9) << "frame " << k;
    EXPECT_EQ(video.pictures[k].pixel_format, AV_PIX_FMT_YUV420P) << "frame " << k;
  }
}

TEST_F(VideoEncoderTest, TagsBt709LimitedRangeInContainerAndBitstream) {
  const std::string out = path("moving.mp4");
  ASSERT_EQ(encode(out, small_settings(), moving_frames()), "");
  const DecodedVideo video = read_video(out);
  ASSERT_EQ(video.error, "");
  EXPECT_EQ(video.primaries, AVCOL_PRI_BT709);
  EXPECT_EQ(video.transfer, AVCOL_TRC_BT709);
  EXPECT_EQ(video.space, AVCOL_SPC_BT709);
  EXPECT_EQ(video.range, AVCOL_RANGE_MPEG);
  ASSERT_FALSE(video.pictures.empty());
  const DecodedVideo::Picture& first = video.pictures.front();
  EXPECT_EQ(first.primaries, AVCOL_PRI_BT709);
  EXPECT_EQ(first.transfer, AVCOL_TRC_BT709);
  EXPECT_EQ(first.space, AVCOL_SPC_BT709);
  EXPECT_EQ(first.range, AVCOL_RANGE_MPEG);
}

TEST_F(VideoEncoderTest, ConvertsRgbWithTheBt709MatrixIntoLimitedRange) {
  // Red separates the matrices (BT.601 would give Y = 81.5, BT.709 gives 62.6); white separates
  // the ranges (full range would give Y = 255, limited gives 235).
  const std::vector<std::array<std::uint8_t, 3>> colours = {
      {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {40, 90, 200}};
  std::vector<Image> frames;
  for (const auto& colour : colours) frames.push_back(solid(kWidth, kHeight, colour));
  const std::string out = path("solid.mp4");
  ASSERT_EQ(encode(out, small_settings(), frames), "");
  const DecodedVideo video = read_video(out);
  ASSERT_EQ(video.error, "");
  ASSERT_EQ(video.pictures.size(), colours.size());
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const std::array<double, 3> expected = bt709_limited_yuv(colours[i]);
    for (int plane = 0; plane < 3; ++plane) {
      EXPECT_NEAR(video.pictures[i].mean_yuv[plane], expected[plane], 1.0)
          << "colour " << i << ", plane " << plane;
    }
  }
}

TEST_F(VideoEncoderTest, PutsTheMoovIndexBeforeTheMediaData) {
  const std::string out = path("moving.mp4");
  ASSERT_EQ(encode(out, small_settings(), moving_frames()), "");
  const std::vector<char> bytes = file_bytes(out);
  const std::vector<Mp4Box> boxes = top_level_boxes(bytes);
  ASSERT_FALSE(boxes.empty());
  EXPECT_EQ(boxes.front().type, "ftyp");
  EXPECT_EQ(boxes.back().offset + boxes.back().size, bytes.size());  // every byte in a box
  std::string order;
  for (const Mp4Box& box : boxes) order += box.type + " ";
  const std::size_t moov = order.find("moov");
  const std::size_t mdat = order.find("mdat");
  ASSERT_NE(moov, std::string::npos) << order;
  ASSERT_NE(mdat, std::string::npos) << order;
  EXPECT_LT(moov, mdat) << order;
}

TEST_F(VideoEncoderTest, DecodedFramesStayCloseToTheSource) {
  const std::vector<Image> frames = moving_frames();
  const std::string out = path("moving.mp4");
  ASSERT_EQ(encode(out, small_settings(), frames), "");
  const DecodedVideo video = read_video(out);
  ASSERT_EQ(video.error, "");
  ASSERT_EQ(video.pictures.size(), frames.size());
  // Measured 0.7 to 1.8 per channel at crf 18 (0.2 to 0.5 at crf 0, which is only the 4:2:0
  // chroma and 8-bit rounding; up to 3.6 at crf 30).
  const double tolerance = 2.0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const std::array<double, 3> error = mean_absolute_error(video.pictures[k].rgb, frames[k]);
    for (int channel = 0; channel < 3; ++channel) {
      EXPECT_LT(error[channel], tolerance) << "frame " << k << ", channel " << channel;
    }
  }
  // The pattern moves, so a shifted frame is measurably different: the check above has teeth.
  const std::array<double, 3> shifted = mean_absolute_error(video.pictures[0].rgb, frames[5]);
  EXPECT_GT(shifted[0], 2 * tolerance);
}

TEST_F(VideoEncoderTest, SameFramesAndSettingsGiveIdenticalBytes) {
  const std::vector<Image> frames = moving_frames();
  const std::string first = path("first.mp4");
  ASSERT_EQ(encode(first, small_settings(), frames), "");
  const std::vector<char> first_bytes = file_bytes(first);
  EXPECT_GT(first_bytes.size(), 1000u);
  // A wall-clock timestamp in the file would differ between encodes a second apart; a dependence
  // on thread timing shows up only in some runs, hence several.
  ::sleep(1);
  for (int run = 1; run <= 3; ++run) {
    const std::string again = path("again" + std::to_string(run) + ".mp4");
    ASSERT_EQ(encode(again, small_settings(), frames), "");
    EXPECT_TRUE(first_bytes == file_bytes(again)) << "run " << run;
  }
}

TEST_F(VideoEncoderTest, RejectsOddWidthOrHeight) {
  for (const auto& [width, height] : {std::pair{161, 120}, std::pair{160, 119}}) {
    const std::string out = path("odd.mp4");
    std::string error;
    const auto encoder = ::tumble::testing::value_or_empty(
        VideoEncoder::open(out, {.width = width, .height = height, .fps = kFps}), error);
    EXPECT_EQ(encoder, nullptr);
    EXPECT_EQ(error, out + ": width and height must be even for H.264 yuv420p video (got " +
                         std::to_string(width) + "x" + std::to_string(height) + ")");
  }
  EXPECT_TRUE(directory_listing().empty());
}

TEST_F(VideoEncoderTest, RejectsAFrameOfTheWrongSizeAndKeepsGoing) {
  const std::string out = path("sized.mp4");
  std::string error;
  const auto encoder =
      ::tumble::testing::value_or_empty(VideoEncoder::open(out, small_settings()), error);
  ASSERT_NE(encoder, nullptr) << error;
  EXPECT_EQ(::tumble::testing::error_text(encoder->add_frame(moving_pattern(kHeight, kWidth, 0))),
            out + ": frame 0 is 120x160, the video is 160x120");
  EXPECT_EQ(encoder->frames_added(), 0);
  EXPECT_EQ(::tumble::testing::error_text(encoder->add_frame(moving_pattern(kWidth, kHeight, 0))),
            "");
  EXPECT_EQ(::tumble::testing::error_text(encoder->add_frame(moving_pattern(kWidth, kHeight, 1))),
            "");
  ASSERT_EQ(::tumble::testing::error_text(encoder->finish()), "");
  EXPECT_EQ(read_video(out).pictures.size(), 2u);
}

TEST_F(VideoEncoderTest, UnwritablePathIsAnErrorAndLeavesNoFile) {
  const std::string out = path("missing/video.mp4");
  std::string error;
  const auto encoder =
      ::tumble::testing::value_or_empty(VideoEncoder::open(out, small_settings()), error);
  EXPECT_EQ(encoder, nullptr);
  EXPECT_EQ(error.rfind(out + ": avio_open(", 0), 0u) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(directory_listing().empty());
}

TEST_F(VideoEncoderTest, UnknownPresetIsAnErrorNamingTheCall) {
  const std::string out = path("preset.mp4");
  VideoSettings settings = small_settings();
  settings.preset = "warp9";
  std::string error;
  EXPECT_EQ(::tumble::testing::value_or_empty(VideoEncoder::open(out, settings), error), nullptr);
  EXPECT_EQ(error, out + ": avcodec_open2(libx264, preset warp9, crf 18): Invalid argument");
  EXPECT_TRUE(directory_listing().empty());
}

TEST_F(VideoEncoderTest, FailedRenameIsAnErrorAndLeavesNoTemporary) {
  const std::string out = path("taken.mp4");
  fs::create_directory(out);  // a directory cannot be replaced by a file
  std::string error;
  const auto encoder =
      ::tumble::testing::value_or_empty(VideoEncoder::open(out, small_settings()), error);
  ASSERT_NE(encoder, nullptr) << error;
  ASSERT_EQ(::tumble::testing::error_text(encoder->add_frame(moving_pattern(kWidth, kHeight, 0))),
            "");
  error = ::tumble::testing::error_text(encoder->finish());
  EXPECT_EQ(error.rfind(out + ": rename(", 0), 0u) << error;
  EXPECT_NE(error.find("Is a directory"), std::string::npos) << error;
  EXPECT_EQ(directory_listing(), std::vector<std::string>{"taken.mp4"});
  EXPECT_TRUE(fs::is_directory(out));
}

TEST_F(VideoEncoderTest, EncoderDestroyedWithoutFinishLeavesNoFile) {
  const std::string out = path("abandoned.mp4");
  std::string error;
  auto encoder =
      ::tumble::testing::value_or_empty(VideoEncoder::open(out, small_settings()), error);
  ASSERT_NE(encoder, nullptr) << error;
  for (int k = 0; k < 10; ++k)
    ASSERT_EQ(::tumble::testing::error_text(encoder->add_frame(moving_pattern(kWidth, kHeight, k))),
              "");
  EXPECT_FALSE(fs::exists(out));  // only the temporary exists while encoding
  EXPECT_EQ(directory_listing().size(), 1u);
  encoder.reset();
  EXPECT_TRUE(directory_listing().empty());
}

TEST_F(VideoEncoderTest, FinishingWithoutFramesIsAnErrorAndLeavesNoFile) {
  const std::string out = path("empty.mp4");
  std::string error;
  const auto encoder =
      ::tumble::testing::value_or_empty(VideoEncoder::open(out, small_settings()), error);
  ASSERT_NE(encoder, nullptr) << error;
  EXPECT_EQ(::tumble::testing::error_text(encoder->finish()), out + ": no frames were added");
  EXPECT_TRUE(directory_listing().empty());
  EXPECT_EQ(::tumble::testing::error_text(encoder->add_frame(moving_pattern(kWidth, kHeight, 0))),
            out + ": no frames were added");
}

VideoSettings settings_for(VideoFormat format, int fps = kFps) {
  return {.format = format, .width = kWidth, .height = kHeight, .fps = fps};
}

TEST_F(VideoEncoderTest, WritesVp9WebmWhoseFramesDecodeAtTheirTimesCloseToTheSource) {
  const std::vector<Image> frames = moving_frames();
  const std::string out = path("moving.webm");
  ASSERT_EQ(encode(out, settings_for(VideoFormat::webm), frames), "");
  const DecodedVideo video = read_video(out);
  ASSERT_EQ(video.error, "");
  EXPECT_EQ(video.codec, AV_CODEC_ID_VP9);
  EXPECT_EQ(video.width, kWidth);
  EXPECT_EQ(video.height, kHeight);
  EXPECT_EQ(video.space, AVCOL_SPC_BT709);
  EXPECT_EQ(video.range, AVCOL_RANGE_MPEG);
  ASSERT_EQ(video.pictures.size(), frames.size());
  // The stated bound, RMS over all channels at vp9_crf 30: measured 1.96 at most on this pattern;
  // a frame 5 steps away differs by far more, so the check can fail.
  double worst = 0.0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    EXPECT_NEAR(video.pictures[k].time, static_cast<double>(k) / kFps, 1e-3) << "frame " << k;
    EXPECT_EQ(video.pictures[k].pixel_format, AV_PIX_FMT_YUV420P);
    worst = std::max(worst, rms_difference(video.pictures[k].rgb, frames[k]));
  }
  std::printf("[ measured ] WebM frames against their sources: RMS at most %.2f\n", worst);
  EXPECT_LT(worst, 4.0);
  EXPECT_GT(rms_difference(video.pictures[0].rgb, frames[5]), 3 * 4.0);
  EXPECT_EQ(directory_listing(), std::vector<std::string>{"moving.webm"});
}

TEST_F(VideoEncoderTest, SameFramesGiveIdenticalWebmAndGifBytes) {
  const std::vector<Image> frames = moving_frames();
  for (const VideoFormat format : {VideoFormat::webm, VideoFormat::gif}) {
    const std::string extension = video_format_name(format);
    ASSERT_EQ(encode(path("first." + extension), settings_for(format), frames), "");
    ASSERT_EQ(encode(path("again." + extension), settings_for(format), frames), "");
    const std::vector<char> first = file_bytes(path("first." + extension));
    EXPECT_GT(first.size(), 1000u) << extension;
    EXPECT_TRUE(first == file_bytes(path("again." + extension))) << extension;
  }
}

TEST(GifTiming, RunsAtTheFastestWholeCentisecondRateNoFasterThanTheVideo) {
  EXPECT_EQ(gif_delay_centiseconds(60), 2);  // 50 fps: browsers slow anything under 2 cs
  EXPECT_EQ(gif_delay_centiseconds(50), 2);
  EXPECT_EQ(gif_delay_centiseconds(30), 4);  // 25 fps
  EXPECT_EQ(gif_delay_centiseconds(25), 4);
  EXPECT_EQ(gif_delay_centiseconds(24), 5);
  EXPECT_EQ(gif_delay_centiseconds(15), 7);
  EXPECT_EQ(gif_delay_centiseconds(10), 10);
  EXPECT_EQ(gif_delay_centiseconds(1), 100);
}

// What a GIF file says of its palettes, frame delays and looping, read from its blocks (GIF89a:
// header, logical screen descriptor and global colour table, then extensions and images).
struct GifBlocks {
  std::string error;
  int global_colours = 0;                 // entries of the global colour table, 0 if none
  std::string global_table;               // its bytes (r, g, b per entry)
  std::vector<std::string> local_tables;  // of the images that carry a table of their own
  int images = 0;
  std::vector<int> delays;  // centiseconds, from each graphic control extension
  int loops = -1;           // the NETSCAPE2.0 loop count (0: forever), -1 without one
};

GifBlocks read_gif_blocks(const std::vector<char>& file) {
  GifBlocks out;
  const auto byte = [&](std::size_t at) { return static_cast<std::uint8_t>(file.at(at)); };
  try {
    if (std::string(file.data(), 6) != "GIF89a") {
      out.error = "not GIF89a";
      return out;
    }
    std::size_t at = 13;
    if (byte(10) & 0x80) {
      out.global_colours = 1 << ((byte(10) & 7) + 1);
      out.global_table.assign(file.data() + at, 3 * static_cast<std::size_t>(out.global_colours));
      at += out.global_table.size();
    }
    const auto skip_sub_blocks = [&] {
      while (const std::uint8_t size = byte(at)) at += 1 + size;
      ++at;
    };
    for (;;) {
      const std::uint8_t kind = byte(at++);
      if (kind == 0x3B) return out;  // trailer
      if (kind == 0x21) {
        const std::uint8_t label = byte(at++);
        if (label == 0xF9) out.delays.push_back(byte(at + 2) | (byte(at + 3) << 8));
        if (label == 0xFF && std::string(file.data() + at + 1, 11) == "NETSCAPE2.0") {
          out.loops = byte(at + 14) | (byte(at + 15) << 8);
        }
        skip_sub_blocks();
      } else if (kind == 0x2C) {
        ++out.images;
        const std::uint8_t packed = byte(at + 8);
        at += 9;
        if (packed & 0x80) {
          const std::size_t size = 3 * (static_cast<std::size_t>(1) << ((packed & 7) + 1));
          out.local_tables.emplace_back(file.data() + at, size);
          at += size;
        }
        ++at;  // LZW minimum code size
        skip_sub_blocks();
      } else {
        out.error = "unknown block " + std::to_string(kind);
        return out;
      }
    }
  } catch (const std::out_of_range&) {
    out.error = "truncated";
  }
  return out;
}

// 30 video frames at 30 fps: a GIF at 25 fps (4 cs a frame), 25 frames, each the video frame
// nearest its time, all on one palette, looping forever.
TEST_F(VideoEncoderTest, WritesAGifOnOnePaletteAtWholeCentisecondDelays) {
  const std::vector<Image> frames = moving_frames();
  const std::string out = path("moving.gif");
  ASSERT_EQ(encode(out, settings_for(VideoFormat::gif), frames), "");
  const GifBlocks blocks = read_gif_blocks(file_bytes(out));
  ASSERT_EQ(blocks.error, "");
  EXPECT_EQ(blocks.global_colours, 256);
  // One palette for the whole video: FFmpeg's encoder repeats it as the first image's own table,
  // and no other image has one.
  EXPECT_LE(blocks.local_tables.size(), 1u);
  for (const std::string& table : blocks.local_tables) EXPECT_TRUE(table == blocks.global_table);
  EXPECT_EQ(blocks.images, 25);
  EXPECT_EQ(blocks.delays, std::vector<int>(25, 4));
  EXPECT_EQ(blocks.loops, 0);
  const DecodedVideo video = read_video(out);
  ASSERT_EQ(video.error, "");
  EXPECT_EQ(video.codec, AV_CODEC_ID_GIF);
  EXPECT_EQ(video.width, kWidth);
  EXPECT_EQ(video.height, kHeight);
  ASSERT_EQ(video.pictures.size(), 25u);
  // 256 colours and a Bayer pattern over smooth sines: measured RMS 6.2 at most against the frame
  // shown; the neighbouring frames differ by far more.
  double worst = 0.0;
  for (std::size_t j = 0; j < video.pictures.size(); ++j) {
    const double time = 0.04 * static_cast<double>(j);
    EXPECT_NEAR(video.pictures[j].time, time, 1e-9) << "GIF frame " << j;
    const auto nearest = static_cast<std::size_t>(std::lround(time * kFps));
    worst = std::max(worst, rms_difference(video.pictures[j].rgb, frames[nearest]));
  }
  std::printf("[ measured ] GIF frames against the video frames they show: RMS at most %.2f\n",
              worst);
  EXPECT_LT(worst, 8.0);
  EXPECT_GT(rms_difference(video.pictures[10].rgb, frames[20]), 2 * 8.0);  // it shows frame 12
  EXPECT_EQ(directory_listing(), std::vector<std::string>{"moving.gif"});  // spool gone too
}

TEST_F(VideoEncoderTest, GifFrom60FpsRunsAt50AndWithoutLoopPlaysOnce) {
  std::vector<Image> frames;
  for (int k = 0; k < 60; ++k) frames.push_back(moving_pattern(kWidth + 1, kHeight + 1, k));
  VideoSettings settings = settings_for(VideoFormat::gif, 60);
  settings.width = kWidth + 1;  // odd sizes are fine: no chroma planes
  settings.height = kHeight + 1;
  settings.loop = false;
  const std::string out = path("once.gif");
  ASSERT_EQ(encode(out, settings, frames), "");
  const GifBlocks blocks = read_gif_blocks(file_bytes(out));
  ASSERT_EQ(blocks.error, "");
  EXPECT_EQ(blocks.images, 50);
  EXPECT_EQ(blocks.delays, std::vector<int>(50, 2));
  EXPECT_EQ(blocks.loops, -1);
}

TEST_F(VideoEncoderTest, GifAbandonedOrEmptyLeavesNoFileAndNoSpool) {
  {
    std::string error;
    const auto encoder = ::tumble::testing::value_or_empty(
        VideoEncoder::open(path("gone.gif"), settings_for(VideoFormat::gif)), error);
    ASSERT_NE(encoder, nullptr) << error;
    ASSERT_EQ(::tumble::testing::error_text(encoder->add_frame(moving_pattern(kWidth, kHeight, 0))),
              "");
    EXPECT_EQ(directory_listing().size(), 2u);  // the partial GIF and its spool
  }
  EXPECT_TRUE(directory_listing().empty());
  std::string error;
  const auto encoder = ::tumble::testing::value_or_empty(
      VideoEncoder::open(path("empty.gif"), settings_for(VideoFormat::gif)), error);
  ASSERT_NE(encoder, nullptr) << error;
  EXPECT_EQ(::tumble::testing::error_text(encoder->finish()),
            path("empty.gif") + ": no frames were added");
  EXPECT_TRUE(directory_listing().empty());
}

}  // namespace
}  // namespace tumble::io
