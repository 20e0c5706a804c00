// VideoDecoder's helpers for comparing a video with the pictures it was encoded from: the round
// trip through a YUV format against its closed form, and the quantiser an H.264 stream reports.
#include "io/video_decoder.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "io/video_encoder.hpp"
#include "support/result_text.hpp"
#include "support/test_frames.hpp"

extern "C" {
#include <libavutil/pixfmt.h>
#include <libswscale/swscale.h>
}

namespace tumble::io {
namespace {

namespace fs = std::filesystem;
using Colour = std::array<int, 3>;

struct LumaWeights {
  double kr, kb;
};
constexpr LumaWeights kBt601{0.299, 0.114}, kBt709{0.2126, 0.0722};

// One 8-bit colour into limited-range Y'CbCr with the weights `to` and back with `from`, by the
// formulas of ITU-R BT.601/BT.709 (BT.709-6 §3.2-3.5): E'Y = Kr E'R + Kg E'G + Kb E'B,
// Y = round(219 E'Y + 16), Cb = round(224 (E'B - E'Y) / (2 (1 - Kb)) + 128), Cr likewise; then
// inverted, rounded and clamped to 0-255.
Colour closed_form_round_trip(Colour rgb, LumaWeights to, LumaWeights from) {
  double kr = to.kr, kb = to.kb, kg = 1.0 - kr - kb;
  const double r = rgb[0] / 255.0, g = rgb[1] / 255.0, b = rgb[2] / 255.0;
  const double ey = kr * r + kg * g + kb * b;
  const double y = std::round(219.0 * ey + 16.0);
  const double cb = std::round(224.0 * (b - ey) / (2.0 * (1.0 - kb)) + 128.0);
  const double cr = std::round(224.0 * (r - ey) / (2.0 * (1.0 - kr)) + 128.0);
  kr = from.kr, kb = from.kb, kg = 1.0 - kr - kb;
  const double back_y = (y - 16.0) / 219.0;
  const double back_b = back_y + (cb - 128.0) / 224.0 * 2.0 * (1.0 - kb);
  const double back_r = back_y + (cr - 128.0) / 224.0 * 2.0 * (1.0 - kr);
  const double back_g = (back_y - kr * back_r - kb * back_b) / kg;
  Colour out{};
  const double levels[] = {back_r, back_g, back_b};
  for (int c = 0; c < 3; ++c) {
    out[c] = std::clamp(static_cast<int>(std::lround(255.0 * levels[c])), 0, 255);
  }
  return out;
}

constexpr Colour kColours[] = {{200, 60, 30}, {30, 180, 90}, {90, 90, 220},
                               {255, 0, 255}, {0, 0, 0},     {255, 255, 255}};

Image flat(Colour colour) {
  Image image(16, 16);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    image.rgb[i] = static_cast<std::uint8_t>(colour[i % 3]);
  }
  return image;
}

// A flat image has no chroma detail for 4:2:0 to lose: every pixel comes back as the closed form
// says, within one level for swscale's fixed-point arithmetic.
void expect_closed_form(int sws_matrix, LumaWeights weights) {
  const VideoPictureFormat format{AV_PIX_FMT_YUV420P, sws_matrix, false};
  for (const Colour colour : kColours) {
    const Colour expected = closed_form_round_trip(colour, weights, weights);
    const Image out = through_picture_format(flat(colour), format);
    ASSERT_EQ(out.width, 16);
    for (std::size_t i = 0; i < out.rgb.size(); ++i) {
      EXPECT_NEAR(out.rgb[i], expected[i % 3], 1)
          << "colour " << colour[0] << "," << colour[1] << "," << colour[2] << " channel " << i % 3;
    }
  }
}

TEST(VideoDecoder, AFlatColourThroughBt709IsTheClosedFormRoundTrip) {
  expect_closed_form(SWS_CS_ITU709, kBt709);
}

TEST(VideoDecoder, AFlatColourThroughBt601IsTheClosedFormRoundTrip) {
  expect_closed_form(SWS_CS_ITU601, kBt601);
}

// The tolerance of one level tells a consistent round trip from one whose matrices disagree
// (BT.709 in, BT.601 out: 12 levels off in red for the first colour).
TEST(VideoDecoder, AMismatchedMatrixWouldBeOffByMoreThanTheTolerance) {
  const Colour right = closed_form_round_trip(kColours[0], kBt709, kBt709);
  const Colour wrong = closed_form_round_trip(kColours[0], kBt709, kBt601);
  EXPECT_EQ(right, (Colour{200, 60, 30}));
  EXPECT_EQ(wrong, (Colour{188, 47, 33}));
  EXPECT_EQ(describe({AV_PIX_FMT_YUV420P, SWS_CS_ITU709, false}), "yuv420p BT.709 limited range");
}

// Writes 10 frames of a moving pattern in `format`; returns the decoder's allowance after
// reading them all.
QuantisationAllowance allowance_of(const std::string& path, VideoFormat format) {
  VideoSettings settings{.format = format, .width = 64, .height = 48, .fps = 25};
  std::string error;
  std::unique_ptr<VideoEncoder> encoder =
      ::tumble::testing::value_or_empty(VideoEncoder::open(path, settings), error);
  EXPECT_TRUE(encoder) << error;
  if (!encoder) return {};
  for (int k = 0; k < 10; ++k)
    EXPECT_EQ(::tumble::testing::error_text(encoder->add_frame(testing::moving_pattern(64, 48, k))),
              "");
  EXPECT_EQ(::tumble::testing::error_text(encoder->finish()), "");
  std::unique_ptr<VideoDecoder> decoder =
      ::tumble::testing::value_or_empty(VideoDecoder::open(path), error);
  EXPECT_TRUE(decoder) << error;
  if (!decoder) return {};
  int frames = 0;
  while (::tumble::testing::value_or_empty(decoder->next(), error)) ++frames;
  EXPECT_EQ(frames, 10);
  return decoder->quantisation_allowance();
}

TEST(VideoDecoder, AnH264VideoReportsTheStepsOfItsCoarsestQp) {
  const fs::path folder =
      fs::temp_directory_path() / ("tumble_decoder_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const QuantisationAllowance mp4 = allowance_of((folder / "v.mp4").string(), VideoFormat::mp4);
  ASSERT_TRUE(mp4.active());
  EXPECT_GE(mp4.qp, 0);
  EXPECT_LE(mp4.qp, 51);
  EXPECT_DOUBLE_EQ(mp4.luma_step, h264_quantiser_step(mp4.qp));
  // x264 at tumble's settings (veryfast) writes chroma_qp_index_offset 0.
  EXPECT_DOUBLE_EQ(mp4.chroma_step, h264_quantiser_step(h264_chroma_qp(mp4.qp, 0)));
  EXPECT_DOUBLE_EQ(mp4.kr, 0.2126);  // the BT.709 the encoder tags
  // A GIF's palette has no quantiser: no allowance.
  EXPECT_FALSE(allowance_of((folder / "v.gif").string(), VideoFormat::gif).active());
  fs::remove_all(folder);
}

}  // namespace
}  // namespace tumble::io
