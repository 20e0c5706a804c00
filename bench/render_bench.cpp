// The cost of text and overlays over a frame, and of the default look (Google Benchmark; not run
// by ctest):
//   build/render_bench --benchmark_filter=CostPerFrame --benchmark_repetitions=5
//   --benchmark_min_time=1
//   build/render_bench --benchmark_filter='Look|FourK' --benchmark_min_time=2
//   build/render_bench --benchmark_filter=Png
// One cube at 720p with the default ground, shadows and edge filter, drawn without text and
// with three texts (a boxed two-line live value, a caption, a label), the values changing every
// frame as a documentation video's do: as two benchmarks, and alternated frame by frame on one
// renderer (BM_TextCostPerFrame720p), whose counters give the ratios of with to without, the
// render stage's cost of text. BM_OverlayCostPerFrame720p does the same with the budget
// case: the three texts, two vectors (ω and L) and a 2 s trail of a corner.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>

#include "io/png_io.hpp"
#include "render/renderer.hpp"

namespace {

using namespace tumble::render;

const std::string kShaders = std::string(TUMBLE_SOURCE_DIR) + "/shaders";

std::unique_ptr<Renderer> make_renderer(RenderSettings settings = {}) {
  // 1280 × 720, edge filter, ground and shadows, the default look
  settings.font = std::string(kDefaultFontFamily);
  settings.overlays = true;
  tumble::Result<std::unique_ptr<Renderer>> renderer = Renderer::create(settings, kShaders);
  if (!renderer) {
    std::fprintf(stderr, "render_bench: %s\n", renderer.error().c_str());
    return nullptr;
  }
  return std::move(renderer).value();
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

// Two arrows from the cube's centre (its ω along x, growing, and a fixed L) and the path of a
// corner over the last 2 s at 60 fps, fading: what app/overlay_view.cpp makes of a scene's
// vector and trail overlays.
void add_vectors_and_trail(FrameView& view, int frame) {
  const double spin = 0.05 * frame;  // rad, as cube_frame turns it
  view.arrows.push_back(Arrow{.from = Vec3::Zero(),
                              .to = Vec3(1.0 + 0.002 * frame, 0.0, 0.0),
                              .color = Rgba(0.84, 0.15, 0.16, 1.0)});
  view.arrows.push_back(
      Arrow{.from = Vec3::Zero(), .to = Vec3(0.2, 1.1, 0.3), .color = Rgba(0.13, 0.38, 1.0, 1.0)});
  Polyline trail{.points = {}, .opacity = {}, .color = Rgba(1.0, 1.0, 1.0, 1.0)};
  for (int k = std::max(0, frame - 120); k <= frame; ++k) {
    const double angle = spin - 0.05 * (frame - k);
    trail.points.push_back(Quat(Eigen::AngleAxisd(angle, Vec3::UnitX())) * Vec3(0.5, 0.5, 0.5));
    trail.opacity.push_back(1.0 - (frame - k) / 120.0);
  }
  view.lines.push_back(std::move(trail));
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

// This process's CPU time, all threads (ms).
double process_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

// Per iteration: `prepare(frame)`, then `first()` and `second()` one after the other, each timed
// (wall, and the process's CPU: llvmpipe rasterises on threads of its own), so that a shared
// machine's load falls on both alike. The iteration's manual time is `iteration_ms(first's,
// second's)`. The sums, in ms, and the frame count.
struct TimesInTurn {
  double wall_first = 0.0, wall_second = 0.0, cpu_first = 0.0, cpu_second = 0.0;
  int frames = 0;
};
template <typename Prepare, typename First, typename Second, typename IterationMs>
TimesInTurn time_in_turn(benchmark::State& state, Prepare prepare, First first, Second second,
                         IterationMs iteration_ms) {
  using Clock = std::chrono::steady_clock;
  TimesInTurn out;
  for (auto _ : state) {
    prepare(out.frames);
    const auto start = Clock::now();
    const double cpu_start = process_cpu_ms();
    first();
    const auto middle = Clock::now();
    const double cpu_middle = process_cpu_ms();
    second();
    const auto end = Clock::now();
    const double one = std::chrono::duration<double, std::milli>(middle - start).count();
    const double two = std::chrono::duration<double, std::milli>(end - middle).count();
    out.cpu_first += cpu_middle - cpu_start;
    out.cpu_second += process_cpu_ms() - cpu_middle;
    out.wall_first += one;
    out.wall_second += two;
    state.SetIterationTime(1e-3 * iteration_ms(one, two));
    ++out.frames;
  }
  return out;
}

// The same frame without and with `add` (the texts, or every overlay) on one renderer. The
// iteration's time is what they add (wall); the counters give the ratios of with to without,
// wall and CPU: the render stage's cost of them as a fraction.
void alternate(benchmark::State& state, void (*add)(FrameView&, int)) {
  const auto renderer = make_renderer();
  if (!renderer) {
    state.SkipWithError("no renderer");
    return;
  }
  tumble::io::Image image;
  FrameView view;
  int frame = 0;
  const TimesInTurn times = time_in_turn(
      state,
      [&](int k) {
        frame = k;
        view = cube_frame(k);
      },
      [&] { renderer->draw(view, image); },
      [&] {
        add(view, frame);
        renderer->draw(view, image);
      },
      [](double without, double with) { return with - without; });
  state.counters["wall_ratio"] = times.wall_second / times.wall_first;
  state.counters["cpu_ratio"] = times.cpu_second / times.cpu_first;
  state.counters["ms_without"] = times.wall_first / times.frames;
}

void BM_TextCostPerFrame720p(benchmark::State& state) {
  alternate(state, add_three_texts);
}

void BM_OverlayCostPerFrame720p(benchmark::State& state) {
  alternate(state, [](FrameView& view, int frame) {
    add_three_texts(view, frame);
    add_vectors_and_trail(view, frame);
  });
}

// The arrows alone and the trail alone, for the share of each (not matched by CostPerFrame).
void BM_TwoArrowsCost720p(benchmark::State& state) {
  alternate(state, [](FrameView& view, int frame) {
    add_vectors_and_trail(view, frame);
    view.lines.clear();
  });
}
void BM_TrailCost720p(benchmark::State& state) {
  alternate(state, [](FrameView& view, int frame) {
    add_vectors_and_trail(view, frame);
    view.arrows.clear();
  });
}

// A settled pile: 1000 boxes of 0.15 to 0.3 m heaped in a cone on the ground (y = 0), turned
// every way, the camera above it as scenes/pile.toml's: the hard case of soft shadows (every box
// casts on its neighbours and the ground) and of occlusion (hundreds of boxes stand on the ground).
FrameView pile_frame(int frame) {
  FrameView view;
  view.camera.position = Vec3(5.0 + 0.01 * frame, 4.5, 7.0);
  view.camera.look_at = Vec3(0.0, 0.5, 0.0);
  for (int i = 0; i < 1000; ++i) {
    const auto fraction = [&](int salt) { return ((i * 37 + salt * 101) % 97) / 96.0; };
    const double radius = 1.6 * std::sqrt(fraction(1));
    const double angle = 6.283185 * fraction(2) + 0.1 * i;
    const double size = 0.15 + 0.15 * fraction(3);
    const double height = std::max(0.0, 1.2 * (1.0 - radius / 1.6)) * fraction(4) + 0.5 * size;
    view.boxes.push_back(
        Box{.position = Vec3(radius * std::cos(angle), height, radius * std::sin(angle)),
            .orientation = Quat(Eigen::AngleAxisd(
                6.0 * fraction(5), Vec3(fraction(6) - 0.5, 0.5, fraction(7) - 0.5).normalized())),
            .size = Vec3(size, size, size),
            .color = Color(0.2 + 0.6 * fraction(8), 0.3, 0.8 - 0.5 * fraction(8))});
  }
  return view;
}

// Two renderers of the same frames drawn in turn, frame by frame: the iteration's time is the
// second's (wall); the counters give the ratios of the second to the first, wall and CPU, and each
// one's ms per frame.
void alternate_renderers(benchmark::State& state, const RenderSettings& first,
                         const RenderSettings& second, FrameView (*frame_at)(int)) {
  const auto a = make_renderer(first);
  const auto b = make_renderer(second);
  if (!a || !b) {
    state.SkipWithError("no renderer");
    return;
  }
  tumble::io::Image image;
  FrameView view;
  const TimesInTurn times = time_in_turn(
      state, [&](int frame) { view = frame_at(frame); }, [&] { a->draw(view, image); },
      [&] { b->draw(view, image); }, [](double, double with) { return with; });
  state.counters["wall_ratio"] = times.wall_second / times.wall_first;
  state.counters["cpu_ratio"] = times.cpu_second / times.cpu_first;
  state.counters["ms_first"] = times.wall_first / times.frames;
  state.counters["ms_second"] = times.wall_second / times.frames;
}

RenderSettings plain_look() {
  RenderSettings settings;
  settings.look = tumble::common::Look::plain();
  return settings;
}

// The default look against the plain one (the look of before soft shadows, occlusion and
// exposure): the budget is 1.3 times.
void BM_LookCostPerFrame720p(benchmark::State& state) {
  alternate_renderers(state, plain_look(), RenderSettings{}, cube_frame);
}
void BM_LookCostPerFrame720pPile(benchmark::State& state) {
  alternate_renderers(state, plain_look(), RenderSettings{}, pile_frame);
}

// The default look without ambient occlusion against the default look, on the pile: what the
// occlusion of the ground and of the boxes by each other costs where it is dearest.
void BM_OcclusionCostPerFrame720pPile(benchmark::State& state) {
  RenderSettings without;
  without.look.ambient_occlusion = 0.0;
  alternate_renderers(state, without, RenderSettings{}, pile_frame);
}

// Each part of the default look alone against the plain look, on the cube: 0 soft shadows,
// 1 ambient occlusion, 2 the fill's contrast and the exposure.
void BM_LookPartCostPerFrame720p(benchmark::State& state) {
  RenderSettings part = plain_look();
  const tumble::common::Look look;
  if (state.range(0) == 0) part.look.shadow_softness = look.shadow_softness;
  if (state.range(0) == 1) part.look.ambient_occlusion = look.ambient_occlusion;
  if (state.range(0) == 2) {
    part.look.fill_light = look.fill_light;
    part.look.exposure = look.exposure;
  }
  alternate_renderers(state, plain_look(), part, cube_frame);
}

// 3840 × 2160 against 1280 × 720 in the default look: wall_ratio / 9 is the cost per pixel at 4K
// as a multiple of that at 720p (the budget: 1.2).
void BM_FourKAgainst720p(benchmark::State& state) {
  RenderSettings four_k;
  four_k.width = 3840;
  four_k.height = 2160;
  alternate_renderers(state, RenderSettings{}, four_k, cube_frame);
  if (state.counters.count("wall_ratio")) {
    state.counters["per_pixel_ratio"] = state.counters["wall_ratio"] / 9.0;
  }
}

// tumble's own PNG encoder against libpng with zlib level 1 unfiltered (the default before it),
// alternated on the same frame (the cube with its three texts): the iteration's time is the own
// encoder's; the counters give own / zlib for time (wall) and file size.
void BM_PngOwnAgainstZlib720p(benchmark::State& state) {
  const auto renderer = make_renderer();
  if (!renderer) {
    state.SkipWithError("no renderer");
    return;
  }
  const std::string folder = std::filesystem::temp_directory_path() / "tumble_render_bench_png";
  std::filesystem::create_directories(folder);
  tumble::io::Image image;
  FrameView view = cube_frame(30);
  add_three_texts(view, 30);
  renderer->draw(view, image);
  const tumble::io::PngSettings zlib{.own_encoder = false, .compression_level = 1};
  const auto write = [&](const char* name, const tumble::io::PngSettings& settings) {
    if (!tumble::io::write_png(folder + "/" + name, image, settings)) {
      state.SkipWithError("cannot write the PNG");
    }
  };
  const TimesInTurn times = time_in_turn(
      state, [](int) {}, [&] { write("own.png", {}); }, [&] { write("zlib.png", zlib); },
      [](double own, double) { return own; });
  state.counters["wall_ratio"] = times.wall_first / times.wall_second;
  state.counters["size_ratio"] =
      static_cast<double>(std::filesystem::file_size(folder + "/own.png")) /
      static_cast<double>(std::filesystem::file_size(folder + "/zlib.png"));
  std::filesystem::remove_all(folder);
}

void BM_Frame720pWithoutText(benchmark::State& state) {
  draw_frames(state, false);
}
void BM_Frame720pWithThreeTexts(benchmark::State& state) {
  draw_frames(state, true);
}

// Wall time per frame, and CPU time of the whole process (llvmpipe rasterises on threads of its
// own): on a shared machine the CPU time is the steadier figure of what text costs.
BENCHMARK(BM_Frame720pWithoutText)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(BM_Frame720pWithThreeTexts)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(BM_TextCostPerFrame720p)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_OverlayCostPerFrame720p)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_TwoArrowsCost720p)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_TrailCost720p)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_LookCostPerFrame720p)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_LookCostPerFrame720pPile)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_OcclusionCostPerFrame720pPile)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_LookPartCostPerFrame720p)
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();
BENCHMARK(BM_FourKAgainst720p)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_PngOwnAgainstZlib720p)->Unit(benchmark::kMillisecond)->UseManualTime();

}  // namespace

BENCHMARK_MAIN();
