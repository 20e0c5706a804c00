#include "job/render_folder.hpp"

#include <algorithm>
#include <sstream>
#include <thread>

#include "io/atomic_file.hpp"
#include "io/json_text.hpp"
#include "io/staged_directory.hpp"
#include "job/output_folder.hpp"
#include "job/scene_hash.hpp"
#include "scene/scene_loader.hpp"
#include "view/overlay_view.hpp"

namespace tumble::job {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string stage_json(const pipeline::StageTime& stage) {
  std::ostringstream out;
  out.precision(6);
  out << "{\"cpu\": " << stage.cpu << ", \"wall\": " << stage.wall << "}";
  return out.str();
}

// What `tumble join` requires to be the same in every chunk (besides the scene's hash): what
// decides the pixels of the frames and the bytes of the files. The videos' pixel formats and
// encoder threads are fixed by the build, and io::join_videos compares the stream headers.
std::string settings_json(const RenderJob& job, const RenderResult& result) {
  const scene::Scene& scene = job.scene;
  std::ostringstream out;
  out << "{\"width\": " << scene.render.width << ", \"height\": " << scene.render.height
      << ", \"fps\": " << scene.fps << ", \"msaa\": " << scene.render.msaa
      << ", \"frames\": " << (scene.output.frames ? "true" : "false")
      << ", \"png_encoder\": " << (job.png.own_encoder ? "\"tumble\"" : "\"zlib\"")
      << ", \"png_zlib_level\": " << job.png.compression_level
      << ", \"png_filter\": " << (job.png.filter ? "true" : "false")
      << ", \"video\": " << (scene.output.video ? "true" : "false") << ", \"formats\": [";
  for (std::size_t i = 0; i < scene.output.formats.size(); ++i) {
    out << (i ? ", " : "") << io::json_string(io::video_format_name(scene.output.formats[i]));
  }
  bool listed = !scene.output.formats.empty();
  for (const auto& [asked, name] : {std::pair{scene.output.gltf, common::kGltfFormatName},
                                    std::pair{scene.output.html, common::kHtmlFormatName}}) {
    if (!asked) continue;
    out << (listed ? ", " : "") << io::json_string(std::string(name));
    listed = true;
  }
  out << "], \"crf\": " << scene.output.crf << ", \"webm_crf\": " << scene.output.webm_crf
      << ", \"preset\": " << io::json_string(scene.output.preset)
      << ", \"font\": " << io::json_string(view::overlay_font(scene));
  // Only when on: the settings of a render without it are written as before.
  if (scene.render.motion_blur.on()) {
    out << ", \"motion_blur\": {\"samples\": " << scene.render.motion_blur.samples
        << ", \"shutter\": " << scene.render.motion_blur.shutter << "}";
  }
  const common::Look& look = scene.render.look;
  out << ", \"look\": {\"shadow_softness\": " << look.shadow_softness
      << ", \"ambient_occlusion\": " << look.ambient_occlusion
      << ", \"fill_light\": " << look.fill_light << ", \"exposure\": ";
  if (look.exposure == common::Look::kAutoExposure) {
    out << "\"auto\"";
  } else {
    out << look.exposure;
  }
  out << "}";
  out << ", \"opengl\": " << io::json_string(result.opengl) << "}";
  return out.str();
}

std::string chunk_json(const RenderJob& job) {
  if (!job.chunk) return "null";
  return "{\"index\": " + std::to_string(job.chunk->index) +
         ", \"count\": " + std::to_string(job.chunk->count) + "}";
}

// {"mp4": path, "webm": path, ...}: every video the render wrote, in [output] formats order.
std::string videos_json(const RenderJob& job) {
  std::string out = "{";
  for (const io::VideoFormat format : job.scene.output.formats) {
    const std::string path = job.video_path(job.directory, format);
    if (path.empty()) continue;
    out += (out.size() > 1 ? ", " : "") + io::json_string(io::video_format_name(format)) + ": " +
           io::json_string(path);
  }
  return out + "}";
}

// {"fps": F, "colors": N, "dither": NAME} of the GIF written, or null: F is the rate it plays
// at, 100 / its delay in centiseconds (io::gif_delay_centiseconds).
std::string gif_json(const RenderJob& job) {
  if (job.video_path(job.directory, io::VideoFormat::gif).empty()) return "null";
  const scene::OutputSpec& output = job.scene.output;
  const int asked = std::min(output.gif_fps.value_or(job.scene.fps), job.scene.fps);
  std::ostringstream out;
  out << "{\"fps\": " << 100.0 / io::gif_delay_centiseconds(asked)
      << ", \"colors\": " << output.gif_colors
      << ", \"dither\": " << io::json_string(common::gif_dither_name(output.gif_dither)) << "}";
  return out.str();
}

std::string report_json(const RenderJob& job, const RenderResult& result,
                        const std::vector<RenderedFile>& kept, double total_seconds) {
  const scene::Scene& scene = job.scene;
  const pipeline::PipelineReport& p = result.pipeline;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // (CPU seconds of every stage / cores) / wall seconds: 1 when every core worked all the time.
  const double efficiency = p.wall > 0 ? p.process_cpu / cores / p.wall : 0.0;
  const std::string frames_directory = job.frames_path(job.directory);
  const std::string video_path = job.video_path(job.directory);
  const std::string gltf_path = job.gltf_path(job.directory);
  const std::string html_path = job.html_path(job.directory);
  std::ostringstream out;
  out.precision(17);
  // This first line is how a folder is known for a render's (output_folder.cpp): keep it.
  out << "{\n  \"scene\": " << io::json_string(scene.name)
      << ",\n  \"version\": " << io::json_string(TUMBLE_VERSION)
      << ",\n  \"scene_file\": " << io::json_string(scene.source_path)
      << ",\n  \"scene_hash\": " << io::json_string(job.scene_hash)
      << ",\n  \"scene_frames\": " << job.frame_count << ",\n  \"chunk\": " << chunk_json(job)
      << ",\n  \"settings\": " << settings_json(job, result)
      << ",\n  \"width\": " << scene.render.width << ",\n  \"height\": " << scene.render.height
      << ",\n  \"fps\": " << scene.fps << ",\n  \"msaa\": " << scene.render.msaa
      << ",\n  \"antialiasing\": " << io::json_string(antialiasing_name(scene.render.msaa))
      << ",\n  \"dt\": " << scene.physics.dt << ",\n  \"integrator\": "
      << io::json_string(std::string(physics::integrator_name(scene.physics.integrator)))
      << ",\n  \"frames\": {\"first\": " << job.first << ", \"end\": " << job.end
      << ", \"count\": " << job.end - job.first << "},\n  \"frames_directory\": "
      << (frames_directory.empty() ? "null" : io::json_string(frames_directory))
      << ",\n  \"video\": " << (video_path.empty() ? "null" : io::json_string(video_path))
      << ",\n  \"videos\": " << videos_json(job)
      << ",\n  \"gltf\": " << (gltf_path.empty() ? "null" : io::json_string(gltf_path))
      << ",\n  \"html\": " << (html_path.empty() ? "null" : io::json_string(html_path))
      << ",\n  \"kept\": " << kept_json(kept) << ",\n  \"gif\": " << gif_json(job)
      << ",\n  \"path\": " << (job.serial ? "\"serial\"" : "\"pipelined\"")
      << ",\n  \"renderer\": " << io::json_string(result.renderer)
      << ",\n  \"backend\": " << io::json_string(result.backend)
      << ",\n  \"device\": " << (result.device.empty() ? "null" : io::json_string(result.device))
      << ",\n  \"physics_steps\": {\"framing\": " << result.framing_steps
      << ", \"frames\": " << result.frame_steps << ", \"to_first_frame\": " << result.seek_steps
      << "}"
      << ",\n  \"stages\": {\"simulate\": " << stage_json(p.simulate)
      << ", \"render\": " << stage_json(p.render);
  for (std::size_t i = 0; i < result.stages.size(); ++i) {
    out << ", " << io::json_string(result.stages[i]) << ": " << stage_json(p.sinks[i]);
  }
  out << "},\n  \"seconds\": {\"setup\": " << result.setup_seconds << ", \"frames\": " << p.wall
      << ", \"finish\": " << result.finish_seconds << ", \"total\": " << total_seconds
      << "},\n  \"cpu_seconds_before_first_frame\": {\"framing\": " << result.framing_seconds
      << ", \"renderer\": " << result.renderer_seconds
      << ", \"to_first_frame\": " << result.seek_seconds
      << "},\n  \"frames_per_second\": " << (p.wall > 0 ? p.frames_done / p.wall : 0.0)
      << ",\n  \"cores\": " << cores << ",\n  \"pipeline_efficiency\": " << efficiency
      << ",\n  \"peak_memory_bytes\": " << peak_memory_bytes() << ",\n  \"bodies\": [";
  for (std::size_t i = 0; i < result.bodies.size(); ++i) {
    const BodyDiagnostics& b = result.bodies[i];
    out << (i ? "," : "") << "\n    {\"name\": " << io::json_string(scene.bodies[i].name)
        << ", \"energy_start\": " << io::json_number(b.energy_start)
        << ", \"energy_end\": " << io::json_number(b.energy_end)
        << ", \"angular_momentum_start\": " << io::json_number(b.angular_momentum_start)
        << ", \"angular_momentum_end\": " << io::json_number(b.angular_momentum_end) << "}";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

}  // namespace

Result<PreparedRender> prepare_render(std::string scene_text, const RenderOptions& options,
                                      Clock::time_point start) {
  const Result<scene::Scene> loaded = scene::parse_scene(scene_text, options.scene_path);
  if (!loaded) return Error{loaded.error()};
  Result<RenderJob> made = make_render_job(*loaded, options);
  if (!made) return Error{made.error()};
  made->scene_hash = scene_hash(scene_text, made->scene);
  // An earlier render of this scene in the folder keeps what this one does not write (the MP4
  // beside a GIF rendered apart); another scene's is replaced whole.
  EarlierRender earlier = read_earlier_render(made->directory, scene_text, made->scene);
  made->stills = writes_own_stills(made->scene, earlier);
  if (const Result<void> replaceable =
          check_replaceable(made->output_root, made->scene.output.directory);
      !replaceable) {
    return Error{replaceable.error()};
  }
  return PreparedRender{.job = std::move(made).value(),
                        .earlier = std::move(earlier),
                        .scene_text = std::move(scene_text),
                        .start = start};
}

std::string stopped_message(const RenderJob& job, const RenderResult& result,
                            const std::string& why) {
  return why + " after " + std::to_string(result.pipeline.frames_done) + " of " +
         std::to_string(job.end - job.first) + " frames; " + job.directory.string() +
         " was left as it was";
}

Result<void> render_to_folder(const PreparedRender& prepared,
                              const std::function<bool()>& stop_requested,
                              const std::function<void(std::int64_t done)>& on_frame_done,
                              RenderOutcome& outcome) {
  outcome = RenderOutcome();
  const RenderJob& job = prepared.job;
  // Everything is written into a hidden folder beside the final one and swapped in at the end.
  Result<io::StagedDirectory> staged = io::StagedDirectory::create(job.directory.string());
  if (!staged) return Error{staged.error()};
  const fs::path staging = staged->path();
  RenderResult& result = outcome.result;
  const Result<void> rendered = render_scene(job, staging, stop_requested, on_frame_done, result);
  const auto failed = [&](const std::string& what) {
    return Error{what + "\ntumble: " + stopped_message(job, result, "render failed")};
  };
  if (stop_requested()) {
    outcome.stopped = true;
    return Error{stopped_message(job, result, "stopped")};
  }
  if (!rendered) return failed(rendered.error());

  outcome.written = render_files(staging, job.scene.name);
  // Read again: what is kept is what the folder holds now, just before the swap.
  Result<std::vector<RenderedFile>> kept =
      keep_earlier_files(read_earlier_render(job.directory, prepared.scene_text, job.scene),
                         job.directory, staging, job.stills);
  if (!kept) return failed(kept.error());
  outcome.kept = std::move(kept).value();
  outcome.total_seconds = seconds_since(prepared.start);
  Result<void> done =
      io::write_file_atomically((staging / "report.json").string(),
                                report_json(job, result, outcome.kept, outcome.total_seconds));
  // Checked again: the folder may have been made or filled while the frames were drawn.
  if (done) done = check_replaceable(job.output_root, job.scene.output.directory);
  if (done) done = staged->commit();
  if (!done) return failed(done.error());
  outcome.leftover = staged->leftover();
  return {};
}

}  // namespace tumble::job
