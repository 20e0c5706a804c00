// Every video format of [output] formats and --format, written from the same frames in one run:
// each decodes to the run's frame count and size; a WebM frame matches its PNG; the GIF keeps
// 20 fps exactly in whole centiseconds; a transparent render gives RGBA PNGs and a WebM whose
// alpha, read by libvpx's own VP9 decoder, is 0 off the cube and 255 on it. (What the encoder
// itself guarantees, palette and timing rules, is tests/io/video_encoder_test.cpp's.)
#include "pipeline/frame_sinks.hpp"

#include <gtest/gtest.h>

#include <png.h>
#include <cstdio>

extern "C" {
#include <libswscale/swscale.h>
}

#include <cmath>
#include <set>

#include "io/png_io.hpp"
#include "io/video_decoder.hpp"
#include "support/command_test.hpp"
#include "support/render_scenes.hpp"
#include "support/result_text.hpp"
#include "support/video_reader.hpp"

namespace tumble::pipeline {
namespace {

using testing::CommandTest;
namespace fs = std::filesystem;
using testing::DecodedVideo;

class VideoSinkTest : public CommandTest {
 protected:
  std::string out(const std::string& file) const { return path("out/spin/" + file); }
  std::string frame(int k) const {
    char name[32];
    std::snprintf(name, sizeof name, "frames/frame_%05d.png", k);
    return out(name);
  }
};

double rms_difference(const io::Image& a, const io::Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = static_cast<double>(a.rgb[i]) - b.rgb[i];
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(a.rgb.size()));
}

// Ten frames (0.5 s at 20 fps) of 96 × 64 pixels.
TEST_F(VideoSinkTest, EveryFormatDecodesToTheRunsFramesAndSize) {
  const fs::path scene =
      write("spin.toml", testing::spinning_cube_scene(0.5,
                                                      "[output]\nformats = [\"mp4\", \"webm\", "
                                                      "\"gif\"]\n"));
  const testing::Outcome run = tumble("render -q " + scene.string() + " -o " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* extension : {"mp4", "webm", "gif"}) {
    const DecodedVideo video = testing::read_video(out(std::string("spin.") + extension));
    ASSERT_EQ(video.error, "") << extension;
    EXPECT_EQ(video.pictures.size(), 10u) << extension;
    EXPECT_EQ(video.width, 96) << extension;
    EXPECT_EQ(video.height, 64) << extension;
  }
  // The GIF: palette-indexed, each frame 5 cs (20 fps is exact in centiseconds), looping.
  const DecodedVideo gif = testing::read_video(out("spin.gif"));
  EXPECT_EQ(gif.codec, AV_CODEC_ID_GIF);
  std::set<std::uint32_t> colours;  // over every frame: one palette for the whole video
  for (std::size_t i = 0; i < gif.pictures.size(); ++i) {
    EXPECT_NEAR(gif.pictures[i].time, 0.05 * static_cast<double>(i), 1e-9) << i;
    const std::vector<std::uint8_t>& rgb = gif.pictures[i].rgb.rgb;
    for (std::size_t p = 0; p < rgb.size(); p += 3) {
      colours.insert(static_cast<std::uint32_t>(rgb[p] << 16 | rgb[p + 1] << 8 | rgb[p + 2]));
    }
  }
  EXPECT_LE(colours.size(), 256u);
  // VP9 at crf 30: a decoded frame is within 6 levels RMS of the PNG it was encoded from
  // (measured: 4.4 to 4.6 on these small frames, where the cube's edges are a large share of
  // the pixels).
  const DecodedVideo webm = testing::read_video(out("spin.webm"));
  EXPECT_EQ(webm.codec, AV_CODEC_ID_VP9);
  for (const int k : {0, 5, 9}) {
    io::Image png;
    ASSERT_EQ(::tumble::testing::take(io::read_png(frame(k)), png), "");
    const double rms = rms_difference(webm.pictures[static_cast<std::size_t>(k)].rgb, png);
    EXPECT_LE(rms, 6.0) << "frame " << k;
    RecordProperty("webm_rms_frame_" + std::to_string(k), std::to_string(rms));
  }
}

TEST_F(VideoSinkTest, FormatOnTheCommandLineReplacesTheScenesAndNoVideoWritesNone) {
  const fs::path scene = write("spin.toml", testing::spinning_cube_scene(0.25));
  ASSERT_EQ(tumble("render -q " + scene.string() + " -o " + path("out") +
                   " --format gif --format webm,gif")
                .exit_code,
            0);
  EXPECT_FALSE(fs::exists(out("spin.mp4")));
  EXPECT_TRUE(fs::exists(out("spin.gif")));
  EXPECT_TRUE(fs::exists(out("spin.webm")));
  const std::string report = testing::read_file(out("report.json"));
  EXPECT_NE(report.find("\"video\": null"), std::string::npos) << report;
  // In the order --format gave them, each once.
  EXPECT_NE(report.find("\"videos\": {\"gif\": \"" + out("spin.gif") + "\", \"webm\": "),
            std::string::npos)
      << report;

  // Into a folder of its own: over the render above it would keep that render's videos
  // (job/kept_files.hpp).
  ASSERT_EQ(
      tumble("render -q " + scene.string() + " -o " + path("plain") + " --no-video").exit_code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "plain/spin/report.json"));
  for (const char* extension : {"mp4", "webm", "gif"}) {
    EXPECT_FALSE(fs::exists(dir_ / "plain/spin" / (std::string("spin.") + extension))) << extension;
  }
  const testing::Outcome bad =
      tumble("render -q " + scene.string() + " -o " + path("out") + " --format avi");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(
      bad.err.find(
          "--format: unknown format \"avi\" (\"mp4\", \"webm\", \"gif\", \"gltf\" or \"html\")"),
      std::string::npos)
      << bad.err;
}

// A PNG file's samples as stored, RGBA (libpng's simplified API adds opaque alpha to RGB).
struct RgbaFile {
  bool has_alpha = false;
  int width = 0;
  std::vector<png_byte> rgba;
  int alpha_at(int x, int y) const {
    return rgba[4 * (static_cast<std::size_t>(y) * width + x) + 3];
  }
};

RgbaFile read_rgba(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  RgbaFile file;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return file;
  file.has_alpha = (image.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  file.width = static_cast<int>(image.width);
  image.format = PNG_FORMAT_RGBA;
  file.rgba.resize(PNG_IMAGE_SIZE(image));
  png_image_finish_read(&image, nullptr, file.rgba.data(), 0, nullptr);
  return file;
}

TEST_F(VideoSinkTest, TransparentBackgroundGivesAlphaInPngAndWebm) {
  const fs::path scene =
      write("spin.toml", testing::spinning_cube_scene(0.25, "[output]\nformats = [\"webm\"]\n",
                                                      "background = \"transparent\"\n"
                                                      "ambient_occlusion = 0\n"));
  const testing::Outcome run = tumble("render -q " + scene.string() + " -o " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The cube sits in the middle of the frame; the corners show nothing (no ground is drawn).
  const RgbaFile png = read_rgba(frame(2));
  ASSERT_TRUE(png.has_alpha);
  EXPECT_EQ(png.alpha_at(0, 0), 0);
  EXPECT_EQ(png.alpha_at(95, 63), 0);
  EXPECT_EQ(png.alpha_at(48, 32), 255);
  // The ground is not drawn but the cube's shadow on it is: partly transparent black, at most
  // diffuse / (ambient + diffuse) = 0.736 opaque (188 of 255) with the default light (and no
  // ambient occlusion, which would darken the fill too). Black
  // within 2 levels a channel (made straight from 8-bit values: straight_alpha.hpp); the other
  // partly transparent pixels are the cube's outline, smoothed by the edge filter.
  int shadow_pixels = 0, most_opaque = 0, outline = 0;
  for (std::size_t i = 3; i < png.rgba.size(); i += 4) {
    if (png.rgba[i] == 0 || png.rgba[i] == 255) continue;
    if (std::max({png.rgba[i - 3], png.rgba[i - 2], png.rgba[i - 1]}) > 2) {
      ++outline;
      continue;
    }
    ++shadow_pixels;
    most_opaque = std::max<int>(most_opaque, png.rgba[i]);
  }
  EXPECT_GT(shadow_pixels, 50);
  EXPECT_GT(outline, 20);
  EXPECT_NEAR(most_opaque, 188, 2);

  const DecodedVideo webm = testing::read_video(out("spin.webm"), "libvpx-vp9");
  ASSERT_EQ(webm.error, "");
  ASSERT_EQ(webm.pictures.size(), 5u);
  for (const DecodedVideo::Picture& picture : webm.pictures) {
    ASSERT_EQ(picture.pixel_format, AV_PIX_FMT_YUVA420P);
    ASSERT_EQ(picture.rgb.alpha.size(), 96u * 64u);
    EXPECT_EQ(picture.rgb.alpha[0], 0);               // top-left corner
    EXPECT_EQ(picture.rgb.alpha[96 * 64 - 1], 0);     // bottom-right corner
    EXPECT_EQ(picture.rgb.alpha[32 * 96 + 48], 255);  // the cube
  }
}

// A transparent render with a red caption on a blue box and a red caption on nothing: its PNG
// frame laid over green and over white shows the caption red and the box blue within 2 levels on
// both; its WebM, read by libvpx (which decodes the alpha plane), the same over both within 2
// levels, and red and blue but for VP9's loss. Both carry straight (unassociated) alpha.
TEST_F(VideoSinkTest, TransparentCaptionKeepsItsColoursOverAnyBackground) {
  // VP9 at the default quality 30, and at 4: the colour within 8 levels (VP9's loss), then 2.
  for (const auto& [webm_crf, codec_levels] : {std::pair{30, 8.0}, std::pair{4, 2.0}}) {
    SCOPED_TRACE("webm_crf " + std::to_string(webm_crf));
    fs::remove_all(path("out"));
    std::string scene_text =
        "name = \"spin\"\nduration = 0.1\n[physics]\ndt = 0.01\n"
        "[[bodies]]\nname = \"cube\"\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n"
        "[render]\nwidth = 256\nheight = 144\nfps = 20\nbackground = \"transparent\"\n"
        "[camera]\nposition = [0.0, 1.5, 4.0]\nlook_at = [0.0, 0.0, 0.0]\n"
        "[ground]\nheight = -1.0\n"
        "[output]\nformats = [\"webm\"]\nwebm_crf = WEBM_CRF\n"
        "[[overlays]]\nkind = \"text\"\ntext = \"HI\"\nanchor = \"top-left\"\nsize = 240\n"
        "color = \"#ff0000\"\nbackground = \"#0000ff\"\n"
        "[[overlays]]\nkind = \"text\"\ntext = \"HI\"\nanchor = \"bottom-right\"\nsize = 240\n"
        "color = \"#ff0000\"\n";
    scene_text.replace(scene_text.find("WEBM_CRF"), 8, std::to_string(webm_crf));
    const fs::path scene = write("spin.toml", scene_text);
    const testing::Outcome run = tumble("render -q " + scene.string() + " -o " + path("out"));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const RgbaFile png = read_rgba(frame(1));
    ASSERT_TRUE(png.has_alpha);
    const int width = 256, height = 144;
    ASSERT_EQ(png.width, width);

    // A straight RGBA pixel laid over `below` (0-255 each): c × a + below × (1 − a).
    const auto over = [](const int* rgba, const std::array<int, 3>& below, int c) {
      const double alpha = rgba[3] / 255.0;
      return rgba[c] * alpha + below[c] * (1.0 - alpha);
    };
    const auto near = [&](const int* rgba, const std::array<int, 3>& below,
                          const std::array<int, 3>& expected) {
      for (int c = 0; c < 3; ++c) {
        if (std::abs(over(rgba, below, c) - expected[c]) > 2.0) return false;
      }
      return true;
    };
    constexpr std::array<int, 3> kGreen{0, 255, 0}, kWhite{255, 255, 255};
    constexpr std::array<int, 3> kRed{255, 0, 0}, kBlue{0, 0, 255};
    // The pixels that show red (or blue) over white in the PNG, and a 3-pixel margin inside them
    // (VP9 keeps one chroma sample per 2 × 2 pixels: a glyph's edge bleeds into its neighbours).
    std::vector<std::uint8_t> kind(static_cast<std::size_t>(width) * height, 0);  // 1 red, 2 blue
    int red = 0, blue = 0;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        const int rgba[4] = {png.rgba[4 * i], png.rgba[4 * i + 1], png.rgba[4 * i + 2],
                             png.rgba[4 * i + 3]};
        const bool is_red = near(rgba, kWhite, kRed), is_blue = near(rgba, kWhite, kBlue);
        // Over green the same: the alpha is 255 there, or the colour would show the green.
        if (is_red) {
          EXPECT_TRUE(near(rgba, kGreen, kRed)) << x << ", " << y;
        }
        if (is_blue) {
          EXPECT_TRUE(near(rgba, kGreen, kBlue)) << x << ", " << y;
        }
        red += is_red;
        blue += is_blue;
        kind[i] = is_red ? 1 : is_blue ? 2 : 0;
      }
    }
    // Each "HI" is about 900 pixels of stroke; the box about 75 × 80.
    EXPECT_GT(red, 600);
    EXPECT_GT(blue, 3000);

    const DecodedVideo webm = testing::read_video(out("spin.webm"), "libvpx-vp9");
    ASSERT_EQ(webm.error, "");
    ASSERT_EQ(webm.pictures.size(), 2u);
    const io::Image& decoded = webm.pictures[1].rgb;
    ASSERT_EQ(decoded.alpha.size(), static_cast<std::size_t>(width) * height);
    // In the video, red and blue as BT.709 limited-range YUV holds them (pure blue comes back as
    // (3, 0, 255) before any compression): the alpha path must add nothing to that.
    const auto as_video = [](const std::array<int, 3>& colour) {
      io::Image flat(16, 16);
      for (std::size_t i = 0; i < flat.rgb.size(); ++i) {
        flat.rgb[i] = static_cast<std::uint8_t>(colour[i % 3]);
      }
      const io::Image back = io::through_picture_format(
          flat, io::VideoPictureFormat{AV_PIX_FMT_YUV420P, SWS_CS_ITU709, false});
      return std::array<int, 3>{back.rgb[0], back.rgb[1], back.rgb[2]};
    };
    const std::array<int, 3> video_red = as_video(kRed), video_blue = as_video(kBlue);
    int inner = 0;
    double worst_between = 0.0, worst_codec = 0.0;
    for (int y = 3; y < height - 3; ++y) {
      for (int x = 3; x < width - 3; ++x) {
        const std::uint8_t k = kind[static_cast<std::size_t>(y) * width + x];
        if (k == 0) continue;
        bool inside = true;
        for (int dy = -3; dy <= 3; ++dy) {
          for (int dx = -3; dx <= 3; ++dx) {
            inside = inside && kind[static_cast<std::size_t>(y + dy) * width + x + dx] == k;
          }
        }
        if (!inside) continue;
        ++inner;
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        const int rgba[4] = {decoded.rgb[3 * i], decoded.rgb[3 * i + 1], decoded.rgb[3 * i + 2],
                             decoded.alpha[i]};
        const std::array<int, 3>& expected = k == 1 ? video_red : video_blue;
        for (int c = 0; c < 3; ++c) {
          const double on_green = over(rgba, kGreen, c), on_white = over(rgba, kWhite, c);
          worst_between = std::max(worst_between, std::abs(on_green - on_white));
          worst_codec = std::max(
              {worst_codec, std::abs(on_green - expected[c]), std::abs(on_white - expected[c])});
        }
      }
    }
    EXPECT_GT(inner, 1000);
    // The same over green and over white within 2 levels: the alpha is what the PNG's is.
    EXPECT_LE(worst_between, 2.0);
    // And the colour as the PNG's, but for VP9's own loss: at quality 30 up to 6 levels in a blue
    // pixel 3 from a red stroke (measured 6 here); at 4, within 2.
    EXPECT_LE(worst_codec, codec_levels);
    std::printf("webm_crf %d: %.2f levels between backgrounds, %.2f from red and blue as YUV\n",
                webm_crf, worst_between, worst_codec);
  }
}

}  // namespace
}  // namespace tumble::pipeline
