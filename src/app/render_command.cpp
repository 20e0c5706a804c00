#include "app/render_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <variant>

#include <algorithm>
#include <thread>

#include "app/exit_codes.hpp"
#include "app/interrupt.hpp"
#include "app/json_text.hpp"
#include "app/output_folder.hpp"
#include "app/progress.hpp"
#include "app/render_job.hpp"
#include "app/stability_report.hpp"
#include "io/atomic_file.hpp"
#include "io/staged_directory.hpp"
#include "scene/scene_loader.hpp"
#include "scene/video_rules.hpp"

namespace tumble::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string stage_json(const StageTime& stage) {
  std::ostringstream out;
  out.precision(6);
  out << "{\"cpu\": " << stage.cpu << ", \"wall\": " << stage.wall << "}";
  return out.str();
}

std::string report_json(const scene::Scene& scene, const RenderPlan& plan,
                        const RenderResult& result, double total_seconds) {
  const PipelineReport& p = result.pipeline;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // (CPU seconds of every stage / cores) / wall seconds: 1 when every core worked all the time.
  const double efficiency = p.wall > 0 ? p.process_cpu / cores / p.wall : 0.0;
  std::ostringstream out;
  out.precision(17);
  // This first line is how a folder is known for a render's (output_folder.cpp): keep it.
  out << "{\n  \"scene\": " << json_string(scene.name)
      << ",\n  \"scene_file\": " << json_string(scene.source_path)
      << ",\n  \"width\": " << scene.render.width << ",\n  \"height\": " << scene.render.height
      << ",\n  \"fps\": " << scene.fps << ",\n  \"msaa\": " << scene.render.msaa
      << ",\n  \"antialiasing\": " << json_string(antialiasing_name(scene.render.msaa))
      << ",\n  \"dt\": " << scene.physics.dt << ",\n  \"integrator\": "
      << json_string(std::string(physics::integrator_name(scene.physics.integrator)))
      << ",\n  \"frames\": {\"first\": " << plan.first << ", \"end\": " << plan.end
      << ", \"count\": " << plan.end - plan.first << "},\n  \"frames_directory\": "
      << (plan.frames_directory.empty() ? "null" : json_string(plan.frames_directory))
      << ",\n  \"video\": " << (plan.video_path.empty() ? "null" : json_string(plan.video_path))
      << ",\n  \"path\": " << (plan.serial ? "\"serial\"" : "\"pipelined\"")
      << ",\n  \"renderer\": " << json_string(result.renderer)
      << ",\n  \"stages\": {\"simulate\": " << stage_json(p.simulate)
      << ", \"render\": " << stage_json(p.render) << ", \"png\": " << stage_json(p.png)
      << ", \"video\": " << stage_json(p.video)
      << "},\n  \"seconds\": {\"setup\": " << result.setup_seconds << ", \"frames\": " << p.wall
      << ", \"finish\": " << result.finish_seconds << ", \"total\": " << total_seconds
      << "},\n  \"frames_per_second\": " << (p.wall > 0 ? p.frames_done / p.wall : 0.0)
      << ",\n  \"cores\": " << cores << ",\n  \"pipeline_efficiency\": " << efficiency
      << ",\n  \"peak_memory_bytes\": " << peak_memory_bytes() << ",\n  \"bodies\": [";
  for (std::size_t i = 0; i < result.bodies.size(); ++i) {
    const BodyDiagnostics& b = result.bodies[i];
    out << (i ? "," : "") << "\n    {\"name\": " << json_string(scene.bodies[i].name)
        << ", \"energy_start\": " << json_number(b.energy_start)
        << ", \"energy_end\": " << json_number(b.energy_end)
        << ", \"angular_momentum_start\": " << json_number(b.angular_momentum_start)
        << ", \"angular_momentum_end\": " << json_number(b.angular_momentum_end) << "}";
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
  install_interrupt_handlers();  // from the start: a signal is acted on before the first frame
  // Spelt one way throughout ("a/../b" is "b"), as StagedDirectory spells it.
  const fs::path root = fs::path(options.output_root).lexically_normal();
  const scene::SceneOrError loaded = scene::load_scene_file(options.scene_path);
  if (const auto* error = std::get_if<scene::SceneError>(&loaded)) {
    std::fprintf(err, "tumble: %s\n", error->message.c_str());
    return kExitBadInput;
  }
  scene::Scene scene = std::get<scene::Scene>(loaded);
  if (options.width) scene.render.width = *options.width;
  if (options.height) scene.render.height = *options.height;
  if (options.fps) scene.fps = *options.fps;
  if (!options.frames) scene.output.frames = false;
  if (!options.video) scene.output.video = false;
  // The loaded scene kept every rule: what breaks one now is an override.
  if (const std::optional<scene::BrokenRule> broken = scene::broken_video_rule(scene)) {
    std::fprintf(err, "tumble: %s: %s, as the command line sets it: %s\n",
                 scene.source_path.c_str(), broken->keys.front().c_str(), broken->problem.c_str());
    return kExitBadInput;
  }
  if (!options.quiet) print_stability_warnings(scene, err);
  const bool write_frames = scene.output.frames;
  const bool write_video = scene.output.video;
  const std::int64_t total = scene::frame_count(scene);
  const std::int64_t first = options.first_frame.value_or(0);
  const std::int64_t end = options.end_frame.value_or(total);
  if (first < 0 || end > total || first >= end) {
    std::fprintf(err, "tumble: --frames %lld:%lld is outside the scene's frames 0:%lld\n",
                 static_cast<long long>(first), static_cast<long long>(end),
                 static_cast<long long>(total));
    return kExitBadInput;
  }
  const std::string shader_directory = find_shader_directory();
  if (shader_directory.empty()) {
    if (const char* asked = std::getenv("TUMBLE_SHADER_DIR")) {
      std::fprintf(err, "tumble: no shaders (body.vert) in TUMBLE_SHADER_DIR=%s\n", asked);
    } else {
      std::fprintf(err, "tumble: cannot find the shaders/ folder (set TUMBLE_SHADER_DIR)\n");
    }
    return kExitBadInput;
  }

  // Everything is written into a hidden folder beside the final one and swapped in at the end:
  // a failed or interrupted render leaves the earlier output as it was.
  const fs::path directory = root / scene.output.directory;
  if (const std::string problem = replace_problem(root, scene.output.directory); !problem.empty()) {
    std::fprintf(err, "tumble: %s\n", problem.c_str());
    return kExitBadInput;
  }
  io::StagedDirectory staged(directory.string());
  const fs::path staging = staged.path();
  std::string setup_error = staged.error();
  if (setup_error.empty() && write_frames) {
    std::error_code error_code;
    fs::create_directory(staging / "frames", error_code);
    if (error_code) {
      setup_error = "cannot create " + (staging / "frames").string() + ": " + error_code.message();
    }
  }
  if (!setup_error.empty()) {
    std::fprintf(err, "tumble: %s\n", setup_error.c_str());
    return kExitBadInput;
  }
  const std::string video_name = scene.name + ".mp4";
  RenderPlan plan{.first = first,
                  .end = end,
                  .frames_directory = write_frames ? (staging / "frames").string() : "",
                  .video_path = write_video ? (staging / video_name).string() : "",
                  .png = options.png,
                  .serial = options.serial,
                  .shader_directory = shader_directory};
  plan.stop_requested = [] { return interrupt_signal() != 0; };
  Progress progress(end - first, options.quiet, err);
  plan.on_frame_done = [&](std::int64_t done) { progress.update(done); };
  const RenderResult result = render_scene(scene, plan);
  progress.finish();
  if (options.verbose && !result.renderer.empty()) {
    std::fprintf(err, "tumble: renderer %s\n", result.renderer.c_str());
  }
  const auto stopped = [&](const std::string& why) {
    std::fprintf(err, "tumble: %s after %lld of %lld frames; %s was left as it was\n", why.c_str(),
                 static_cast<long long>(result.pipeline.frames_done),
                 static_cast<long long>(end - first), directory.c_str());
  };
  if (const int signal = interrupt_signal()) {
    stopped(std::string("stopped by ") + signal_name(signal));
    return kExitInterrupted + signal;
  }
  if (!result.error.empty()) {
    std::fprintf(err, "tumble: %s\n", result.error.c_str());
    stopped("render failed");
    return kExitBadInput;
  }

  // The report names the final paths, where the files will be once the folder is in place.
  RenderPlan final_paths = plan;
  final_paths.frames_directory = write_frames ? (directory / "frames").string() : "";
  final_paths.video_path = write_video ? (directory / video_name).string() : "";
  const double total_seconds = seconds_since(start);
  std::string error = write_text_file((staging / "report.json").string(),
                                      report_json(scene, final_paths, result, total_seconds));
  // Checked again: the folder may have been made or filled while the frames were drawn.
  if (error.empty()) error = replace_problem(root, scene.output.directory);
  if (error.empty() && !staged.commit()) error = staged.error();
  if (!error.empty()) {
    std::fprintf(err, "tumble: %s\n", error.c_str());
    stopped("render failed");
    return kExitBadInput;
  }
  if (!staged.leftover().empty())
    std::fprintf(err, "tumble: warning: %s\n", staged.leftover().c_str());
  if (!options.quiet) {
    std::fprintf(
        err, "tumble: %lld frames in %.1f s (%.1f frames/s) -> %s\n",
        static_cast<long long>(end - first), total_seconds,
        static_cast<double>(end - first) / total_seconds,
        write_video ? final_paths.video_path.c_str() : final_paths.frames_directory.c_str());
  }
  return kExitOk;
}

}  // namespace tumble::app
