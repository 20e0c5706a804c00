// The cost of text over a frame (Google Benchmark; not run by ctest):
//   build/render_bench [--benchmark_repetitions=5]
// One cube at 720p with the default ground, shadows and edge filter, drawn without text and
// with three texts (a boxed two-line live value, a caption, a label), the values changing every
// frame as a documentation video's do. The ratio of the two is what text costs the render stage.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>

#include "render/renderer.hpp"

namespace {

using namespace tumble::render;

const std::string kShaders = std::string(TUMBLE_SOURCE_DIR) + "/shaders";

std::unique_ptr<Renderer> make_renderer() {
  RenderSettings settings;  // 1280 × 720, edge filter, ground and shadows
  settings.font = std::string(kDefaultFontFamily);
  std::string error;
  auto renderer = Renderer::create(settings, kShaders, error);
  if (!renderer) std::fprintf(stderr, "render_bench: %s\n", error.c_str());
  return renderer;
}

// The cube turning frame by frame, as in scenes/spinning_cube.toml.
FrameView cube_frame(int frame) {
  FrameView view;
  view.boxes.push_back(Box{.orientation = Quat(Eigen::AngleAxisd(0.05 * frame, Vec3::UnitX()))});
  return view;
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), pattern, value);
  return text;
}

void add_three_texts(FrameView& view, int frame) {
  const double t = frame / 60.0;  // s
  view.texts.push_back(
      Text{.text = format("\xCF\x89 = %.2f rad/s", 10.0 * (1.0 - 1.0 / (1.0 + t))) +
                   format("   t = %.2f s\n\xCF\x84 = 1.00 N\xC2\xB7m   ", t) +
                   format("\xCE\x94"
                          "E = %.3f J",
                          0.001 * frame),
           .anchor = Anchor::kTopLeft,
           .offset = Eigen::Vector2d(24.0, 24.0),
           .height = 32.0,
           .background = Rgba(0.0, 0.0, 0.0, 0.5)});
  view.texts.push_back(Text{.text = "Spinning cube: torque against angular damping",
                            .anchor = Anchor::kBottom,
                            .offset = Eigen::Vector2d(0.0, -24.0),
                            .height = 28.0,
                            .color = Rgba(0.1, 0.1, 0.2, 1.0)});
  view.texts.push_back(Text{.text = format("|L| = %.3f kg\xC2\xB7m\xC2\xB2/s", 1.0 + 0.01 * frame),
                            .anchor = Anchor::kTopRight,
                            .offset = Eigen::Vector2d(-24.0, 24.0),
                            .height = 24.0,
                            .opacity = 0.8});
}

void draw_frames(benchmark::State& state, bool with_text) {
  const auto renderer = make_renderer();
  if (!renderer) {
    state.SkipWithError("no renderer");
    return;
  }
  tumble::io::Image image;
  int frame = 0;
  for (auto _ : state) {
    FrameView view = cube_frame(frame);
    if (with_text) add_three_texts(view, frame);
    renderer->draw(view, image);
    benchmark::DoNotOptimize(image.rgb.data());
    ++frame;
  }
}

void BM_Frame720pWithoutText(benchmark::State& state) {
  draw_frames(state, false);
}
void BM_Frame720pWithThreeTexts(benchmark::State& state) {
  draw_frames(state, true);
}

BENCHMARK(BM_Frame720pWithoutText)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Frame720pWithThreeTexts)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
