// What in a frame depends on the machine: llvmpipe's SIMD width (LP_NATIVE_VECTOR_WIDTH=128 is
// what a machine without AVX gets) and its rasterizer threads (LP_NUM_THREADS). The same frames
// rendered under each must be the default run's, byte for byte, for a golden drawn on one machine
// to hold on another with the same Mesa (docs/commands.md, "Goldens across machines").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/command_test.hpp"

namespace tumble::testing {
namespace {

class LlvmpipeSettings : public CommandTest {};

// scenes/cube_in_a_box.toml cut to its first second: a shadowed cube, a gridded floor and four
// walls, two of them seen from the back (translucent); with the default edge filter or 4 samples.
std::string cube_in_a_box(bool multisampled) {
  std::string scene = read_file(std::string(TUMBLE_SOURCE_DIR) + "/scenes/cube_in_a_box.toml");
  const std::string duration = "duration = 5.0";
  scene.replace(scene.find(duration), duration.size(), "duration = 1.0");
  if (multisampled) scene += "\n[render]\nmsaa = 4\n";
  return scene;
}

TEST_F(LlvmpipeSettings, GiveTheDefaultRunsFramesByteForByte) {
  const std::vector<std::string> settings = {"LP_NATIVE_VECTOR_WIDTH=128", "LP_NUM_THREADS=1",
                                             "LP_NUM_THREADS=2", "LP_NUM_THREADS=4"};
  for (const bool multisampled : {false, true}) {
    SCOPED_TRACE(multisampled ? "msaa 4" : "edge filter");
    write("scene.toml", cube_in_a_box(multisampled));
    const auto render = [&](const std::string& folder, const std::string& environment) {
      const Outcome outcome = tumble("render " + path("scene.toml") + " -o " + path(folder) +
                                         " --width 320 --height 180 --frames 20:23 --no-video",
                                     "exec env " + environment + " ");
      EXPECT_EQ(outcome.exit_code, 0) << environment << ": " << outcome.err;
      std::vector<std::string> frames;
      for (int k = 20; k < 23; ++k) {
        frames.push_back(read_file(fs::path(path(folder)) / "cube_in_a_box" / "frames" /
                                   ("frame_000" + std::to_string(k) + ".png")));
      }
      return frames;
    };
    const std::vector<std::string> reference = render("default", "TUMBLE_UNUSED=1");
    for (const std::string& frame : reference) ASSERT_GT(frame.size(), 1000u);
    for (const std::string& environment : settings) {
      const std::vector<std::string> frames = render(environment, environment);
      // The setting took: report.json names the renderer, with its SIMD width.
      const std::string report =
          read_file(fs::path(path(environment)) / "cube_in_a_box" / "report.json");
      if (environment == "LP_NATIVE_VECTOR_WIDTH=128") {
        EXPECT_NE(report.find("llvmpipe (LLVM"), std::string::npos) << report;
        EXPECT_NE(report.find("128 bits"), std::string::npos) << report;
      }
      for (std::size_t k = 0; k < frames.size(); ++k) {
        EXPECT_TRUE(frames[k] == reference[k]) << environment << ", frame " << 20 + k;
      }
    }
  }
}

// --backend picks the off-screen OpenGL; report.json names the one that drew, and OSMesa's and
// EGL's frames are the same bytes.
TEST_F(LlvmpipeSettings, BackendOptionChoosesTheOffscreenOpenGLAndTheFramesAgree) {
  write("scene.toml", cube_in_a_box(false));
  std::string frames[2];
  const char* names[2] = {"osmesa", "egl"};
  const char* says[2] = {"(OSMesa)", "(EGL surfaceless)"};
  for (int i = 0; i < 2; ++i) {
    const Outcome outcome =
        tumble("render " + path("scene.toml") + " -o " + path(names[i]) +
               " --width 320 --height 180 --frames 20:21 --no-video -q" + " --backend " + names[i]);
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    const fs::path folder = fs::path(path(names[i])) / "cube_in_a_box";
    EXPECT_NE(read_file(folder / "report.json").find(says[i]), std::string::npos);
    frames[i] = read_file(folder / "frames" / "frame_00020.png");
  }
  EXPECT_GT(frames[0].size(), 1000u);
  EXPECT_TRUE(frames[0] == frames[1]);
  const Outcome bad = tumble("render " + path("scene.toml") + " --backend vulkan");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--backend: vulkan not in {auto,osmesa,egl}"), std::string::npos)
      << bad.err;
}

// --egl-device N draws through EGL's device platform on device N (here Mesa's software device,
// the one EGL lists on a machine without a GPU): report.json and the summary name the back end
// and the device, the frame is OSMesa's byte for byte, and nothing needs a display (DISPLAY and
// WAYLAND_DISPLAY name ones that do not exist). A device EGL does not list, or one named for
// OSMesa, is an error (exit 2) that leaves no output.
TEST_F(LlvmpipeSettings, EglDeviceOptionDrawsOnThatDeviceWithoutADisplay) {
  write("scene.toml", cube_in_a_box(false));
  const std::string render =
      "render " + path("scene.toml") + " --width 320 --height 180 --frames 20:21 --no-video -o ";
  const std::string no_display = "exec env DISPLAY=:97 WAYLAND_DISPLAY=tumble-none ";
  const Outcome osmesa = tumble(render + path("osmesa") + " -q --backend osmesa");
  ASSERT_EQ(osmesa.exit_code, 0) << osmesa.err;
  const Outcome device = tumble(render + path("device") + " --egl-device 0", no_display);
  ASSERT_EQ(device.exit_code, 0) << device.err;
  const fs::path folder = fs::path(path("device")) / "cube_in_a_box";
  const std::string report = read_file(folder / "report.json");
  EXPECT_NE(report.find("\"backend\": \"egl\""), std::string::npos) << report;
  EXPECT_NE(report.find("\"device\": \"device 0 of "), std::string::npos) << report;
  EXPECT_NE(device.err.find("frames/s, egl, device 0 of "), std::string::npos) << device.err;
  if (report.find("Mesa software") != std::string::npos) {
    EXPECT_TRUE(
        read_file(folder / "frames" / "frame_00020.png") ==
        read_file(fs::path(path("osmesa")) / "cube_in_a_box" / "frames" / "frame_00020.png"));
  }
  const Outcome surfaceless = tumble(render + path("surfaceless") + " --backend egl", no_display);
  ASSERT_EQ(surfaceless.exit_code, 0) << surfaceless.err;
  EXPECT_NE(surfaceless.err.find("frames/s, egl, surfaceless)"), std::string::npos)
      << surfaceless.err;

  const Outcome unlisted = tumble(render + path("unlisted") + " --egl-device 255");
  EXPECT_EQ(unlisted.exit_code, 2);
  EXPECT_NE(unlisted.err.find("egl_device 255: no such EGL device (this machine's: 0: "),
            std::string::npos)
      << unlisted.err;
  EXPECT_FALSE(fs::exists(path("unlisted")) && !fs::is_empty(path("unlisted")));
  const Outcome for_osmesa =
      tumble(render + path("contradiction") + " --backend osmesa --egl-device 0");
  EXPECT_EQ(for_osmesa.exit_code, 2);
  EXPECT_NE(for_osmesa.err.find("is for the egl back end, not osmesa"), std::string::npos)
      << for_osmesa.err;
}

}  // namespace
}  // namespace tumble::testing
