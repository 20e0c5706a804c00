#include "app/render_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <variant>

#include "app/progress.hpp"
#include "app/scene_view.hpp"
#include "app/exit_codes.hpp"
#include "io/atomic_file.hpp"
#include "io/png_io.hpp"
#include "io/video_encoder.hpp"
#include "render/renderer.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"

namespace tumble::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// shaders/ is looked for beside an installed binary, then in the source tree this binary was
// built from; TUMBLE_SHADER_DIR overrides both.
std::string find_shader_directory() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("TUMBLE_SHADER_DIR")) candidates.emplace_back(env);
  std::error_code ignored;
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

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

struct StageTimes {
  double simulate = 0.0;  // s, wall
  double render = 0.0;
  double png = 0.0;
  double video = 0.0;
};

struct BodyDiagnostics {
  double energy_start, energy_end;                      // J
  double angular_momentum_start, angular_momentum_end;  // |L| (kg m²/s)
};

std::string report_json(const scene::Scene& scene, std::int64_t first, std::int64_t end,
                        const std::string& frames_directory, const std::string& video_path,
                        const StageTimes& times, double total_seconds, const std::string& renderer,
                        const std::vector<BodyDiagnostics>& bodies) {
  std::ostringstream out;
  out.precision(17);
  const std::int64_t count = end - first;
  out << "{\n  \"scene\": " << json_string(scene.name)
      << ",\n  \"scene_file\": " << json_string(scene.source_path)
      << ",\n  \"width\": " << scene.render.width << ",\n  \"height\": " << scene.render.height
      << ",\n  \"fps\": " << scene.fps << ",\n  \"msaa\": " << scene.render.msaa
      << ",\n  \"dt\": " << scene.physics.dt << ",\n  \"integrator\": "
      << json_string(std::string(physics::integrator_name(scene.physics.integrator)))
      << ",\n  \"frames\": {\"first\": " << first << ", \"end\": " << end
      << ", \"count\": " << count << "},\n  \"frames_directory\": "
      << (frames_directory.empty() ? "null" : json_string(frames_directory))
      << ",\n  \"video\": " << (video_path.empty() ? "null" : json_string(video_path))
      << ",\n  \"renderer\": " << json_string(renderer)
      << ",\n  \"seconds\": {\"simulate\": " << times.simulate << ", \"render\": " << times.render
      << ", \"png\": " << times.png << ", \"video\": " << times.video
      << ", \"total\": " << total_seconds
      << "},\n  \"frames_per_second\": " << (total_seconds > 0 ? count / total_seconds : 0.0)
      << ",\n  \"bodies\": [";
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BodyDiagnostics& b = bodies[i];
    out << (i ? "," : "") << "\n    {\"name\": " << json_string(scene.bodies[i].name)
        << ", \"energy_start\": " << b.energy_start << ", \"energy_end\": " << b.energy_end
        << ", \"angular_momentum_start\": " << b.angular_momentum_start
        << ", \"angular_momentum_end\": " << b.angular_momentum_end << "}";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

std::string write_text_file(const std::string& path, const std::string& text) {
  io::AtomicFile file(path);
  if (!file.ok()) return file.error();
  std::fwrite(text.data(), 1, text.size(), file.stream());
  return file.commit() ? std::string() : file.error();
}

}  // namespace

int run_render(const RenderOptions& options, std::FILE* err) {
  const auto start = Clock::now();
  const scene::SceneOrError loaded = scene::load_scene_file(options.scene_path);
  if (const auto* error = std::get_if<scene::SceneError>(&loaded)) {
    std::fprintf(err, "tumble: %s\n", error->message.c_str());
    return kExitBadInput;
  }
  scene::Scene scene = std::get<scene::Scene>(loaded);
  if (options.width) scene.render.width = *options.width;
  if (options.height) scene.render.height = *options.height;
  if (options.fps) scene.fps = *options.fps;
  const bool write_frames = options.frames && scene.output.frames;
  const bool write_video = options.video && scene.output.video;
  if (!write_frames && !write_video) {
    std::fprintf(err, "tumble: nothing to write: frames and video are both off\n");
    return kExitBadInput;
  }
  if (write_video && (scene.render.width % 2 || scene.render.height % 2)) {
    std::fprintf(err,
                 "tumble: width and height must be even for H.264 yuv420p video (got %dx%d); "
                 "change them or render frames only with --no-video\n",
                 scene.render.width, scene.render.height);
    return kExitBadInput;
  }

  const std::int64_t total = std::llround(scene.duration * scene.fps);
  const std::int64_t first = options.first_frame.value_or(0);
  const std::int64_t end = options.end_frame.value_or(total);
  if (first < 0 || end > total || first >= end) {
    std::fprintf(err, "tumble: --frames %lld:%lld is outside the scene's frames 0:%lld\n",
                 static_cast<long long>(first), static_cast<long long>(end),
                 static_cast<long long>(total));
    return kExitBadInput;
  }

  const fs::path directory = fs::path(options.output_root) / scene.output.directory;
  const fs::path frames_directory = directory / "frames";
  std::error_code error_code;
  fs::create_directories(write_frames ? frames_directory : directory, error_code);
  if (error_code) {
    std::fprintf(err, "tumble: cannot create output folder %s: %s\n",
                 (write_frames ? frames_directory : directory).c_str(),
                 error_code.message().c_str());
    return kExitBadInput;
  }

  const std::string shader_directory = find_shader_directory();
  if (shader_directory.empty()) {
    std::fprintf(err, "tumble: cannot find the shaders/ folder (set TUMBLE_SHADER_DIR)\n");
    return kExitBadInput;
  }
  std::string error;
  render::RenderSettings settings = scene.render;
  StageTimes times;
  auto stage_start = Clock::now();
  const Framing framing = frame_scene(scene, total);
  settings.ground.height = framing.ground_height;
  times.simulate += seconds_since(stage_start);

  const std::unique_ptr<render::Renderer> renderer =
      render::Renderer::create(settings, shader_directory, error);
  if (!renderer) {
    std::fprintf(err, "tumble: %s\n", error.c_str());
    return kExitBadInput;
  }
  if (options.verbose) std::fprintf(err, "tumble: renderer %s\n", renderer->description().c_str());

  const std::string video_path = (directory / (scene.name + ".mp4")).string();
  std::unique_ptr<io::VideoEncoder> encoder;
  if (write_video) {
    encoder = io::VideoEncoder::open(video_path,
                                     {.width = settings.width,
                                      .height = settings.height,
                                      .fps = scene.fps,
                                      .crf = scene.output.crf,
                                      .preset = scene.output.preset},
                                     error);
    if (!encoder) {
      std::fprintf(err, "tumble: %s\n", error.c_str());
      return kExitBadInput;
    }
  }

  sim::Simulation simulation = scene::build_simulation(scene);
  std::vector<BodyDiagnostics> diagnostics;
  for (const physics::BodyState& state : simulation.current()) {
    diagnostics.push_back(
        {physics::kinetic_energy(state), 0.0, state.angular_momentum().norm(), 0.0});
  }
  Progress progress(end - first, options.quiet, err);
  io::Image image;
  for (std::int64_t k = first; k < end; ++k) {
    stage_start = Clock::now();
    const double t = static_cast<double>(k) / scene.fps;
    const render::FrameView view = frame_view(scene, framing, simulation.states_at(t), t);
    times.simulate += seconds_since(stage_start);

    stage_start = Clock::now();
    renderer->draw(view, image);
    times.render += seconds_since(stage_start);

    if (write_frames) {
      stage_start = Clock::now();
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05lld.png", static_cast<long long>(k));
      error = io::write_png((frames_directory / name).string(), image);
      times.png += seconds_since(stage_start);
      if (!error.empty()) {
        std::fprintf(err, "\ntumble: %s\n", error.c_str());
        return kExitBadInput;
      }
    }
    if (encoder) {
      stage_start = Clock::now();
      error = encoder->add_frame(image);
      times.video += seconds_since(stage_start);
      if (!error.empty()) {
        std::fprintf(err, "\ntumble: %s\n", error.c_str());
        return kExitBadInput;
      }
    }
    progress.update(k - first + 1);
  }
  if (encoder) {
    stage_start = Clock::now();
    error = encoder->finish();
    times.video += seconds_since(stage_start);
    if (!error.empty()) {
      progress.finish();
      std::fprintf(err, "tumble: %s\n", error.c_str());
      return kExitBadInput;
    }
  }
  progress.finish();
  for (std::size_t i = 0; i < diagnostics.size(); ++i) {
    diagnostics[i].energy_end = physics::kinetic_energy(simulation.current()[i]);
    diagnostics[i].angular_momentum_end = simulation.current()[i].angular_momentum().norm();
  }

  const double total_seconds = seconds_since(start);
  error =
      write_text_file((directory / "report.json").string(),
                      report_json(scene, first, end, write_frames ? frames_directory.string() : "",
                                  write_video ? video_path : "", times, total_seconds,
                                  renderer->description(), diagnostics));
  if (!error.empty()) {
    std::fprintf(err, "tumble: %s\n", error.c_str());
    return kExitBadInput;
  }
  if (!options.quiet) {
    std::fprintf(err, "tumble: %lld frames in %.1f s (%.1f frames/s) -> %s\n",
                 static_cast<long long>(end - first), total_seconds,
                 static_cast<double>(end - first) / total_seconds,
                 write_video ? video_path.c_str() : frames_directory.c_str());
  }
  return kExitOk;
}

}  // namespace tumble::app
