#include "app/render_job.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "app/scene_view.hpp"
#include "io/video_encoder.hpp"
#include "render/renderer.hpp"
#include "scene/scene_builder.hpp"
#include "scene/video_rules.hpp"

namespace tumble::app {
namespace {

namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::string find_shader_directory() {
  std::error_code ignored;
  // Asked for by name: that folder or none, never a silent fall-back to another one.
  if (const char* env = std::getenv("TUMBLE_SHADER_DIR")) {
    return fs::exists(fs::path(env) / "body.vert", ignored) ? std::string(env) : std::string();
  }
  std::vector<fs::path> candidates;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ignored);
  if (!executable.empty()) {
    candidates.push_back(executable.parent_path().parent_path() / "share/tumble/shaders");
  }
  candidates.emplace_back(TUMBLE_SOURCE_SHADER_DIR);
  for (const fs::path& candidate : candidates) {
    if (fs::exists(candidate / "body.vert", ignored)) return candidate.string();
  }
  return {};
}

std::string antialiasing_name(int msaa) {
  if (msaa == render::kEdgeFilter) return "edge filter";
  return msaa == 1 ? "none" : "MSAA " + std::to_string(msaa);
}

std::int64_t peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::int64_t>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

RenderResult render_scene(const scene::Scene& scene, const RenderPlan& plan) {
  RenderResult result;
  const auto setup_start = std::chrono::steady_clock::now();
  const std::int64_t total = scene::frame_count(scene);
  Framing framing;
  try {
    framing = frame_scene(scene, total, plan.stop_requested);
  } catch (const RenderStopped& stopped) {
    result.error = stopped.what();
    return result;
  }
  // The automatic back end, and no font: no scene draws text yet.
  render::RenderSettings settings{scene.render, render::Backend::automatic, std::string()};
  settings.ground = framing.ground;

  const std::unique_ptr<render::Renderer> renderer =
      render::Renderer::create(settings, plan.shader_directory, result.error);
  if (!renderer) {
    // Mostly what the scene asks of this OpenGL ([render] msaa beyond its samples): name it.
    result.error = scene.source_path + ": " + result.error;
    return result;
  }
  result.renderer = renderer->description();

  std::unique_ptr<io::VideoEncoder> encoder;
  if (!plan.video_path.empty()) {
    encoder = io::VideoEncoder::open(plan.video_path,
                                     {.width = settings.width,
                                      .height = settings.height,
                                      .fps = scene.fps,
                                      .crf = scene.output.crf,
                                      .preset = scene.output.preset},
                                     result.error);
    if (!encoder) return result;
  }

  sim::Simulation simulation = scene::build_simulation(scene);
  for (const physics::BodyState& state : simulation.current()) {
    result.bodies.push_back({.energy_start = physics::kinetic_energy(state),
                             .angular_momentum_start = state.angular_momentum().norm()});
  }
  result.setup_seconds = seconds_since(setup_start);

  const FrameSource source{
      .view =
          [&](std::int64_t k) {
            const double t = static_cast<double>(k) / scene.fps;
            return frame_view(scene, framing,
                              checked_states_at(simulation, scene, t, plan.stop_requested), t);
          },
      .draw = [&](const render::FrameView& view,
                  io::Image& image) { renderer->draw(view, image); }};
  FrameSinks sinks;
  if (!plan.frames_directory.empty()) {
    sinks.png = [&](std::int64_t k, const io::Image& image) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05lld.png", static_cast<long long>(k));
      return io::write_png((fs::path(plan.frames_directory) / name).string(), image, plan.png);
    };
  }
  if (encoder) {
    sinks.video = [&](const io::Image& image) { return encoder->add_frame(image); };
  }
  result.pipeline =
      run_frames(plan.first, plan.end, source, sinks, plan.serial, plan.on_frame_done);
  if (!result.pipeline.error.empty()) {
    result.error = result.pipeline.error;
    return result;  // the encoder's destructor removes its partial file
  }

  const auto finish_start = std::chrono::steady_clock::now();
  if (encoder) result.error = encoder->finish();
  result.finish_seconds = seconds_since(finish_start);
  for (std::size_t i = 0; i < result.bodies.size(); ++i) {
    result.bodies[i].energy_end = physics::kinetic_energy(simulation.current()[i]);
    result.bodies[i].angular_momentum_end = simulation.current()[i].angular_momentum().norm();
  }
  return result;
}

}  // namespace tumble::app
