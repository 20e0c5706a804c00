// End-to-end tests of `tumble render`: the real executable, PNG frames read back with libpng and
// the MP4 read back with libavformat/libavcodec.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "diff/image_diff.hpp"
#include "io/json_reader.hpp"
#include "io/png_io.hpp"
#include "render/offscreen_context.hpp"
#include "support/command_test.hpp"
#include "support/result_text.hpp"
#include "support/scene_text.hpp"
#include "support/video_reader.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::io::Image;
using tumble::testing::Outcome;
using tumble::testing::read_file;

// Half a second at 30 frames/s: 15 frames of a cube spinning up, small and quick to render.
const std::string kScene = tumble::testing::spin_scene(160, 120, tumble::testing::kTorqueX);

class RenderCommand : public tumble::testing::CommandTest {
 protected:
  std::string scene() { return write("spin.toml", kScene).string(); }
  std::string frame(const std::string& root, int k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", k);
    return (dir_ / root / "spin" / "frames" / name).string();
  }
};

TEST_F(RenderCommand, WritesEveryFrameAndAnH264Mp4OfTheRightShape) {
  const Outcome run = tumble("render " + scene() + " -o " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("15 frames in"), std::string::npos) << run.err;

  int frames = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "out/spin/frames")) {
    (void)entry;
    ++frames;
  }
  EXPECT_EQ(frames, 15);
  Image last;
  ASSERT_EQ(::tumble::testing::take(tumble::io::read_png(frame("out", 14)), last), "");
  EXPECT_EQ(last.width, 160);
  EXPECT_EQ(last.height, 120);

  const auto video = tumble::testing::read_video(path("out/spin/spin.mp4"));
  ASSERT_EQ(video.error, "");
  EXPECT_EQ(video.codec, AV_CODEC_ID_H264);
  EXPECT_EQ(video.stream_pixel_format, AV_PIX_FMT_YUV420P);
  EXPECT_EQ(video.width, 160);
  EXPECT_EQ(video.height, 120);
  EXPECT_EQ(video.avg_frame_rate.num, 30);
  EXPECT_EQ(video.avg_frame_rate.den, 1);
  EXPECT_NEAR(video.duration, 0.5, 0.5 / 30);
  ASSERT_EQ(video.pictures.size(), 15u);
  // The video shows the frames that were written as PNG: decoded frame 14 against the PNG,
  // within what H.264 at CRF 20 loses on a small image full of edges (measured RMS 4.7 of 255;
  // the frame half a second earlier gives about 25).
  const tumble::diff::DiffResult diff = tumble::diff::compare_images(
      last, video.pictures[14].rgb, {.threshold = 255, .max_pixels = 0});
  EXPECT_LT(diff.rms, 8.0);

  EXPECT_TRUE(fs::exists(dir_ / "out/spin/report.json"));
  EXPECT_NE(read_file(dir_ / "out/spin/report.json").find("\"count\": 15"), std::string::npos);
}

TEST_F(RenderCommand, RenderingTwiceGivesByteIdenticalFramesAndVideo) {
  ASSERT_EQ(tumble("render -q " + scene() + " -o " + path("a")).exit_code, 0);
  ASSERT_EQ(tumble("render -q " + scene() + " -o " + path("b")).exit_code, 0);
  for (int k = 0; k < 15; ++k) {
    EXPECT_EQ(read_file(frame("a", k)), read_file(frame("b", k))) << "frame " << k;
  }
  EXPECT_EQ(read_file(dir_ / "a/spin/spin.mp4"), read_file(dir_ / "b/spin/spin.mp4"));
}

TEST_F(RenderCommand, PipelinedAndSerialPathsGiveTheSameBytes) {
  ASSERT_EQ(tumble("render -q " + scene() + " -o " + path("piped")).exit_code, 0);
  ASSERT_EQ(tumble("render -q --serial " + scene() + " -o " + path("serial")).exit_code, 0);
  for (int k = 0; k < 15; ++k) {
    EXPECT_EQ(read_file(frame("piped", k)), read_file(frame("serial", k))) << "frame " << k;
  }
  EXPECT_EQ(read_file(dir_ / "piped/spin/spin.mp4"), read_file(dir_ / "serial/spin/spin.mp4"));
  const auto piped = tumble::testing::read_video(path("piped/spin/spin.mp4"));
  const auto serial = tumble::testing::read_video(path("serial/spin/spin.mp4"));
  ASSERT_EQ(piped.pictures.size(), 15u);
  ASSERT_EQ(serial.pictures.size(), 15u);
  for (std::size_t k = 0; k < 15; ++k) {
    EXPECT_EQ(piped.pictures[k].rgb.rgb, serial.pictures[k].rgb.rgb) << "decoded frame " << k;
  }
  EXPECT_NE(read_file(dir_ / "piped/spin/report.json").find("\"path\": \"pipelined\""),
            std::string::npos);
  EXPECT_NE(read_file(dir_ / "serial/spin/report.json").find("\"path\": \"serial\""),
            std::string::npos);
}

// Bounded queues: twenty times the frames, the same peak memory (within allocator noise).
TEST_F(RenderCommand, PeakMemoryDoesNotGrowWithTheNumberOfFrames) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's quarantine grows with every allocation";
#endif
  std::string long_scene = kScene;
  long_scene.replace(long_scene.find("duration = 0.5"), 14, "duration = 20.0");
  const std::string scene_path = write("long.toml", long_scene).string();
  // With one malloc arena: glibc opens an arena for a thread that finds the others busy, so how
  // many a run ends with (and the memory they hold) depends on how its threads met, which a
  // loaded machine changes; the test is about what tumble keeps, which grows with each frame
  // only if something leaks. (It failed once under ctest -j2, by more than 4 MB; not reproduced.)
  const auto peak = [&](const std::string& frames, const std::string& root) {
    const Outcome run =
        tumble("render -q --frames " + frames + " " + scene_path + " -o " + path(root),
               "exec env MALLOC_ARENA_MAX=1 ");
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const std::string report = read_file(dir_ / root / "spin/report.json");
    const std::size_t at = report.find("\"peak_memory_bytes\": ");
    EXPECT_NE(at, std::string::npos);
    return at == std::string::npos ? 0.0 : std::stod(report.substr(at + 21));
  };
  const double short_run = peak("0:30", "short");
  const double long_run = peak("0:600", "long");
  std::printf("[ measured ] peak memory: %.0f bytes for 30 frames, %.0f for 600\n", short_run,
              long_run);
  EXPECT_LT(long_run, short_run + 4e6) << short_run << " then " << long_run << " bytes";
}

TEST_F(RenderCommand, AFrameRangeGivesTheSamePixelsAsTheWholeRender) {
  ASSERT_EQ(tumble("render -q --no-video " + scene() + " -o " + path("whole")).exit_code, 0);
  const Outcome part =
      tumble("render -q --no-video --frames 5:8 " + scene() + " -o " + path("part"));
  ASSERT_EQ(part.exit_code, 0) << part.err;
  EXPECT_FALSE(fs::exists(frame("part", 4)));
  EXPECT_FALSE(fs::exists(frame("part", 8)));
  for (int k = 5; k < 8; ++k) {
    ASSERT_TRUE(fs::exists(frame("part", k)));
    EXPECT_EQ(read_file(frame("part", k)), read_file(frame("whole", k))) << "frame " << k;
  }
  EXPECT_FALSE(fs::exists(dir_ / "part/spin/spin.mp4"));
}

// A level floor plane is drawn as the ground [ground] height places: the same bytes. A wall
// beside the cube then changes the picture.
TEST_F(RenderCommand, AFloorPlaneDrawsTheGroundAtItsHeight) {
  const std::string cube = std::string(kScene) + "[output]\nvideo = false\n";
  const std::string grounded = cube + "[ground]\nheight = -2.0\n";
  const std::string floored = cube + "[[planes]]\npoint = [0, -2, 0]\nnormal = [0, 1, 0]\n";
  const std::string walled = floored + "[[planes]]\npoint = [-2, 0, 0]\nnormal = [1, 0, 0]\n";
  for (const auto& [name, text] : {std::pair{"grounded", grounded}, std::pair{"floored", floored},
                                   std::pair{"walled", walled}}) {
    const Outcome run =
        tumble("render -q --frames 0:1 " + write(std::string(name) + ".toml", text).string() +
               " -o " + path(name));
    ASSERT_EQ(run.exit_code, 0) << name << ": " << run.err;
  }
  EXPECT_EQ(read_file(frame("floored", 0)), read_file(frame("grounded", 0)));
  EXPECT_NE(read_file(frame("walled", 0)), read_file(frame("floored", 0)));
}

TEST_F(RenderCommand, CommandLineSizeAndRateOverrideTheScene) {
  const Outcome run = tumble("render -q --no-frames --width 96 --height 64 --fps 10 " + scene() +
                             " -o " + path("o"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto video = tumble::testing::read_video(path("o/spin/spin.mp4"));
  ASSERT_EQ(video.error, "");
  EXPECT_EQ(video.width, 96);
  EXPECT_EQ(video.height, 64);
  EXPECT_EQ(video.pictures.size(), 5u);  // 0.5 s at 10 frames/s
  EXPECT_FALSE(fs::exists(dir_ / "o/spin/frames"));
}

// The scene's rules hold after the command line's overrides too, checked in the same place
// (scene/video_rules.hpp): one error, naming the scene file and the key the override broke.
TEST_F(RenderCommand, AnOverrideThatBreaksAVideoRuleGivesOneClearError) {
  const Outcome odd = tumble("render -q --width 161 " + scene() + " -o " + path("odd"));
  EXPECT_EQ(odd.exit_code, 2);
  EXPECT_EQ(odd.err, "tumble: " + scene() +
                         ": render.width, as the command line sets it: must be even for H.264 "
                         "yuv420p video, which stores colour per 2×2 pixels (got 161); or set "
                         "[output] video = false (--no-video) for PNG frames only\n");
  EXPECT_FALSE(fs::exists(dir_ / "odd"));
  // 0.4 s at 30 frames/s is 12 frames; at 1 frame/s it rounds to none.
  std::string short_scene = kScene;
  short_scene.replace(short_scene.find("duration = 0.5"), 14, "duration = 0.4");
  const Outcome none = tumble("render -q --fps 1 " + write("short.toml", short_scene).string() +
                              " -o " + path("none"));
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("render.fps, as the command line sets it: duration × fps gives no frame"),
            std::string::npos)
      << none.err;
  const Outcome nothing =
      tumble("render -q --no-frames --no-video " + scene() + " -o " + path("nothing"));
  EXPECT_EQ(nothing.exit_code, 2);
  EXPECT_NE(nothing.err.find("output.video, as the command line sets it: frames and video are "
                             "both off: nothing to write"),
            std::string::npos)
      << nothing.err;
  const Outcome frames =
      tumble("render -q --no-video --width 161 --frames 0:1 " + scene() + " -o " + path("odd"));
  ASSERT_EQ(frames.exit_code, 0) << frames.err;
  Image image;
  ASSERT_EQ(::tumble::testing::take(tumble::io::read_png(frame("odd", 0)), image), "");
  EXPECT_EQ(image.width, 161);
}

// The framing pass (the whole run simulated to choose the camera and ground) runs only when the
// scene leaves one of them open; report.json counts its physics steps.
TEST_F(RenderCommand, AGivenCameraAndGroundNeedNoFramingPass) {
  const std::string given = std::string(kScene) +
                            "[camera]\nposition = [4.0, 3.0, 6.0]\nlook_at = [0.0, 0.0, 0.0]\n" +
                            "[ground]\nheight = -1.5\n";
  for (const auto& [name, text] :
       {std::pair{"given", given}, std::pair{"open", std::string(kScene)}}) {
    const Outcome run =
        tumble("render -q --no-video --frames 0:3 " +
               write(std::string(name) + ".toml", text).string() + " -o " + path(name));
    ASSERT_EQ(run.exit_code, 0) << name << ": " << run.err;
  }
  // 3 frames at 30 frames/s reach t = 2/30 s: 7 steps of 0.01 s. The framing pass of the open
  // scene runs to its last frame, 14/30 s: 47 steps.
  EXPECT_NE(read_file(dir_ / "given/spin/report.json")
                .find("\"physics_steps\": {\"framing\": 0, \"frames\": 7, \"to_first_frame\": 0}"),
            std::string::npos)
      << read_file(dir_ / "given/spin/report.json");
  EXPECT_NE(read_file(dir_ / "open/spin/report.json")
                .find("\"physics_steps\": {\"framing\": 47, \"frames\": 7, \"to_first_frame\": 0}"),
            std::string::npos)
      << read_file(dir_ / "open/spin/report.json");
}

// Without a framing pass a render simulates only up to its last frame: a body that blows up
// later does not stop a render of the frames before.
TEST_F(RenderCommand, ABlowUpAfterTheLastFrameStopsOnlyARenderThatFramesTheWholeRun) {
  // k dt = 100 / s × 0.05 s = 5, beyond explicit Euler's limit of 2: it blows up at t = 0.7 s.
  const std::string stiff = R"(duration = 2.0
[physics]
dt = 0.05
integrator = "euler"
[[bodies]]
name = "slab"
shape = "cube"
size = 1.0
mass = 1.0
velocity = [1.0, 0.0, 0.0]
[[bodies.forces]]
kind = "linear_damping"
coefficient = 100.0
[render]
width = 64
height = 48
fps = 10
[output]
video = false
)";
  const std::string framed = stiff +
                             "[camera]\nposition = [4.0, 3.0, 6.0]\nlook_at = [0.0, 0.0, 0.0]\n" +
                             "[ground]\nheight = -1.0\n";
  const Outcome given =
      tumble("render -q --frames 0:5 " + write("given.toml", framed).string() + " -o " + path("a"));
  EXPECT_EQ(given.exit_code, 0) << given.err;
  const Outcome open =
      tumble("render -q --frames 0:5 " + write("open.toml", stiff).string() + " -o " + path("b"));
  EXPECT_EQ(open.exit_code, 2) << open.err;
  EXPECT_NE(open.err.find("body \"slab\" blew up at t = 0.7 s"), std::string::npos) << open.err;
  EXPECT_FALSE(fs::exists(dir_ / "b"));
}

// JSON has no infinity: a kinetic energy that leaves double range during the run is null.
// 1e300 kg at 1e4 m/s has 5e307 J; pushed to 2e4 m/s in half a second it would have 2e308.
TEST_F(RenderCommand, AnEnergyBeyondDoubleRangeIsNullInTheReport) {
  const Outcome run = tumble("render -q --no-video " +
                             write("heavy.toml", R"(name = "heavy"
duration = 0.5
[[bodies]]
shape = "cube"
size = 1.0
mass = 1e300
velocity = [1e4, 0.0, 0.0]
[[bodies.forces]]
kind = "force"
force = [2e304, 0.0, 0.0]
[render]
width = 64
height = 48
fps = 10
)")
                                 .string() +
                             " -o " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string report = read_file(dir_ / "out/heavy/report.json");
  EXPECT_NE(report.find("\"energy_start\": 5.0000000000000001e+307"), std::string::npos) << report;
  EXPECT_NE(report.find("\"energy_end\": null"), std::string::npos) << report;
  EXPECT_EQ(report.find("inf"), std::string::npos) << report;
}

// A camera placed where it would look by default (the centre of the motion) has no direction:
// an error naming what to add, instead of a blank video.
TEST_F(RenderCommand, ACameraWithNoDirectionIsAnError) {
  const Outcome run =
      tumble("render -q " +
             write("inside.toml", std::string(kScene) + "[camera]\nposition = [0.0, 0.0, 0.0]\n")
                 .string() +
             " -o " + path("out"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("the view has no direction; give [camera] look_at"), std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// A file name may hold any bytes; report.json must stay valid JSON: UTF-8 kept, the rest U+FFFD.
TEST_F(RenderCommand, TheReportIsValidJsonWhateverTheSceneFileIsCalled) {
  const fs::path scene = write("caf\xc3\xa9 \"\xff\".toml", kScene);
  const Outcome run =
      tumble("render -q --frames 0:1 --no-video '" + scene.string() + "' -o " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string report = read_file(dir_ / "out/spin/report.json");
  EXPECT_NE(report.find("caf\xc3\xa9 \\\"\\ufffd\\\".toml\""), std::string::npos) << report;
}

// Every example scene renders: its first two frames, small. Each is a copy cut to its first 2 s:
// a render frames the bodies over the whole run first, and the 20 s pour of pile.toml alone took
// 206 s of the sanitizer build so.
TEST_F(RenderCommand, EveryExampleSceneRenders) {
  int scenes = 0;
  fs::create_directories(path("copies"));
  // The meshes the scenes name, relative to them.
  fs::copy(fs::path(TUMBLE_SOURCE_DIR) / "scenes" / "models", path("copies/models"),
           fs::copy_options::recursive);
  for (const auto& entry : fs::directory_iterator(fs::path(TUMBLE_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    ++scenes;
    std::string text = read_file(entry.path());
    const std::size_t at = text.find("\nduration = ");
    if (at != std::string::npos) {
      const std::size_t end = text.find('\n', at + 1);
      text.replace(at, end - at, "\nduration = 2.0");
    }
    const fs::path copy = write("copies/" + entry.path().filename().string(), text);
    const Outcome run = tumble("render -q --no-video --width 96 --height 64 --frames 0:2 " +
                               copy.string() + " -o " + path("scenes"));
    EXPECT_EQ(run.exit_code, 0) << entry.path() << ": " << run.err;
  }
  EXPECT_GE(scenes, 5);
  int frames = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir_ / "scenes")) {
    // Frames only: poster.png and contact_sheet.png are written beside them.
    frames +=
        entry.path().extension() == ".png" && entry.path().parent_path().filename() == "frames";
  }
  EXPECT_EQ(frames, 2 * scenes);
}

TEST_F(RenderCommand, BadInputExitsWithTwo) {
  EXPECT_EQ(tumble("render " + path("missing.toml") + " -o " + path("o")).exit_code, 2);
  EXPECT_EQ(tumble("render --frames 10:20 " + scene() + " -o " + path("o")).exit_code, 2);
  EXPECT_EQ(tumble("render --frames 3 " + scene() + " -o " + path("o")).exit_code, 2);
  EXPECT_EQ(tumble("render --no-frames --no-video " + scene() + " -o " + path("o")).exit_code, 2);
  EXPECT_EQ(tumble("render --width 0 " + scene() + " -o " + path("o")).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "o/spin/spin.mp4"));
}

// report.json names the scene as rendered: the same file and options give the same hash; another
// file, or --width, another.
TEST_F(RenderCommand, ReportHashesTheSceneAsRenderedWithItsOverrides) {
  const auto hash = [&](const std::string& scene_path, const std::string& root,
                        const std::string& options) {
    const Outcome run = tumble("render -q --no-video --frames 0:1 " + scene_path + " -o " +
                               path(root) + " " + options);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const auto report = tumble::io::parse_json(read_file(dir_ / root / "spin/report.json"));
    EXPECT_TRUE(report) << report.error();
    const tumble::io::JsonValue* value = report ? report->find("scene_hash") : nullptr;
    return value ? value->string : std::string();
  };
  const std::string first = hash(scene(), "a", "");
  EXPECT_EQ(first.size(), 64u);
  EXPECT_EQ(first.find_first_not_of("0123456789abcdef"), std::string::npos) << first;
  EXPECT_EQ(hash(scene(), "b", ""), first);
  EXPECT_NE(hash(scene(), "c", "--width 162"), first);
  std::string other = kScene;
  other.replace(other.find("torque = [1.0"), 13, "torque = [2.0");
  fs::create_directories(dir_ / "other");
  EXPECT_NE(hash(write("other/spin.toml", other).string(), "d", ""), first);
}

// A chunk from frame 8 steps the physics to frame 8's time and no further before drawing: at
// 30 frames/s and dt = 0.01 s, ceil((8 / 30) / 0.01) = 27 steps, the steps a render of frames
// 0..8 takes; then it ends where the whole render ends (frame 14: ceil(46.67) = 47 steps).
TEST_F(RenderCommand, AChunkStepsThePhysicsOnlyUpToItsFirstFrame) {
  fs::create_directories(dir_ / "framed");
  const std::string framed =
      write("framed/spin.toml", std::string(kScene) +
                                    "[camera]\nposition = [0.0, 1.5, 4.0]\nlook_at = [0.0, 0.0, "
                                    "0.0]\n[ground]\nheight = -1.5\n")
          .string();
  const auto steps = [&](const std::string& frames, const std::string& root) {
    const Outcome run = tumble("render -q --no-video " + framed + " -o " + path(root) +
                               " --width 64 --height 36 --frames " + frames);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const auto report = tumble::io::parse_json(read_file(dir_ / root / "spin/report.json"));
    EXPECT_TRUE(report) << report.error();
    return report ? *report->find("physics_steps") : tumble::io::JsonValue();
  };
  const tumble::io::JsonValue chunk = steps("8:15", "chunk");
  ASSERT_NE(chunk.find("framing"), nullptr);
  EXPECT_EQ(chunk.find("framing")->number, 0);  // camera and ground written: no framing pass
  EXPECT_EQ(chunk.find("to_first_frame")->number, 27);
  EXPECT_EQ(chunk.find("to_first_frame")->number, steps("0:9", "head").find("frames")->number);
  EXPECT_EQ(chunk.find("frames")->number, 47);
  EXPECT_EQ(chunk.find("frames")->number, steps("0:15", "whole").find("frames")->number);
  EXPECT_EQ(steps("0:15", "again").find("to_first_frame")->number, 0);
}

// [render] backend chooses the off-screen OpenGL, and --backend overrides it; report.json names
// the one that drew.
TEST_F(RenderCommand, SceneBackendKeyChoosesTheOpenGLAndTheOptionOverridesIt) {
  using tumble::render::Backend;
  if (!tumble::render::backend_built(Backend::osmesa) ||
      !tumble::render::backend_built(Backend::egl)) {
    GTEST_SKIP() << "this build lacks a back end";
  }
  const std::string egl = write("egl.toml", std::string(kScene) + "backend = \"egl\"\n").string();
  const auto renderer = [&](const std::string& root, const std::string& options) {
    const Outcome run = tumble("render -q --no-video --frames 0:1 --width 64 --height 36 " + egl +
                               " -o " + path(root) + " " + options);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return read_file(dir_ / root / "spin/report.json");
  };
  EXPECT_NE(renderer("scene", "").find("(EGL surfaceless)\""), std::string::npos);
  EXPECT_NE(renderer("option", "--backend osmesa").find("(OSMesa)\""), std::string::npos);
}

// Every file of a render folder below `folder` (frames/ included), by name, with its bytes.
std::map<std::string, std::string> files_of(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) {
      files[fs::relative(entry.path(), folder).string()] = read_file(entry.path());
    }
  }
  return files;
}

// The README's advice: a small GIF rendered in a run of its own into the same -o. The second
// run writes the GIF and keeps every file of the first that it does not write, byte for byte,
// and report.json says which render each kept file came from.
TEST_F(RenderCommand, AGifRenderedApartKeepsTheEarlierMp4FramesAndStills) {
  const std::string small = write("small.toml", tumble::testing::spin_scene(64, 36)).string();
  ASSERT_EQ(tumble("render -q " + small + " --format mp4 -o " + path("out")).exit_code, 0);
  std::map<std::string, std::string> first = files_of(dir_ / "out/spin");
  first.erase("report.json");
  ASSERT_EQ(first.size(), 15u + 3u);  // frames, spin.mp4, poster.png, contact_sheet.png

  const Outcome gif = tumble("render " + small +
                             " --format gif --width 48 --height 28 --no-frames -o " + path("out"));
  ASSERT_EQ(gif.exit_code, 0) << gif.err;
  std::map<std::string, std::string> second = files_of(dir_ / "out/spin");
  ASSERT_TRUE(second.count("spin.gif"));
  second.erase("spin.gif");
  second.erase("report.json");
  EXPECT_EQ(second, first);  // the same names and the same bytes
  EXPECT_NE(gif.err.find(path("out/spin") + "/: spin.gif, report.json\n"), std::string::npos)
      << gif.err;
  EXPECT_NE(gif.err.find("kept of the earlier render of this scene in " + path("out/spin") +
                         "/: frames/, spin.mp4, poster.png, contact_sheet.png\n"),
            std::string::npos)
      << gif.err;
  const auto report = tumble::io::parse_json(read_file(dir_ / "out/spin/report.json"));
  ASSERT_TRUE(report) << report.error();
  const tumble::io::JsonValue* kept = report->find("kept");
  ASSERT_TRUE(kept);
  ASSERT_EQ(kept->items.size(), 4u);
  EXPECT_EQ(kept->items[1].find("file")->string, "spin.mp4");
  EXPECT_EQ(kept->items[1].find("from")->find("width")->number, 64);
  EXPECT_EQ(report->find("videos")->text, "{\"gif\": \"" + path("out/spin/spin.gif") + "\"}");
  EXPECT_EQ(report->find("frames_directory")->kind, tumble::io::JsonValue::Kind::null);

  // A third run at the first size writes its own MP4 and keeps the GIF of the second, whose
  // origin is the second run's size, and the frames of the first.
  const Outcome mp4 = tumble("render -q " + small + " --format mp4 --no-frames -o " + path("out"));
  ASSERT_EQ(mp4.exit_code, 0) << mp4.err;
  const auto third = tumble::io::parse_json(read_file(dir_ / "out/spin/report.json"));
  ASSERT_TRUE(third) << third.error();
  const tumble::io::JsonValue& kept_third = *third->find("kept");
  ASSERT_EQ(kept_third.items.size(), 2u);
  EXPECT_EQ(kept_third.items[0].find("file")->string, "frames");
  EXPECT_EQ(kept_third.items[0].find("from")->find("width")->number, 64);
  EXPECT_EQ(kept_third.items[1].find("file")->string, "spin.gif");
  EXPECT_EQ(kept_third.items[1].find("from")->find("width")->number, 48);
  EXPECT_TRUE(fs::exists(dir_ / "out/spin/poster.png"));  // its own, with the MP4
  EXPECT_EQ(files_of(dir_ / "out/spin").size(), 15u + 5u);
}

// --format gltf writes <scene>.glb beside the videos: named in the summary and in report.json's
// "gltf" (not among its "videos"), kept by a later render that does not write it, and written
// under --no-video, since it is no video.
TEST_F(RenderCommand, AGltfIsListedInTheReportAndKeptByALaterRender) {
  const std::string small = write("small.toml", tumble::testing::spin_scene(64, 36)).string();
  const Outcome both =
      tumble("render " + small + " --format mp4,gltf --no-frames -o " + path("out"));
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_NE(both.err.find(path("out/spin") +
                          "/: spin.mp4, spin.glb, poster.png, contact_sheet.png, report.json\n"),
            std::string::npos)
      << both.err;
  const std::string glb = read_file(dir_ / "out/spin/spin.glb");
  ASSERT_GT(glb.size(), 12u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  const auto report = tumble::io::parse_json(read_file(dir_ / "out/spin/report.json"));
  ASSERT_TRUE(report) << report.error();
  EXPECT_EQ(report->find("gltf")->string, path("out/spin/spin.glb"));
  EXPECT_EQ(report->find("videos")->text, "{\"mp4\": \"" + path("out/spin/spin.mp4") + "\"}");
  EXPECT_EQ(report->find("settings")->find("formats")->text, "[\"mp4\", \"gltf\"]");

  const Outcome mp4 = tumble("render " + small + " --format mp4 --no-frames -o " + path("out"));
  ASSERT_EQ(mp4.exit_code, 0) << mp4.err;
  EXPECT_NE(mp4.err.find("kept of the earlier render of this scene in " + path("out/spin") +
                         "/: spin.glb\n"),
            std::string::npos)
      << mp4.err;
  EXPECT_EQ(read_file(dir_ / "out/spin/spin.glb"), glb);
  const auto second = tumble::io::parse_json(read_file(dir_ / "out/spin/report.json"));
  ASSERT_TRUE(second) << second.error();
  EXPECT_EQ(second->find("gltf")->kind, tumble::io::JsonValue::Kind::null);

  fs::remove_all(dir_ / "out");
  const Outcome alone =
      tumble("render -q " + small + " --format gltf --no-video --no-frames -o " + path("out"));
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_EQ(read_file(dir_ / "out/spin/spin.glb"), glb);  // the same bytes again
  EXPECT_FALSE(fs::exists(dir_ / "out/spin/spin.mp4"));
}

// Another scene file in the folder's place: replaced as a whole, as before, and said.
TEST_F(RenderCommand, ARenderOfAnotherSceneReplacesTheFolderWholeAndSaysSo) {
  const std::string small = write("small.toml", tumble::testing::spin_scene(64, 36)).string();
  ASSERT_EQ(tumble("render -q " + small + " --format mp4 -o " + path("out")).exit_code, 0);
  const std::string edited =
      write("small.toml", tumble::testing::spin_scene(64, 36) + "# edited\n").string();
  const Outcome gif = tumble("render " + edited + " --format gif --no-frames -o " + path("out"));
  ASSERT_EQ(gif.exit_code, 0) << gif.err;
  EXPECT_NE(gif.err.find(path("out/spin") + " holds a render of another scene file"),
            std::string::npos)
      << gif.err;
  EXPECT_NE(gif.err.find("it is replaced as a whole, nothing of it kept"), std::string::npos);
  std::map<std::string, std::string> files = files_of(dir_ / "out/spin");
  EXPECT_EQ(files.size(), 4u);  // spin.gif, poster.png, contact_sheet.png, report.json
  EXPECT_TRUE(files.count("spin.gif"));
  EXPECT_FALSE(files.count("spin.mp4"));
  EXPECT_NE(files["report.json"].find("\"kept\": []"), std::string::npos);
}

TEST_F(RenderCommand, VersionFlagAndReportNameTheProjectVersion) {
  const Outcome version = tumble("--version");
  EXPECT_EQ(version.exit_code, 0) << version.err;
  EXPECT_EQ(version.out, "tumble " TUMBLE_VERSION "\n");
  EXPECT_EQ(std::string(TUMBLE_VERSION).find_first_not_of("0123456789."), std::string::npos);
  ASSERT_EQ(tumble("render -q --no-video --frames 0:1 " + scene() + " -o " + path("o")).exit_code,
            0);
  EXPECT_NE(read_file(dir_ / "o/spin/report.json").find("\"version\": \"" TUMBLE_VERSION "\""),
            std::string::npos);
}

// 2.6 s at 25 frames/s, 64x36: 65 frames. At 25 frames/s a GIF shows every frame (4 cs each).
std::string gif_scene(const std::string& output) {
  std::string text = tumble::testing::spin_scene(64, 36, tumble::testing::kTorqueX);
  text.replace(text.find("duration = 0.5"), 14, "duration = 2.6");
  text.replace(text.find("fps = 30"), 8, "fps = 25");
  return text + "[output]\nformats = [\"gif\"]\nframes = false\n" + output;
}

// --frames A:B writes a GIF of those frames alone, with a palette of its own.
TEST_F(RenderCommand, AGifOfAFrameRangeHoldsThoseFrames) {
  const Outcome run = tumble("render -q " + write("gif.toml", gif_scene("")).string() +
                             " --frames 30:60 -o " + path("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto gif = tumble::testing::read_video(path("out/spin/spin.gif"));
  ASSERT_EQ(gif.error, "");
  EXPECT_EQ(gif.codec, AV_CODEC_ID_GIF);
  EXPECT_EQ(gif.pictures.size(), 30u);
  EXPECT_NEAR(gif.duration, 30 * 0.04, 1e-9);
}

// gif_colors, gif_fps and gif_dither change the GIF as they say; a scene without them gives the
// GIF it gave before they existed (its filters' text is unchanged; see io/video_encoder.cpp).
TEST_F(RenderCommand, GifKeysChooseColoursRateAndDithering) {
  const auto gif_of = [&](const std::string& name, const std::string& output) {
    const Outcome run = tumble("render -q " + write(name + ".toml", gif_scene(output)).string() +
                               " --frames 0:30 -o " + path(name));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return read_file(dir_ / name / "spin/spin.gif");
  };
  const std::string full = gif_of("full", "");
  const std::string few = gif_of("few", "gif_colors = 32\n");
  std::printf("[ measured ] GIF of 30 frames at 64x36: %zu bytes at 256 colours, %zu at 32\n",
              full.size(), few.size());
  EXPECT_LT(few.size(), full.size());
  EXPECT_EQ(gif_of("same", "gif_colors = 256\ngif_dither = \"bayer\"\n"), full);
  EXPECT_NE(gif_of("plain", "gif_dither = \"none\"\n"), full);
  EXPECT_NE(gif_of("diffused", "gif_dither = \"floyd_steinberg\"\n"), full);
  // 10 frames/s: a GIF frame every 10 cs shows video frame round(2.5 j), j = 0 .. 11, of 30.
  gif_of("slow", "gif_fps = 10\n");
  const auto slow = tumble::testing::read_video(path("slow/spin/spin.gif"));
  ASSERT_EQ(slow.error, "");
  EXPECT_EQ(slow.pictures.size(), 12u);
  EXPECT_NE(read_file(dir_ / "slow/spin/report.json")
                .find("\"gif\": {\"fps\": 10, \"colors\": 256, \"dither\": \"bayer\"}"),
            std::string::npos);
}

}  // namespace
