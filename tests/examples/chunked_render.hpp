// What the render-farm examples' tests share: a tiny scene, a run of any program the way a user's
// shell runs it, and the check that a joined render equals a whole render of the same scene.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "diff/image_diff.hpp"
#include "io/png_io.hpp"
#include "support/command_test.hpp"
#include "support/result_text.hpp"
#include "support/video_reader.hpp"

namespace tumble::testing {

// 0.4 s at 30 frames/s: 12 frames of a cube spinning up at 64x36, so that a chunked render, its
// join and a whole render take a few seconds together (3 chunks of 4 frames). It turns about
// 0.33 rad a frame, so that each frame differs plainly from the next.
inline constexpr const char* kTinyScene = R"(name = "tiny"
duration = 0.4
[physics]
dt = 0.01
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
angular_velocity = [0.0, 9.0, 4.0]
[[bodies.forces]]
kind = "torque"
torque = [1.0, 0.0, 0.0]
[render]
width = 64
height = 36
fps = 30
)";
inline constexpr int kTinyFrames = 12;

inline std::string frame_name(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", k);
  return name;
}

// The names in `folder`, sorted (directory order is the file system's).
inline std::vector<std::string> names_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The decoded `picture` against every PNG in `frames`: the RMS channel difference (0-255) to each.
inline std::vector<double> rms_to_each_frame(const Image& picture,
                                             const std::filesystem::path& frames) {
  std::vector<double> rms;
  for (int k = 0; k < kTinyFrames; ++k) {
    Image png;
    EXPECT_EQ(::tumble::testing::take(io::read_png((frames / frame_name(k)).string()), png), "");
    rms.push_back(png.width == picture.width && png.height == picture.height
                      ? diff::compare_images(png, picture, {.threshold = 255, .max_pixels = 0}).rms
                      : 255.0);
  }
  return rms;
}

// The render folder `joined` (from an example) against `whole` (one `tumble render` of the same
// scene): the same PNG files byte for byte; an MP4 with the same frame count, presentation times
// and duration; each decoded frame k within RMS 10 of 255 of PNG k (what H.264 at tumble's CRF
// loses on a 64x36 frame full of edges: measured 5.6 to 7.5 on the joined MP4 of 3 chunks, 6.0 to
// 7.6 on the whole render's own) and nearer to PNG k than to any other frame's PNG (measured 11.5
// at least), so no frame is missing, doubled or out of place; a report.json.
inline void expect_joined_equals_whole(const std::filesystem::path& joined,
                                       const std::filesystem::path& whole) {
  ASSERT_EQ(names_in(joined / "frames").size(), static_cast<std::size_t>(kTinyFrames));
  EXPECT_EQ(names_in(joined / "frames"), names_in(whole / "frames"));
  for (int k = 0; k < kTinyFrames; ++k) {
    EXPECT_EQ(read_file(joined / "frames" / frame_name(k)),
              read_file(whole / "frames" / frame_name(k)))
        << "frame " << k;
  }

  const DecodedVideo video = read_video((joined / "tiny.mp4").string());
  const DecodedVideo reference = read_video((whole / "tiny.mp4").string());
  ASSERT_EQ(video.error, "");
  ASSERT_EQ(reference.error, "");
  ASSERT_EQ(video.pictures.size(), static_cast<std::size_t>(kTinyFrames));
  ASSERT_EQ(reference.pictures.size(), static_cast<std::size_t>(kTinyFrames));
  EXPECT_EQ(video.duration, reference.duration);
  for (int k = 0; k < kTinyFrames; ++k) {
    EXPECT_EQ(video.pictures[k].time, reference.pictures[k].time) << "decoded frame " << k;
    const std::vector<double> rms = rms_to_each_frame(video.pictures[k].rgb, whole / "frames");
    EXPECT_LT(rms[k], 10.0) << "decoded frame " << k;
    EXPECT_EQ(std::min_element(rms.begin(), rms.end()) - rms.begin(), k)
        << "decoded frame " << k << " looks most like another frame";
  }
  EXPECT_TRUE(std::filesystem::is_regular_file(joined / "report.json"));
}

}  // namespace tumble::testing
