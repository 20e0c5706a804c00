// Segments of one video joined by stream copy against the same video encoded whole: the same
// frame count, timestamps and length, and every decoded frame within a stated distance of the
// whole's; and every way a set of segments can be wrong refused, with nothing written.
#include "io/video_join.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/video_encoder.hpp"
#include "support/result_text.hpp"
#include "support/test_frames.hpp"
#include "support/video_reader.hpp"

namespace tumble::io {
namespace {

namespace fs = std::filesystem;
using testing::moving_pattern;
using testing::read_video;
using testing::rms_difference;

constexpr int kWidth = 160, kHeight = 120, kFps = 30, kFrames = 40;

class VideoJoinTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    directory_ =
        fs::temp_directory_path() / ("tumble-join-" + std::to_string(::getpid()) + "-" + test);
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  std::string path(const std::string& name) const { return (directory_ / name).string(); }

  // Frames [first, end) of the moving pattern as a video at `name` (its format by its extension).
  std::string encode(const std::string& name, int first, int end, bool segment = true) const {
    std::string error;
    const VideoFormat format = name.ends_with(".webm") ? VideoFormat::webm : VideoFormat::mp4;
    const auto encoder = ::tumble::testing::value_or_empty(
        VideoEncoder::open(path(name), {.format = format,
                                        .width = kWidth,
                                        .height = kHeight,
                                        .fps = kFps,
                                        .segment = segment,
                                        .first_frame = segment ? first : 0}),
        error);
    EXPECT_NE(encoder, nullptr) << error;
    if (!encoder) return {};
    for (int k = first; k < end; ++k) {
      EXPECT_EQ(
          ::tumble::testing::error_text(encoder->add_frame(moving_pattern(kWidth, kHeight, k))),
          "");
    }
    EXPECT_EQ(::tumble::testing::error_text(encoder->finish()), "");
    return path(name);
  }

  // The pattern as segments a, b and c (`extension`: ".mp4" or ".webm") of frames 0-16, 17 (one
  // frame) and 18 on; b's own record of its place checked.
  std::vector<std::string> three_segments(const std::string& extension) const {
    const std::vector<std::string> parts = {encode("a" + extension, 0, 17),
                                            encode("b" + extension, 17, 18),
                                            encode("c" + extension, 18, kFrames)};
    VideoSegmentInfo b;
    EXPECT_EQ(::tumble::testing::take(read_segment_info(parts[1]), b), "");
    EXPECT_EQ(b.first_frame, 17);
    EXPECT_EQ(b.frames, 1);
    EXPECT_EQ(b.fps, kFps);
    return parts;
  }

  fs::path directory_;
};

// Three uneven segments, one of a single frame.
TEST_F(VideoJoinTest, JoinedSegmentsDecodeAsTheWholeVideo) {
  const std::string whole = encode("whole.mp4", 0, kFrames, false);
  const std::vector<std::string> parts = three_segments(".mp4");
  ASSERT_EQ(::tumble::testing::error_text(join_videos(parts, path("joined.mp4"))), "");
  const testing::DecodedVideo joined = read_video(path("joined.mp4"));
  const testing::DecodedVideo reference = read_video(whole);
  ASSERT_EQ(joined.error, "");
  ASSERT_EQ(reference.error, "");
  EXPECT_EQ(joined.width, kWidth);
  EXPECT_EQ(av_cmp_q(joined.avg_frame_rate, AVRational{kFps, 1}), 0);
  EXPECT_NEAR(joined.duration, reference.duration, 1e-9);
  EXPECT_NEAR(joined.duration, static_cast<double>(kFrames) / kFps, 0.5 / kFps);
  ASSERT_EQ(joined.pictures.size(), static_cast<std::size_t>(kFrames));
  // Each segment is its own encode (its own IDR frame and rate control), so its frames are not
  // the whole encode's bits: the stated bound is on the distance of each decoded frame from the
  // whole's, RMS over all channels, and from the source it was encoded from.
  double worst_from_whole = 0.0, worst_from_source = 0.0;
  for (int k = 0; k < kFrames; ++k) {
    const auto j = static_cast<std::size_t>(k);
    EXPECT_NEAR(joined.pictures[j].time, static_cast<double>(k) / kFps, 1e-9) << "frame " << k;
    EXPECT_NEAR(joined.pictures[j].time, reference.pictures[j].time, 1e-9) << "frame " << k;
    worst_from_whole = std::max(worst_from_whole,
                                rms_difference(joined.pictures[j].rgb, reference.pictures[j].rgb));
    worst_from_source =
        std::max(worst_from_source,
                 rms_difference(joined.pictures[j].rgb, moving_pattern(kWidth, kHeight, k)));
  }
  std::printf(
      "[ measured ] joined frames: RMS at most %.2f from the whole encode's, %.2f from "
      "the source\n",
      worst_from_whole, worst_from_source);
  EXPECT_LT(worst_from_whole, 3.0);   // measured 2.52
  EXPECT_LT(worst_from_source, 2.5);  // measured 2.25
  // The frames are in their places: a frame against its neighbour differs by far more.
  EXPECT_GT(rms_difference(joined.pictures[17].rgb, reference.pictures[20].rgb), 3 * 3.0);
}

// VP9 segments in WebM, one of a single frame, join into a WebM of the whole's frames and times.
TEST_F(VideoJoinTest, WebmSegmentsJoinIntoTheWholeWebm) {
  const std::vector<std::string> parts = three_segments(".webm");
  ASSERT_EQ(::tumble::testing::error_text(join_videos(parts, path("joined.webm"))), "");
  const testing::DecodedVideo joined = read_video(path("joined.webm"));
  ASSERT_EQ(joined.error, "");
  ASSERT_EQ(joined.pictures.size(), static_cast<std::size_t>(kFrames));
  EXPECT_NEAR(joined.duration, static_cast<double>(kFrames) / kFps, 1e-3);  // milliseconds
  double worst_from_source = 0.0;
  for (int k = 0; k < kFrames; ++k) {
    const auto j = static_cast<std::size_t>(k);
    EXPECT_NEAR(joined.pictures[j].time, static_cast<double>(k) / kFps, 1e-3) << "frame " << k;
    worst_from_source =
        std::max(worst_from_source,
                 rms_difference(joined.pictures[j].rgb, moving_pattern(kWidth, kHeight, k)));
  }
  std::printf("[ measured ] joined WebM frames: RMS at most %.2f from the source\n",
              worst_from_source);
  EXPECT_LT(worst_from_source, 4.0);
  // Each frame is in its place: frame 17 (segment b's one frame) is far from frame 20.
  EXPECT_GT(rms_difference(joined.pictures[17].rgb, moving_pattern(kWidth, kHeight, 20)), 12.0);
  // H.264 and VP9 segments do not join.
  const std::string error = ::tumble::testing::error_text(
      join_videos({encode("a.mp4", 0, 17), parts[1]}, path("mixed.mp4")));
  EXPECT_NE(error.find("b.webm: is VP9, " + path("a.mp4") + " H.264"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(path("mixed.mp4")));
}

TEST_F(VideoJoinTest, RefusesAGapAnOverlapAnotherEncodeAndATruncatedSegment) {
  const std::string a = encode("a.mp4", 0, 10), b = encode("b.mp4", 10, 20);
  const std::string late = encode("late.mp4", 12, 20), early = encode("early.mp4", 8, 20);
  const std::string plain = encode("plain.mp4", 0, 10, false);
  const auto refused = [&](const std::vector<std::string>& parts, const std::string& says) {
    const std::string error = ::tumble::testing::error_text(join_videos(parts, path("joined.mp4")));
    EXPECT_NE(error.find(says), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(path("joined.mp4")));
  };
  refused({a, late}, "frames 10 to 11 are missing");
  refused({a, early}, "frames overlap");
  refused({b}, "starts at frame 10, where frame 0 comes next");
  refused({plain, b}, "stream headers differ");  // not written as a segment
  // A copy cut short: its index still lists every frame.
  const std::string cut = path("cut.mp4");
  fs::copy_file(b, cut);
  fs::resize_file(cut, fs::file_size(cut) - 2000);
  refused({a, cut}, "cut.mp4");
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(directory_)) {
    left.push_back(entry.path().filename().string());
  }
  EXPECT_EQ(left.size(), 6u);  // the inputs only: no partial file
}

}  // namespace
}  // namespace tumble::io
