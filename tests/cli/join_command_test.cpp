// End-to-end tests of the render farm's path: `tumble render --chunk I/N` and `--frames A:B`
// chunks joined by `tumble join` against the whole render (PNG bytes, the MP4's frame count,
// timestamps, duration and decoded frames), and every refusal of join, each with its message,
// exit code 2 and no output left.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "io/json_text.hpp"
#include "io/png_io.hpp"
#include "support/command_test.hpp"
#include "support/result_text.hpp"
#include "support/scene_text.hpp"
#include "support/test_frames.hpp"
#include "support/video_reader.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;
using tumble::testing::read_file;

// Half a second at 30 frames/s, 64x36: 15 frames of a cube spun up by a torque. The camera and
// ground are written out, so no framing pass runs and a chunk steps the physics only up to its
// first frame.
const std::string kScene = tumble::testing::spin_scene(
    64, 36, tumble::testing::kTorqueX,
    "[camera]\nposition = [0.0, 1.5, 4.0]\nlook_at = [0.0, 0.0, 0.0]\n[ground]\nheight = -1.5\n");

// RMS distance (levels, all channels) of a joined video's decoded frame from the whole render's
// decoded frame: measured 5.53 at most on this scene (the one-frame chunk; 3.1 to 4.7 for the
// others, frames away from the boundaries included), with Debian 12's x264 (core 164) at crf 20,
// veryfast, 64x36. And of a decoded frame from the PNG it was encoded from: measured 6.66 at
// most for the joined video, 6.54 for the whole one (x264's loss at crf 20 on so few pixels).
constexpr double kDecodedTolerance = 7.0;
constexpr double kFromSourceTolerance = 9.0;

class JoinCommand : public tumble::testing::CommandTest {
 protected:
  std::string scene() { return write("spin.toml", kScene).string(); }

  // `tumble render SCENE -q -o ROOT ARGUMENTS`, which must succeed; returns ROOT/spin.
  fs::path render(const std::string& root, const std::string& arguments,
                  const std::string& scene_path = "") {
    const Outcome run = tumble("render -q " + (scene_path.empty() ? scene() : scene_path) + " -o " +
                               path(root) + " " + arguments);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return dir_ / root / "spin";
  }

  Outcome join(const std::vector<fs::path>& chunks) {
    std::string arguments = "join " + path("joined");
    for (const fs::path& chunk : chunks) {
      arguments += ' ';  // appended apart: GCC 12 warns (-Wrestrict) about " " + string
      arguments += chunk.string();
    }
    return tumble(arguments);
  }

  // A refusal: exit 2, the message, and nothing written (no joined folder, no partial one).
  void expect_refused(const std::vector<fs::path>& chunks, const std::string& says) {
    const Outcome run = join(chunks);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find(says), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "joined"));
    for (const auto& entry : fs::directory_iterator(dir_)) {
      EXPECT_EQ(entry.path().filename().string().find(".joined"), std::string::npos)
          << entry.path();
    }
  }

  static std::vector<std::string> names_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }
};

// Three uneven chunks, one of a single frame, given out of order.
TEST_F(JoinCommand, ThreeUnevenChunksJoinIntoTheWholeRender) {
  const fs::path whole = render("whole", "");
  const fs::path a = render("a", "--frames 0:7"), b = render("b", "--frames 7:8"),
                 c = render("c", "--frames 8:15");
  const Outcome run = join({c, a, b});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path joined = dir_ / "joined";
  EXPECT_NE(read_file(joined / "report.json").find("\"version\": \"" TUMBLE_VERSION "\""),
            std::string::npos);
  EXPECT_EQ(names_in(joined), (std::vector<std::string>{"contact_sheet.png", "frames", "poster.png",
                                                        "report.json", "spin.mp4"}));
  // The stills a whole render writes, byte for byte: the poster of the chunk that drew its frame
  // (7, the middle: chunk b) and the contact sheet composed again from the joined frames.
  for (const char* still : {"poster.png", "contact_sheet.png"}) {
    ASSERT_TRUE(fs::exists(whole / still)) << still;
    EXPECT_EQ(read_file(joined / still), read_file(whole / still)) << still;
  }
  EXPECT_FALSE(fs::exists(a / "poster.png"));  // a chunk without the poster frame writes none
  EXPECT_NE(run.err.find("poster.png, contact_sheet.png, report.json"), std::string::npos)
      << run.err;

  // The PNG frames: the same names and the same bytes.
  ASSERT_EQ(names_in(joined / "frames"), names_in(whole / "frames"));
  EXPECT_EQ(names_in(joined / "frames").size(), 15u);
  for (const std::string& name : names_in(whole / "frames")) {
    EXPECT_EQ(read_file(joined / "frames" / name), read_file(whole / "frames" / name)) << name;
  }

  // The MP4: frame count, timestamps and duration of the whole render's.
  const auto joined_video = tumble::testing::read_video((joined / "spin.mp4").string());
  const auto whole_video = tumble::testing::read_video((whole / "spin.mp4").string());
  ASSERT_EQ(joined_video.error, "");
  ASSERT_EQ(whole_video.error, "");
  ASSERT_EQ(joined_video.pictures.size(), 15u);
  ASSERT_EQ(whole_video.pictures.size(), 15u);
  EXPECT_NEAR(joined_video.duration, whole_video.duration, 1e-9);
  EXPECT_NEAR(joined_video.duration, 0.5, 1e-9);
  EXPECT_EQ(av_cmp_q(joined_video.avg_frame_rate, whole_video.avg_frame_rate), 0);
  // Each chunk is an encode of its own (its own IDR frame and rate control, x264's stitchable
  // headers), so its decoded frames are near the whole encode's, not equal to them; and as near
  // to the frames they were encoded from (the PNGs) as the whole encode's are.
  const std::vector<std::string> frame_names = names_in(whole / "frames");
  double worst = 0.0, worst_from_source = 0.0, whole_from_source = 0.0;
  for (std::size_t k = 0; k < 15; ++k) {
    EXPECT_NEAR(joined_video.pictures[k].time, whole_video.pictures[k].time, 1e-9) << k;
    EXPECT_NEAR(joined_video.pictures[k].time, static_cast<double>(k) / 30, 1e-9) << k;
    tumble::io::Image source;
    ASSERT_EQ(::tumble::testing::take(
                  tumble::io::read_png((whole / "frames" / frame_names[k]).string()), source),
              "");
    const auto& joined_rgb = joined_video.pictures[k].rgb;
    const double rms = tumble::testing::rms_difference(joined_rgb, whole_video.pictures[k].rgb);
    const double from_source = tumble::testing::rms_difference(joined_rgb, source);
    const double whole_rms = tumble::testing::rms_difference(whole_video.pictures[k].rgb, source);
    std::printf(
        "[ measured ] frame %zu: RMS %.3f from the whole render's decoded frame; from the "
        "PNG %.3f (the whole render's %.3f)\n",
        k, rms, from_source, whole_rms);
    worst = std::max(worst, rms);
    worst_from_source = std::max(worst_from_source, from_source);
    whole_from_source = std::max(whole_from_source, whole_rms);
  }
  EXPECT_LT(worst, kDecodedTolerance);
  EXPECT_LT(worst_from_source, kFromSourceTolerance);
  EXPECT_LT(whole_from_source, kFromSourceTolerance);

  const std::string report = read_file(joined / "report.json");
  EXPECT_EQ(report.rfind("{\n  \"scene\": \"spin\"", 0), 0u) << report;
  EXPECT_NE(report.find("\"frames\": {\"first\": 0, \"end\": 15, \"count\": 15}"),
            std::string::npos);
  EXPECT_NE(report.find("\"joined_from\": ["), std::string::npos);
  EXPECT_NE(report.find("\"first\": 7, \"end\": 8"), std::string::npos);
}

// Chunks without PNG frames still give the whole render's poster; the contact sheet, which needs
// the frames' pixels, is left out, and the join says so.
TEST_F(JoinCommand, ChunksWithoutFramesGiveThePosterAndSayThereIsNoContactSheet) {
  const fs::path whole = render("whole", "--no-frames");
  const fs::path a = render("a", "--frames 0:9 --no-frames"),
                 b = render("b", "--frames 9:15 --no-frames");
  const Outcome run = join({a, b});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path joined = dir_ / "joined";
  EXPECT_EQ(names_in(joined), (std::vector<std::string>{"poster.png", "report.json", "spin.mp4"}));
  EXPECT_EQ(read_file(joined / "poster.png"), read_file(whole / "poster.png"));
  EXPECT_NE(run.err.find("no contact_sheet.png: the chunks hold no PNG frames"), std::string::npos)
      << run.err;
}

// --chunk I/N renders line I of `plan --chunks N` into <directory>.chunk-I-of-N, and the chunks
// of a plan join into the whole render.
TEST_F(JoinCommand, ChunkIOfNRendersLineIOfThePlanAndTheChunksJoin) {
  const Outcome plan = tumble("plan " + scene() + " --chunks 3");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_EQ(plan.out, "0:5\n5:10\n10:15\n");
  std::vector<fs::path> chunks;
  for (int i = 1; i <= 3; ++i) {
    const Outcome run = tumble("render -q " + scene() + " -o " + path("farm") + " --chunk " +
                               std::to_string(i) + "/3");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    chunks.push_back(dir_ / "farm" / ("spin.chunk-" + std::to_string(i) + "-of-3"));
  }
  EXPECT_EQ(
      names_in(dir_ / "farm"),
      (std::vector<std::string>{"spin.chunk-1-of-3", "spin.chunk-2-of-3", "spin.chunk-3-of-3"}));
  EXPECT_EQ(names_in(chunks[1] / "frames"),
            (std::vector<std::string>{"frame_00005.png", "frame_00006.png", "frame_00007.png",
                                      "frame_00008.png", "frame_00009.png"}));
  const std::string report = read_file(chunks[1] / "report.json");
  EXPECT_NE(report.find("\"chunk\": {\"index\": 2, \"count\": 3}"), std::string::npos) << report;
  EXPECT_NE(report.find("\"frames\": {\"first\": 5, \"end\": 10, \"count\": 5}"),
            std::string::npos);
  EXPECT_NE(report.find("\"scene_frames\": 15"), std::string::npos);

  const Outcome run = join({chunks[2], chunks[0], chunks[1]});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path whole = render("whole", "--no-video");
  for (const std::string& name : names_in(whole / "frames")) {
    EXPECT_EQ(read_file(dir_ / "joined/frames" / name), read_file(whole / "frames" / name)) << name;
  }
  EXPECT_EQ(tumble::testing::read_video(path("joined/spin.mp4")).pictures.size(), 15u);
}

// A trail shows the body's past: a chunk must draw the trail a render from frame 0 draws, though
// it starts its physics late (to the trail's oldest frame, not its own first).
TEST_F(JoinCommand, AChunkDrawsTheTrailOfTheWholeRender) {
  const std::string trail_scene =
      write("trail.toml",
            tumble::testing::spin_scene(
                320, 180, std::string("name = \"cube\"\n") + tumble::testing::kTorqueX,
                "[camera]\nposition = [0.0, 1.5, 4.0]\nlook_at = [0.0, 0.0, 0.0]\n[ground]\n"
                "height = -1.5\n[[overlays]]\nkind = \"trail\"\nbody = \"cube\"\n"
                "point = [0.5, 0.5, 0.5]\nlength = 0.3\n"))
          .string();
  const fs::path whole = render("whole", "--no-video", trail_scene);
  const fs::path chunk = render("chunk", "--no-video --frames 12:15", trail_scene);
  for (const char* name : {"frame_00012.png", "frame_00014.png"}) {
    // Not EXPECT_EQ: a failure would print two PNGs' bytes.
    EXPECT_TRUE(read_file(chunk / "frames" / name) == read_file(whole / "frames" / name))
        << name << ": the chunk's frame is not the whole render's";
  }
}

// A render that writes MP4 and WebM joins both: the WebM's VP9 is stream-copied as the MP4's H.264
// is, and decodes to the whole render's frame count and times, each frame near its PNG.
TEST_F(JoinCommand, ChunksWithAnMp4AndAWebmJoinIntoBoth) {
  const std::string formats = " --format mp4,webm";
  const fs::path a = render("a", "--frames 0:7" + formats),
                 b = render("b", "--frames 7:8" + formats),
                 c = render("c", "--frames 8:15" + formats);
  const Outcome run = join({a, b, c});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path joined = dir_ / "joined";
  EXPECT_EQ(names_in(joined), (std::vector<std::string>{"contact_sheet.png", "frames", "poster.png",
                                                        "report.json", "spin.mp4", "spin.webm"}));
  const auto webm = tumble::testing::read_video((joined / "spin.webm").string());
  ASSERT_EQ(webm.error, "");
  ASSERT_EQ(webm.pictures.size(), 15u);
  EXPECT_NEAR(webm.duration, 0.5, 1e-3);  // WebM keeps times in milliseconds
  const std::vector<std::string> frame_names = names_in(joined / "frames");
  double worst = 0.0;
  for (std::size_t k = 0; k < 15; ++k) {
    EXPECT_NEAR(webm.pictures[k].time, static_cast<double>(k) / 30, 1e-3) << k;
    tumble::io::Image source;
    ASSERT_EQ(::tumble::testing::take(
                  tumble::io::read_png((joined / "frames" / frame_names[k]).string()), source),
              "");
    worst = std::max(worst, tumble::testing::rms_difference(webm.pictures[k].rgb, source));
  }
  std::printf("[ measured ] joined WebM: RMS at most %.3f from the PNGs\n", worst);
  EXPECT_LT(worst, kFromSourceTolerance);
  EXPECT_EQ(tumble::testing::read_video((joined / "spin.mp4").string()).pictures.size(), 15u);
  const std::string report = read_file(joined / "report.json");
  EXPECT_NE(report.find(
                "\"videos\": {\"mp4\": " + tumble::io::json_string((joined / "spin.mp4").string()) +
                ", \"webm\": " + tumble::io::json_string((joined / "spin.webm").string())),
            std::string::npos)
      << report;
}

// A transparent render's WebM chunks join into a WebM that keeps its alpha (alpha_mode 1).
TEST_F(JoinCommand, TransparentWebmChunksKeepTheirAlpha) {
  std::string transparent = kScene;
  transparent.replace(transparent.find("fps = 30\n"), 9,
                      "fps = 30\nbackground = \"transparent\"\n");
  const std::string clear =
      write("clear.toml", transparent + "[output]\nformats = [\"webm\"]\n").string();
  const fs::path a = render("a", "--frames 0:7", clear), c = render("c", "--frames 7:15", clear);
  const Outcome run = join({a, c});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto webm = tumble::testing::read_video(path("joined/spin.webm"), "libvpx-vp9");
  ASSERT_EQ(webm.error, "");
  ASSERT_EQ(webm.pictures.size(), 15u);
  EXPECT_EQ(webm.alpha_mode, "1");  // players show the alpha only when the track says so
  for (const auto& picture : webm.pictures) {
    ASSERT_EQ(picture.pixel_format, AV_PIX_FMT_YUVA420P);
    ASSERT_EQ(picture.rgb.alpha.size(), 64u * 36u);
    EXPECT_EQ(picture.rgb.alpha[0], 0);  // top-left corner: nothing there
    // The cube in the middle: VP9 codes the alpha plane with loss too (measured 250 to 255 at
    // this tiny size).
    EXPECT_GE(picture.rgb.alpha[18 * 64 + 32], 240);
  }
}

// A WebM's index does not count its frames: a copy cut short is found against the chunk's report.
TEST_F(JoinCommand, RefusesATruncatedWebmSegment) {
  const fs::path a = render("a", "--frames 0:7 --format webm"),
                 c = render("c", "--frames 7:15 --format webm");
  const fs::path webm = c / "spin.webm";
  fs::resize_file(webm, fs::file_size(webm) / 2);
  expect_refused({a, c}, webm.string());
}

// A GIF's palette is its own frames': --chunk refuses it before rendering anything, and so does
// `tumble plan` of a scene that writes one (every chunk of it would be refused on the farm).
TEST_F(JoinCommand, AChunkOfAGifIsRefusedBeforeRendering) {
  const Outcome run =
      tumble("render " + scene() + " --chunk 1/2 --format mp4,gif -o " + path("out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--chunk: gif is not written in parts"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  const std::string gif_scene =
      write("gif.toml", kScene + "[output]\nformats = [\"mp4\", \"gif\"]\n").string();
  const Outcome plan = tumble("plan " + gif_scene + " --chunks 2");
  EXPECT_EQ(plan.exit_code, 2);
  EXPECT_EQ(plan.out, "");
  EXPECT_NE(plan.err.find("tumble: plan: " + gif_scene + ": gif is not written in parts"),
            std::string::npos)
      << plan.err;
}

// A glTF is one animation of the frames it holds, and join joins videos only: --chunk and
// `tumble plan` refuse a scene that writes one, before rendering, saying what to do instead.
TEST_F(JoinCommand, AChunkOfAGltfIsRefusedBeforeRendering) {
  const Outcome run =
      tumble("render " + scene() + " --chunk 1/2 --format mp4,gltf -o " + path("out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--chunk: gltf is not written in parts"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("render the glTF whole, or of a frame range with --frames"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  const std::string gltf_scene =
      write("gltf.toml", kScene + "[output]\nformats = [\"gltf\"]\nvideo = false\n").string();
  const Outcome plan = tumble("plan " + gltf_scene + " --chunks 2");
  EXPECT_EQ(plan.exit_code, 2);
  EXPECT_EQ(plan.out, "");
  EXPECT_NE(plan.err.find("tumble: plan: " + gltf_scene + ": gltf is not written in parts"),
            std::string::npos)
      << plan.err;
}

TEST_F(JoinCommand, ChunkRefusesFramesBesideItAndAChunkPastTheFrames) {
  const Outcome both = tumble("render " + scene() + " --chunk 1/3 --frames 0:5 -o " + path("out"));
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--frames excludes --chunk"), std::string::npos) << both.err;
  const Outcome beyond = tumble("render " + scene() + " --chunk 16/16 -o " + path("out"));
  EXPECT_EQ(beyond.exit_code, 2);
  EXPECT_NE(beyond.err.find("--chunk 16/16: 16 chunks cannot split the scene's 15 frames"),
            std::string::npos)
      << beyond.err;
  const Outcome zero = tumble("render " + scene() + " --chunk 0/3 -o " + path("out"));
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("--chunk: expected I/N (chunk I of N, 1 <= I <= N), got 0/3"),
            std::string::npos)
      << zero.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(JoinCommand, RefusesChunksOfAnotherScene) {
  const fs::path a = render("a", "--frames 0:7"), c = render("c", "--frames 8:15");
  std::string other = kScene;
  other.replace(other.find("torque = [1.0"), 13, "torque = [2.0");
  fs::create_directories(dir_ / "other");
  const fs::path b = render("b", "--frames 7:8", write("other/spin.toml", other).string());
  expect_refused({a, b, c}, "differ in the scene they rendered (scene_hash");
}

TEST_F(JoinCommand, RefusesChunksOfOtherSettings) {
  const fs::path a = render("a", "--frames 0:7"), b = render("b", "--frames 7:8"),
                 c = render("c", "--frames 8:15 --width 80");
  expect_refused({a, b, c},
                 "chunks " + a.string() + " and " + c.string() + " differ in width: 64 and 80");
}

TEST_F(JoinCommand, RefusesAMissingRangeAndAnOverlap) {
  const fs::path a = render("a", "--frames 0:7"), c = render("c", "--frames 8:15"),
                 d = render("d", "--frames 5:15");
  expect_refused({a, c}, "the chunks do not hold every frame once: frames 7:8 are missing");
  expect_refused({d, a}, "frames 5:7 are in both " + a.string() + " and " + d.string());
}

TEST_F(JoinCommand, RefusesATruncatedSegment) {
  const fs::path a = render("a", "--frames 0:7"), c = render("c", "--frames 7:15");
  const fs::path mp4 = c / "spin.mp4";
  fs::resize_file(mp4, fs::file_size(mp4) - 500);
  expect_refused({a, c}, mp4.string());
}

TEST_F(JoinCommand, RefusesAFolderThatIsNotARendersAndFoldersWithoutAReport) {
  const fs::path a = render("a", "--frames 0:7"), c = render("c", "--frames 7:15");
  expect_refused({a, dir_ / "nowhere"}, (dir_ / "nowhere").string() + ": no report.json");
  fs::create_directories(dir_ / "joined");
  write("joined/notes.txt", "mine");
  const Outcome run = join({a, c});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("exists and is not a tumble render"), std::string::npos) << run.err;
  EXPECT_EQ(read_file(dir_ / "joined/notes.txt"), "mine");
}

}  // namespace

// `tumble render --jobs N`: N chunk processes at once, joined. The frames, poster and contact
// sheet are the one-process render's byte for byte; the MP4 has its frames and timestamps (each
// chunk's segment is an encode of its own, joined by stream copy as `tumble join` does); the
// hidden folder of the chunks is gone.
TEST_F(JoinCommand, JobsRendersChunksInProcessesAndJoinsThemIntoTheWholeRender) {
  const fs::path whole = render("whole", "");
  for (const int jobs : {2, 4, 20}) {  // 20: more processes than frames, one a frame
    const std::string root = "jobs" + std::to_string(jobs);
    const fs::path joined = render(root, "--jobs " + std::to_string(jobs));
    EXPECT_EQ(names_in(dir_ / root), std::vector<std::string>{"spin"}) << jobs;
    EXPECT_EQ(names_in(joined),
              (std::vector<std::string>{"contact_sheet.png", "frames", "poster.png", "report.json",
                                        "spin.mp4"}));
    ASSERT_EQ(names_in(joined / "frames"), names_in(whole / "frames"));
    for (const std::string& name : names_in(whole / "frames")) {
      EXPECT_EQ(read_file(joined / "frames" / name), read_file(whole / "frames" / name)) << name;
    }
    for (const char* still : {"poster.png", "contact_sheet.png"}) {
      EXPECT_EQ(read_file(joined / still), read_file(whole / still)) << still;
    }
    const auto video = tumble::testing::read_video((joined / "spin.mp4").string());
    ASSERT_EQ(video.error, "");
    ASSERT_EQ(video.pictures.size(), 15u);
    for (std::size_t k = 0; k < 15; ++k) {
      EXPECT_NEAR(video.pictures[k].time, static_cast<double>(k) / 30, 1e-9) << k;
    }
    const std::string report = read_file(joined / "report.json");
    EXPECT_NE(report.find("\"frames\": {\"first\": 0, \"end\": 15, \"count\": 15}"),
              std::string::npos);
    EXPECT_NE(report.find("\"joined_from\": ["), std::string::npos);
  }
}

TEST_F(JoinCommand, JobsRefusesAGifAChunkAndFramesBeforeRenderingAnything) {
  const Outcome gif = tumble("render " + scene() + " --jobs 2 --format mp4,gif -o " + path("out"));
  EXPECT_EQ(gif.exit_code, 2);
  EXPECT_NE(gif.err.find("--jobs: gif is not written in parts"), std::string::npos) << gif.err;
  const Outcome chunk = tumble("render " + scene() + " --jobs 2 --chunk 1/2 -o " + path("out"));
  EXPECT_EQ(chunk.exit_code, 2);
  EXPECT_NE(chunk.err.find("excludes"), std::string::npos) << chunk.err;
  const Outcome zero = tumble("render " + scene() + " --jobs 0 -o " + path("out"));
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}
