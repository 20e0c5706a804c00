#include "app/render_job.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "app/contact_sheet.hpp"
#include "app/poster_sink.hpp"
#include "app/quality_preset.hpp"
#include "app/scene_view.hpp"
#include "app/video_sink.hpp"
#include "render/renderer.hpp"
#include "scene/video_rules.hpp"

namespace tumble::app {
namespace {

namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The scene with the command line's --quality and --format, checked.
Result<scene::Scene> with_choices(const RenderOptions& options, scene::Scene scene) {
  if (options.quality) {
    const std::optional<QualityPreset> preset = quality_preset(*options.quality);
    if (!preset) {
      return Error{"--quality: unknown preset \"" + *options.quality + "\" (" +
                   quality_preset_names() + ")"};
    }
    scene.render.width = preset->width;
    scene.render.height = preset->height;
    scene.fps = preset->fps;
  }
  if (options.formats.empty()) return scene;
  scene.output.formats.clear();
  for (const std::string& name : options.formats) {
    const std::optional<io::VideoFormat> format = common::video_format_named(name);
    if (!format) return Error{"--format: unknown format \"" + name + "\" (mp4, webm, gif)"};
    if (std::find(scene.output.formats.begin(), scene.output.formats.end(), *format) ==
        scene.output.formats.end()) {
      scene.output.formats.push_back(*format);
    }
  }
  return scene;
}

void apply_overrides(const RenderOptions& options, scene::Scene& scene) {
  if (options.width) scene.render.width = *options.width;
  if (options.height) scene.render.height = *options.height;
  if (options.fps) scene.fps = *options.fps;
  if (options.msaa) scene.render.msaa = *options.msaa;
  if (options.duration) scene.duration = *options.duration;
  if (options.preset) scene.output.preset = *options.preset;
  scene.output.frames = scene.output.frames && options.frames;
  scene.output.video = scene.output.video && options.video;
}

// Every output the job asks for, opened in `folder`.
Result<std::vector<std::unique_ptr<FrameSink>>> open_sinks(const RenderJob& job,
                                                           const fs::path& folder) {
  std::vector<std::unique_ptr<FrameSink>> sinks;
  const scene::Scene& scene = job.scene;
  if (scene.output.frames) {
    Result<std::unique_ptr<FrameSink>> png = PngFrames::open(job.frames_path(folder), job.png);
    if (!png) return Error{png.error()};
    sinks.push_back(std::move(*png));
  }
  for (const io::VideoFormat format :
       scene.output.video ? scene.output.formats : std::vector<io::VideoFormat>{}) {
    const io::VideoSettings settings{.format = format,
                                     .width = scene.render.width,
                                     .height = scene.render.height,
                                     .fps = scene.fps,
                                     .crf = scene.output.crf,
                                     .loop = scene.output.gif_loop,
                                     .alpha = scene.render.transparent,
                                     .preset = scene.output.preset};
    const std::string path = job.video_path(folder, format);
    Result<std::unique_ptr<FrameSink>> video = format == io::VideoFormat::mp4
                                                   ? Mp4Video::open(path, settings)
                                                   : VideoSink::open(path, settings);
    if (!video) return Error{video.error()};
    sinks.push_back(std::move(*video));
  }
  if (job.stills) {
    sinks.push_back(std::make_unique<PosterSink>((folder / "poster.png").string(),
                                                 scene::poster_frame(scene), job.png));
    sinks.push_back(std::make_unique<ContactSheet>((folder / "contact_sheet.png").string(),
                                                   job.first, job.end, scene.fps, job.png));
  }
  return sinks;
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

std::string RenderJob::frames_path(const fs::path& folder) const {
  return scene.output.frames ? (folder / "frames").string() : std::string();
}

std::string RenderJob::video_path(const fs::path& folder) const {
  return video_path(folder, io::VideoFormat::mp4);
}

std::string RenderJob::video_path(const fs::path& folder, io::VideoFormat format) const {
  const std::vector<io::VideoFormat>& formats = scene.output.formats;
  if (!scene.output.video || std::find(formats.begin(), formats.end(), format) == formats.end()) {
    return {};
  }
  return (folder / (scene.name + "." + io::video_format_name(format))).string();
}

Result<RenderJob> make_render_job(scene::Scene written, const RenderOptions& options) {
  Result<scene::Scene> chosen = with_choices(options, std::move(written));
  if (!chosen) return Error{chosen.error()};
  scene::Scene scene = std::move(*chosen);
  apply_overrides(options, scene);
  // The loaded scene kept every rule: what breaks one now is an override.
  if (const std::optional<scene::BrokenRule> broken = scene::broken_video_rule(scene)) {
    return Error{scene.source_path + ": " + broken->keys.front() +
                 ", as the command line sets it: " + broken->problem};
  }
  const std::int64_t total = scene::frame_count(scene);
  const std::int64_t first = options.first_frame.value_or(0);
  const std::int64_t end = options.end_frame.value_or(total);
  if (first < 0 || end > total || first >= end) {
    return Error{"--frames " + std::to_string(first) + ":" + std::to_string(end) +
                 " is outside the scene's frames 0:" + std::to_string(total)};
  }
  std::string shader_directory = find_shader_directory();
  if (shader_directory.empty()) {
    const char* asked = std::getenv("TUMBLE_SHADER_DIR");
    return Error{asked ? std::string("no shaders (body.vert) in TUMBLE_SHADER_DIR=") + asked
                       : "cannot find the shaders/ folder (set TUMBLE_SHADER_DIR)"};
  }
  const fs::path root = fs::path(options.output_root).lexically_normal();
  const fs::path directory = root / scene.output.directory;
  return RenderJob{.scene = std::move(scene),
                   .frame_count = total,
                   .first = first,
                   .end = end,
                   .output_root = root,
                   .directory = directory,
                   .png = options.png,
                   .serial = options.serial,
                   .backend = options.backend,
                   .shader_directory = std::move(shader_directory)};
}

RenderResult render_scene(const RenderJob& job, const fs::path& folder,
                          const std::function<bool()>& stop_requested,
                          const std::function<void(std::int64_t done)>& on_frame_done) {
  RenderResult result;
  const scene::Scene& scene = job.scene;
  const auto setup_start = std::chrono::steady_clock::now();
  Result<std::vector<std::unique_ptr<FrameSink>>> sinks = open_sinks(job, folder);
  if (!sinks) {
    result.error = sinks.error();
    return result;
  }
  const Result<Framing> framing = frame_scene(scene, job.frame_count, stop_requested);
  if (!framing) {
    result.error = framing.error();
    return result;
  }
  result.framing_steps = framing->physics_steps;
  // No font: no scene draws text yet.
  render::RenderSettings settings{scene.render, job.backend, std::string()};
  settings.ground = framing->ground;
  const std::unique_ptr<render::Renderer> renderer =
      render::Renderer::create(settings, job.shader_directory, result.error);
  if (!renderer) {
    // Mostly what the scene asks of this OpenGL ([render] msaa beyond its samples): name it.
    result.error = scene.source_path + ": " + result.error;
    return result;
  }
  result.renderer = renderer->description();
  SimulatedFrames source(scene, *framing, stop_requested);
  for (const physics::BodyState& state : source.simulation().current()) {
    result.bodies.push_back({.energy_start = physics::kinetic_energy(state),
                             .angular_momentum_start = state.angular_momentum().norm()});
  }
  std::vector<FrameSink*> sink_list;
  for (const std::unique_ptr<FrameSink>& sink : *sinks) {
    sink_list.push_back(sink.get());
    result.stages.push_back(sink->stage());
  }
  result.setup_seconds = seconds_since(setup_start);

  result.pipeline =
      run_frames(job.first, job.end, source, *renderer, sink_list, job.serial, on_frame_done);
  result.frame_steps = source.simulation().step_count();
  if (!result.pipeline.error.empty()) {
    result.error = result.pipeline.error;
    return result;  // each sink's destructor removes its partial file
  }
  const auto finish_start = std::chrono::steady_clock::now();
  for (FrameSink* sink : sink_list) {
    if (result.error.empty()) result.error = sink->finish();
  }
  result.finish_seconds = seconds_since(finish_start);
  for (std::size_t i = 0; i < result.bodies.size(); ++i) {
    const physics::BodyState& state = source.simulation().current()[i];
    result.bodies[i].energy_end = physics::kinetic_energy(state);
    result.bodies[i].angular_momentum_end = state.angular_momentum().norm();
  }
  return result;
}

}  // namespace tumble::app
