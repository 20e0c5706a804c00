#include "job/render_job.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "io/glb_writer.hpp"
#include "job/gltf_scene.hpp"
#include "job/html_replay.hpp"
#include "job/quality_preset.hpp"
#include "pipeline/contact_sheet.hpp"
#include "pipeline/poster_sink.hpp"
#include "render/renderer.hpp"
#include "scene/video_rules.hpp"
#include "view/overlay_view.hpp"
#include "view/scene_view.hpp"

namespace tumble::job {
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
  scene.output.gltf = false;
  scene.output.html = false;
  for (const std::string& name : options.formats) {
    if (bool* const file = scene::file_format_flag(scene.output, name)) {
      *file = true;
      continue;
    }
    const std::optional<io::VideoFormat> format = common::video_format_named(name);
    if (!format) {
      return Error{"--format: unknown format \"" + name + "\" (" + common::kFormatNames + ")"};
    }
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
  if (options.backend) scene.render.backend = *options.backend;
  if (options.egl_device) scene.render.egl_device = *options.egl_device;
  scene.output.frames = scene.output.frames && options.frames;
  scene.output.video = scene.output.video && options.video;
}

// Every output the job asks for, opened in `folder`.
Result<std::vector<std::unique_ptr<pipeline::FrameSink>>> open_sinks(const RenderJob& job,
                                                                     const fs::path& folder) {
  std::vector<std::unique_ptr<pipeline::FrameSink>> sinks;
  const scene::Scene& scene = job.scene;
  if (scene.output.frames) {
    Result<std::unique_ptr<pipeline::FrameSink>> png =
        pipeline::PngFrames::open(job.frames_path(folder), job.png);
    if (!png) return Error{png.error()};
    sinks.push_back(std::move(*png));
  }
  for (const io::VideoFormat format :
       scene.output.video ? scene.output.formats : std::vector<io::VideoFormat>{}) {
    // A GIF of part of the frames is a GIF of its own (its own palette), not a segment.
    const bool segment = job.partial() && common::joins_in_segments(format);
    const io::VideoSettings settings{.format = format,
                                     .width = scene.render.width,
                                     .height = scene.render.height,
                                     .fps = scene.fps,
                                     .crf = scene.output.crf,
                                     .vp9_crf = scene.output.webm_crf,
                                     .loop = scene.output.gif_loop,
                                     .gif_fps = scene.output.gif_fps.value_or(0),
                                     .gif_colors = scene.output.gif_colors,
                                     .gif_dither = scene.output.gif_dither,
                                     .alpha = scene.render.transparent,
                                     .segment = segment,
                                     .first_frame = segment ? job.first : 0,
                                     .preset = scene.output.preset};
    const std::string path = job.video_path(folder, format);
    Result<std::unique_ptr<pipeline::FrameSink>> video = pipeline::VideoSink::open(path, settings);
    if (!video) return Error{video.error()};
    sinks.push_back(std::move(*video));
  }
  if (job.stills) {
    sinks.push_back(std::make_unique<pipeline::PosterSink>((folder / "poster.png").string(),
                                                           scene::poster_frame(scene), job.png));
    Result<std::unique_ptr<pipeline::ContactSheet>> sheet =
        pipeline::ContactSheet::open((folder / "contact_sheet.png").string(), job.first, job.end,
                                     scene.fps, job.png, view::overlay_font(scene));
    if (!sheet) return Error{sheet.error()};
    sinks.push_back(std::move(*sheet));
  }
  return sinks;
}

// The frames the options ask for out of the scene's `total`: all, --frames A:B, or --chunk I/N.
Result<FrameRange> frame_range(const RenderOptions& options, std::int64_t total) {
  if (options.chunk) {
    if (options.first_frame || options.end_frame) {
      return Error{"--chunk and --frames both choose the frames: give one of them"};
    }
    const Result<std::vector<FrameRange>> plan = plan_chunks(total, options.chunk->count);
    if (!plan)
      return Error{"--chunk " + std::to_string(options.chunk->index) + "/" +
                   std::to_string(options.chunk->count) + ": " + plan.error()};
    return (*plan)[static_cast<std::size_t>(options.chunk->index - 1)];
  }
  const FrameRange range{options.first_frame.value_or(0), options.end_frame.value_or(total)};
  if (range.first < 0 || range.end > total || range.first >= range.end) {
    return Error{"--frames " + range_text(range) +
                 " is outside the scene's frames 0:" + std::to_string(total)};
  }
  return range;
}

// The renderer of the job's frames on this thread (its context, its shaders compiled), timed and
// described in `result`; an error when this OpenGL cannot draw the scene.
Result<std::unique_ptr<render::Renderer>> make_renderer(const RenderJob& job,
                                                        const view::Framing& framing,
                                                        RenderResult& result) {
  const double start = pipeline::process_cpu_seconds();
  const scene::Scene& scene = job.scene;
  const render::RenderSettings settings = view::renderer_settings(scene, framing);
  Result<std::unique_ptr<render::Renderer>> made =
      render::Renderer::create(settings, job.shader_directory);
  if (!made) {
    // Mostly what the scene asks of this OpenGL ([render] msaa beyond its samples): name it.
    return Error{job.scene.source_path + ": " + made.error()};
  }
  std::unique_ptr<render::Renderer> renderer = std::move(made).value();
  result.renderer = renderer->description();
  result.backend = render::backend_name(renderer->backend());
  result.device = renderer->device();
  result.opengl = renderer->opengl();
  result.warnings = view::missing_character_warnings(scene, renderer->font());
  result.renderer_seconds = pipeline::process_cpu_seconds() - start;
  return renderer;
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

std::string RenderJob::gltf_path(const fs::path& folder) const {
  return scene.output.gltf
             ? (folder / (scene.name + "." + std::string(common::kGltfExtension))).string()
             : std::string();
}

std::string RenderJob::html_path(const fs::path& folder) const {
  return scene.output.html
             ? (folder / (scene.name + "." + std::string(common::kHtmlExtension))).string()
             : std::string();
}

std::string RenderJob::video_path(const fs::path& folder, io::VideoFormat format) const {
  const std::vector<io::VideoFormat>& formats = scene.output.formats;
  if (!scene.output.video || std::find(formats.begin(), formats.end(), format) == formats.end()) {
    return {};
  }
  return (folder / (scene.name + "." + io::video_format_name(format))).string();
}

Result<scene::Scene> scene_as_rendered(scene::Scene written, const RenderOptions& options) {
  Result<scene::Scene> chosen = with_choices(options, std::move(written));
  if (!chosen) return Error{chosen.error()};
  scene::Scene scene = std::move(*chosen);
  apply_overrides(options, scene);
  if (scene.render.backend == render::Backend::osmesa &&
      scene.render.egl_device != render::kAutomaticEglDevice) {
    return Error{scene.source_path + ": the EGL device " + std::to_string(scene.render.egl_device) +
                 " ([render] egl_device or --egl-device) is for the egl back end, not osmesa "
                 "([render] backend or --backend)"};
  }
  // The loaded scene kept every rule: what breaks one now is an override.
  if (const std::optional<scene::BrokenRule> broken = scene::broken_video_rule(scene)) {
    return Error{scene.source_path + ": " + broken->keys.front() +
                 ", as the command line sets it: " + broken->problem};
  }
  return scene;
}

Result<void> check_joinable_formats(const scene::Scene& scene, const std::string& asked_by) {
  if (scene.output.gltf || scene.output.html) {
    const std::string name(scene.output.gltf ? common::kGltfFormatName : common::kHtmlFormatName);
    return Error{asked_by + ": " + name +
                 " is not written in parts (one file holds the animation of every frame it "
                 "covers, and `tumble join` joins videos only): leave it out with --format mp4 or "
                 "--format webm (or [output] formats), and render the " +
                 (scene.output.gltf ? "glTF" : "html replay") +
                 " whole, or of a frame range with --frames"};
  }
  if (!scene.output.video) return {};
  for (const io::VideoFormat format : scene.output.formats) {
    if (common::joins_in_segments(format)) continue;
    const std::string name = io::video_format_name(format);
    return Error{asked_by + ": " + name +
                 " is not written in parts (its palette is chosen for the frames it holds, so "
                 "parts of one do not join): leave it out with --format mp4 or --format webm (or "
                 "[output] formats), and render the " +
                 name + " whole, or of a frame range with --frames"};
  }
  return {};
}

Result<RenderJob> make_render_job(scene::Scene loaded, const RenderOptions& options) {
  Result<scene::Scene> overridden = scene_as_rendered(std::move(loaded), options);
  if (!overridden) return Error{overridden.error()};
  scene::Scene& scene = *overridden;
  const std::int64_t total = scene::frame_count(scene);
  Result<FrameRange> range = frame_range(options, total);
  if (!range) return Error{range.error()};
  if (options.chunk) {
    if (const Result<void> joinable = check_joinable_formats(scene, "--chunk"); !joinable) {
      return Error{joinable.error()};
    }
  }
  if (options.chunk) {
    scene.output.directory += ".chunk-" + std::to_string(options.chunk->index) + "-of-" +
                              std::to_string(options.chunk->count);
  }
  if (!options.shader_directory.empty()) {
    std::error_code ignored;
    if (!fs::exists(fs::path(options.shader_directory) / "body.vert", ignored)) {
      return Error{"no shaders (body.vert) in " + options.shader_directory};
    }
  }
  std::string shader_directory =
      options.shader_directory.empty() ? find_shader_directory() : options.shader_directory;
  if (shader_directory.empty()) {
    const char* asked = std::getenv("TUMBLE_SHADER_DIR");
    return Error{asked ? std::string("no shaders (body.vert) in TUMBLE_SHADER_DIR=") + asked
                       : "cannot find the shaders/ folder (set TUMBLE_SHADER_DIR)"};
  }
  std::optional<ReplayAssets> replay_assets;
  if (scene.output.html) {
    Result<ReplayAssets> assets = load_replay_assets(options.web_directory);
    if (!assets) return Error{assets.error()};
    replay_assets = std::move(*assets);
  }
  const fs::path root = fs::path(options.output_root).lexically_normal();
  const fs::path directory = root / scene.output.directory;
  return RenderJob{.scene = std::move(scene),
                   .frame_count = total,
                   .first = range->first,
                   .end = range->end,
                   .chunk = options.chunk,
                   .scene_hash = std::string(),  // set by the caller that read the file
                   .output_root = root,
                   .directory = directory,
                   .png = options.png,
                   .serial = options.serial,
                   .shader_directory = std::move(shader_directory),
                   .replay_assets = std::move(replay_assets)};
}

Result<void> render_scene(const RenderJob& job, const fs::path& folder,
                          const std::function<bool()>& stop_requested,
                          const std::function<void(std::int64_t done)>& on_frame_done,
                          RenderResult& result) {
  result = RenderResult();
  const scene::Scene& scene = job.scene;
  const auto setup_start = std::chrono::steady_clock::now();
  Result<std::vector<std::unique_ptr<pipeline::FrameSink>>> sinks = open_sinks(job, folder);
  if (!sinks) return Error{sinks.error()};
  double start = pipeline::process_cpu_seconds();
  const Result<view::Framing> framing = view::frame_scene(scene, job.frame_count, stop_requested);
  if (!framing) return Error{framing.error()};
  result.framing_steps = framing->physics_steps;
  result.framing_seconds = pipeline::process_cpu_seconds() - start;
  const Result<std::unique_ptr<render::Renderer>> made = make_renderer(job, *framing, result);
  if (!made) return Error{made.error()};
  const std::unique_ptr<render::Renderer>& renderer = *made;
  view::SimulatedFrames source(scene, *framing, stop_requested);
  for (const physics::BodyState& state : source.simulation().current()) {
    result.bodies.push_back({.energy_start = physics::kinetic_energy(state),
                             .angular_momentum_start = state.angular_momentum().norm()});
  }
  start = pipeline::process_cpu_seconds();
  const Result<std::int64_t> seek_steps = source.seek(job.first);
  if (!seek_steps) return Error{seek_steps.error()};
  result.seek_steps = *seek_steps;
  result.seek_seconds = pipeline::process_cpu_seconds() - start;
  if (scene.output.gltf || scene.output.html) source.record_motion();
  std::vector<pipeline::FrameSink*> sink_list;
  for (const std::unique_ptr<pipeline::FrameSink>& sink : *sinks) {
    sink_list.push_back(sink.get());
    result.stages.push_back(sink->stage());
  }
  result.setup_seconds = seconds_since(setup_start);

  const Result<void> ran = pipeline::run_frames(job.first, job.end, source, *renderer, sink_list,
                                                job.serial, on_frame_done, result.pipeline);
  result.frame_steps = source.simulation().step_count();
  if (!ran) return ran;  // each sink's destructor removes its partial file
  const auto finish_start = std::chrono::steady_clock::now();
  Result<void> finished = Result<void>::success();
  for (pipeline::FrameSink* sink : sink_list) {
    finished = sink->finish();
    if (!finished) break;
  }
  if (finished && scene.output.gltf) {
    finished = io::write_glb(
        job.gltf_path(folder),
        gltf_scene(scene, *framing, source.motion(), std::string("tumble ") + TUMBLE_VERSION));
  }
  if (finished && scene.output.html) {
    finished = write_html_replay(job.html_path(folder), *job.replay_assets, scene, *framing,
                                 source.motion(), job.first);
  }
  result.finish_seconds = seconds_since(finish_start);
  for (std::size_t i = 0; i < result.bodies.size(); ++i) {
    const physics::BodyState& state = source.simulation().current()[i];
    result.bodies[i].energy_end = physics::kinetic_energy(state);
    result.bodies[i].angular_momentum_end = state.angular_momentum().norm();
  }
  return finished;
}

}  // namespace tumble::job
