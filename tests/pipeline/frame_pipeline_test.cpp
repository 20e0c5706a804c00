// The frame loop: frames pulled from a source, drawn, pushed to every sink in order, on one
// thread or pipelined with the same results; an error from the source or any sink stops it.
#include "pipeline/frame_pipeline.hpp"
#include "support/result_text.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace tumble::pipeline {
namespace {

// A cube that turns a little each frame, so that every frame's picture differs.
class TurningCube final : public FrameSource {
 public:
  explicit TurningCube(std::int64_t fail_at = -1) : fail_at_(fail_at) {}
  Result<render::FrameView> view(std::int64_t frame) override {
    if (frame == fail_at_) return Error{"the source failed at frame " + std::to_string(frame)};
    render::FrameView view;
    view.boxes.push_back(
        render::Box{.orientation = render::Quat(Eigen::AngleAxisd(0.1 * static_cast<double>(frame),
                                                                  render::Vec3::UnitY()))});
    return view;
  }

 private:
  std::int64_t fail_at_;
};

// Keeps what it was given: the frame numbers and pictures, in the order they came.
class Recorder final : public FrameSink {
 public:
  explicit Recorder(std::int64_t fail_at = -1) : fail_at_(fail_at) {}
  const char* stage() const override { return "record"; }
  Result<void> write(std::int64_t frame, const io::Image& image) override {
    if (frame == fail_at_) return Error{"the sink failed at frame " + std::to_string(frame)};
    frames.push_back(frame);
    pictures.push_back(image.rgb);
    return Result<void>::success();
  }
  std::vector<std::int64_t> frames;
  std::vector<std::vector<std::uint8_t>> pictures;

 private:
  std::int64_t fail_at_;
};

std::unique_ptr<render::Renderer> small_renderer() {
  render::RenderSettings settings;
  settings.width = 32;
  settings.height = 24;
  std::string error;
  auto renderer = ::tumble::testing::value_or_empty(
      render::Renderer::create(settings, std::string(TUMBLE_SOURCE_DIR) + "/shaders"), error);
  EXPECT_TRUE(renderer) << error;
  return renderer;
}

TEST(FramePipeline, EverySinkSeesEveryFrameInOrderTheSameOnBothPaths) {
  const std::unique_ptr<render::Renderer> renderer = small_renderer();
  ASSERT_TRUE(renderer);
  std::vector<std::vector<std::uint8_t>> serial_pictures;
  for (const bool serial : {true, false}) {
    SCOPED_TRACE(serial ? "serial" : "pipelined");
    TurningCube source;
    Recorder first, second, third;
    std::int64_t done = 0;
    PipelineReport report;
    const Result<void> ran = run_frames(
        2, 12, source, *renderer, {&first, &second, &third}, serial,
        [&](std::int64_t n) { done = n; }, report);
    ASSERT_TRUE(ran.ok()) << ran.error();
    EXPECT_EQ(report.frames_done, 10);
    EXPECT_EQ(done, 10);
    ASSERT_EQ(report.sinks.size(), 3u);
    for (const Recorder* sink : {&first, &second, &third}) {
      EXPECT_EQ(sink->frames, (std::vector<std::int64_t>{2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
      EXPECT_EQ(sink->pictures, first.pictures);
    }
    EXPECT_NE(first.pictures.front(), first.pictures.back());
    if (serial) serial_pictures = first.pictures;
    EXPECT_EQ(first.pictures, serial_pictures);
  }
}

TEST(FramePipeline, AnErrorFromTheSourceOrASinkStopsTheRunWithItsMessage) {
  const std::unique_ptr<render::Renderer> renderer = small_renderer();
  ASSERT_TRUE(renderer);
  for (const bool serial : {true, false}) {
    SCOPED_TRACE(serial ? "serial" : "pipelined");
    TurningCube failing_source(5);
    Recorder sink;
    PipelineReport from_source;
    EXPECT_EQ(
        ::tumble::testing::error_text(run_frames(
            0, 10, failing_source, *renderer, {&sink}, serial, [](std::int64_t) {}, from_source)),
        "the source failed at frame 5");
    EXPECT_LE(from_source.frames_done, 5);

    TurningCube source;
    Recorder failing_sink(3), other;
    PipelineReport from_sink;
    EXPECT_EQ(::tumble::testing::error_text(run_frames(
                  0, 10, source, *renderer, {&other, &failing_sink}, serial, [](std::int64_t) {},
                  from_sink)),
              "the sink failed at frame 3");
    EXPECT_LE(from_sink.frames_done, 3);
    EXPECT_EQ(failing_sink.frames, (std::vector<std::int64_t>{0, 1, 2}));
  }
}

}  // namespace
}  // namespace tumble::pipeline
