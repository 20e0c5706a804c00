#include "cli/render_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <sstream>
#include <thread>
#include <variant>

#include "cli/options.hpp"
#include "common/exit_codes.hpp"
#include "io/atomic_file.hpp"
#include "io/json_text.hpp"
#include "io/staged_directory.hpp"
#include "job/kept_files.hpp"
#include "job/output_folder.hpp"
#include "job/render_golden.hpp"
#include "job/render_job.hpp"
#include "job/scene_hash.hpp"
#include "pipeline/progress.hpp"
#include "scene/scene_loader.hpp"
#include "scene/stability_report.hpp"
#include "sys/interrupt.hpp"
#include "view/overlay_view.hpp"

namespace tumble::cli {
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
std::string settings_json(const job::RenderJob& job, const job::RenderResult& result) {
  const scene::Scene& scene = job.scene;
  std::ostringstream out;
  out << "{\"width\": " << scene.render.width << ", \"height\": " << scene.render.height
      << ", \"fps\": " << scene.fps << ", \"msaa\": " << scene.render.msaa
      << ", \"frames\": " << (scene.output.frames ? "true" : "false")
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
      << ", \"font\": " << io::json_string(view::overlay_font(scene))
      << ", \"opengl\": " << io::json_string(result.opengl) << "}";
  return out.str();
}

std::string chunk_json(const job::RenderJob& job) {
  if (!job.chunk) return "null";
  return "{\"index\": " + std::to_string(job.chunk->index) +
         ", \"count\": " + std::to_string(job.chunk->count) + "}";
}

// {"mp4": path, "webm": path, ...}: every video the render wrote, in [output] formats order.
std::string videos_json(const job::RenderJob& job) {
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
std::string gif_json(const job::RenderJob& job) {
  if (job.video_path(job.directory, io::VideoFormat::gif).empty()) return "null";
  const scene::OutputSpec& output = job.scene.output;
  const int asked = std::min(output.gif_fps.value_or(job.scene.fps), job.scene.fps);
  std::ostringstream out;
  out << "{\"fps\": " << 100.0 / io::gif_delay_centiseconds(asked)
      << ", \"colors\": " << output.gif_colors
      << ", \"dither\": " << io::json_string(common::gif_dither_name(output.gif_dither)) << "}";
  return out.str();
}

std::string report_json(const job::RenderJob& job, const job::RenderResult& result,
                        const std::vector<job::RenderedFile>& kept, double total_seconds) {
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
      << ",\n  \"antialiasing\": " << io::json_string(job::antialiasing_name(scene.render.msaa))
      << ",\n  \"dt\": " << scene.physics.dt << ",\n  \"integrator\": "
      << io::json_string(std::string(physics::integrator_name(scene.physics.integrator)))
      << ",\n  \"frames\": {\"first\": " << job.first << ", \"end\": " << job.end
      << ", \"count\": " << job.end - job.first << "},\n  \"frames_directory\": "
      << (frames_directory.empty() ? "null" : io::json_string(frames_directory))
      << ",\n  \"video\": " << (video_path.empty() ? "null" : io::json_string(video_path))
      << ",\n  \"videos\": " << videos_json(job)
      << ",\n  \"gltf\": " << (gltf_path.empty() ? "null" : io::json_string(gltf_path))
      << ",\n  \"html\": " << (html_path.empty() ? "null" : io::json_string(html_path))
      << ",\n  \"kept\": " << job::kept_json(kept) << ",\n  \"gif\": " << gif_json(job)
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
      << ",\n  \"peak_memory_bytes\": " << job::peak_memory_bytes() << ",\n  \"bodies\": [";
  for (std::size_t i = 0; i < result.bodies.size(); ++i) {
    const job::BodyDiagnostics& b = result.bodies[i];
    out << (i ? "," : "") << "\n    {\"name\": " << io::json_string(scene.bodies[i].name)
        << ", \"energy_start\": " << io::json_number(b.energy_start)
        << ", \"energy_end\": " << io::json_number(b.energy_end)
        << ", \"angular_momentum_start\": " << io::json_number(b.angular_momentum_start)
        << ", \"angular_momentum_end\": " << io::json_number(b.angular_momentum_end) << "}";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

// "tumble: N frames in S s (F frames/s, BACKEND) -> DIR/: FILE, ..., report.json", and the files
// kept of an earlier render on a line of their own.
void print_summary(const job::RenderJob& job, const job::RenderResult& result,
                   const std::vector<std::string>& written,
                   const std::vector<job::RenderedFile>& kept, double total_seconds,
                   std::FILE* err) {
  const auto listed = [](const std::string& name) { return name == "frames" ? "frames/" : name; };
  std::string files;
  for (const std::string& name : written) files += listed(name) + ", ";
  files += "report.json";
  const std::string drawn_by = result.backend + (result.device.empty() ? "" : ", " + result.device);
  const long long count = job.end - job.first;
  std::fprintf(err, "tumble: %lld frames in %.1f s (%.1f frames/s, %s) -> %s/: %s\n", count,
               total_seconds, static_cast<double>(count) / total_seconds, drawn_by.c_str(),
               job.directory.c_str(), files.c_str());
  if (kept.empty()) return;
  std::string names;
  for (const job::RenderedFile& file : kept)
    names += (names.empty() ? "" : ", ") + listed(file.name);
  std::fprintf(err, "tumble: kept of the earlier render of this scene in %s/: %s\n",
               job.directory.c_str(), names.c_str());
}

}  // namespace

CommandResult run_render(const job::RenderOptions& options,
                         const std::optional<diff::DiffCommandOptions>& golden, std::FILE* out,
                         std::FILE* err) {
  const auto start = Clock::now();
  sys::install_interrupt_handlers();  // from the start: a signal is acted on before the first frame
  const Result<std::string> text = scene::read_scene_text(options.scene_path);
  if (!text) return Error{text.error()};
  const Result<scene::Scene> loaded = scene::parse_scene(*text, options.scene_path);
  if (!loaded) return Error{loaded.error()};
  Result<job::RenderJob> made = job::make_render_job(*loaded, options);
  if (!made) return Error{made.error()};
  made->scene_hash = job::scene_hash(*text, made->scene);
  // An earlier render of this scene in the folder keeps what this one does not write (the MP4
  // beside a GIF rendered apart); another scene's is replaced whole, and that is said.
  const job::EarlierRender earlier = job::read_earlier_render(made->directory, *text, made->scene);
  made->stills = job::writes_own_stills(made->scene, earlier);
  const job::RenderJob& job = *made;
  if (golden) {
    if (const Result<void> usable = job::check_golden(*golden, job); !usable) {
      return Error{usable.error()};
    }
  }
  if (!options.quiet) scene::print_stability_warnings(job.scene, err);

  // Everything is written into a hidden folder beside the final one and swapped in at the end:
  // a failed or interrupted render leaves the earlier output as it was.
  if (const Result<void> replaceable =
          job::check_replaceable(job.output_root, job.scene.output.directory);
      !replaceable) {
    return Error{replaceable.error()};
  }
  if (!options.quiet && earlier.kind == job::EarlierRender::Kind::other_scene) {
    std::fprintf(err, "tumble: %s holds %s: it is replaced as a whole, nothing of it kept\n",
                 job.directory.c_str(), earlier.why.c_str());
  }
  Result<io::StagedDirectory> staged = io::StagedDirectory::create(job.directory.string());
  if (!staged) return Error{staged.error()};
  const fs::path staging = staged->path();
  const std::int64_t count = job.end - job.first;
  pipeline::Progress progress(count, options.quiet, err);
  job::RenderResult result;
  const Result<void> rendered = job::render_scene(
      job, staging, [] { return sys::interrupt_signal() != 0; },
      [&](std::int64_t done) { progress.update(done); }, result);
  progress.finish();
  if (!options.quiet) {
    for (const std::string& line : result.warnings) {
      std::fprintf(err, "tumble: warning: %s\n", line.c_str());
    }
  }
  if (options.verbose && !result.renderer.empty()) {
    std::fprintf(err, "tumble: renderer %s\n", result.renderer.c_str());
  }
  // "<why> after K of N frames; <folder> was left as it was".
  const auto stopped = [&](const std::string& why) {
    return why + " after " + std::to_string(result.pipeline.frames_done) + " of " +
           std::to_string(count) + " frames; " + job.directory.string() + " was left as it was";
  };
  if (const int signal = sys::interrupt_signal()) {
    std::fprintf(err, "tumble: %s\n",
                 stopped(std::string("stopped by ") + sys::signal_name(signal)).c_str());
    return interrupted_by(signal);
  }
  // Two lines, each "tumble: ...": what failed, then what became of the output.
  if (!rendered) return Error{rendered.error() + "\ntumble: " + stopped("render failed")};

  const std::vector<std::string> written = job::render_files(staging, job.scene.name);
  // Read again: what is kept is what the folder holds now, just before the swap.
  const Result<std::vector<job::RenderedFile>> kept =
      job::keep_earlier_files(job::read_earlier_render(job.directory, *text, job.scene),
                              job.directory, staging, job.stills);
  if (!kept) return Error{kept.error() + "\ntumble: " + stopped("render failed")};
  const double total_seconds = seconds_since(start);
  Result<void> done = io::write_file_atomically((staging / "report.json").string(),
                                                report_json(job, result, *kept, total_seconds));
  // Checked again: the folder may have been made or filled while the frames were drawn.
  if (done) done = job::check_replaceable(job.output_root, job.scene.output.directory);
  if (done) done = staged->commit();
  if (!done) return Error{done.error() + "\ntumble: " + stopped("render failed")};
  if (!staged->leftover().empty())
    std::fprintf(err, "tumble: warning: %s\n", staged->leftover().c_str());
  if (!options.quiet) print_summary(job, result, written, *kept, total_seconds, err);
  return golden ? job::compare_with_golden(*golden, job, out) : kExitOk;
}

namespace {

// The command line of `tumble render`, as given: what run_render takes is made of it once parsed.
struct RenderCommandLine {
  job::RenderOptions render;
  std::string frame_range;  // --frames A:B
  std::string chunk_index;  // --chunk I/N
  std::string backend;      // --backend (checked by IsMember)
  std::string png_compression = "fast";
  diff::DiffCommandOptions golden;  // --golden DIR and tumble diff's options
  ComparisonOptions golden_comparison;
};

CommandResult run_command_line(RenderCommandLine& line) {
  job::RenderOptions& render = line.render;
  if (!line.frame_range.empty()) {
    const std::optional<std::pair<long long, long long>> range = parse_range(line.frame_range);
    if (!range) return Error{frames_error(line.frame_range)};
    render.first_frame = range->first;
    render.end_frame = range->second;
  }
  if (!line.chunk_index.empty()) {
    render.chunk = job::parse_chunk_index(line.chunk_index);
    if (!render.chunk) {
      return Error{"--chunk: expected I/N (chunk I of N, 1 <= I <= N), got " + line.chunk_index};
    }
  }
  render.png = *io::png_settings_named(line.png_compression);  // checked by IsMember
  for (const auto each : common::kAllBackends) {
    if (line.backend == common::backend_name(each)) render.backend = each;
  }
  std::optional<diff::DiffCommandOptions> compare;
  if (!line.golden.first_path.empty()) {
    line.golden_comparison.apply_antialiasing(line.golden);
    compare = line.golden;
  }
  return run_render(render, compare, stdout, stderr);
}

}  // namespace

void add_render_command(CLI::App& app, Commands& commands) {
  const auto line = std::make_shared<RenderCommandLine>();
  job::RenderOptions& render = line->render;
  CLI::App* command = app.add_subcommand(
      "render", "Render a scene to PNG frames and videos (MP4, WebM, GIF), off-screen");
  command->add_option("scene", render.scene_path, "Scene file (TOML)")->required();
  command
      ->add_option("-o,--output", render.output_root,
                   "Output folder; files go to OUTPUT/<scene name>/")
      ->check(not_empty())
      ->capture_default_str();
  add_setting_option(command, common::render_setting("width"), render.width);
  add_setting_option(command, common::render_setting("height"), render.height);
  add_setting_option(command, common::render_setting("fps"), render.fps);
  CLI::Option* frames =
      command->add_option("--frames", line->frame_range, "Render frames A to B-1 only (A:B)")
          ->check(not_empty());
  command
      ->add_option("--chunk", line->chunk_index,
                   "Render chunk I of N (I/N, from 1): the frames of line I of `tumble plan "
                   "--chunks N`, into OUTPUT/<scene output directory>.chunk-I-of-N/")
      ->check(not_empty())
      ->excludes(frames);
  command->add_flag("!--no-frames", render.frames, "Do not write PNG frames");
  command->add_option(
      "--quality", render.quality,
      "Size and frame rate: low (854x480, 15 fps), medium (1280x720, 30), high (1920x1080, 60), "
      "production (2560x1440, 60), 4k (3840x2160, 60); --width, --height, --fps win");
  command
      ->add_option("--format", render.formats,
                   "Formats to write: videos mp4, webm or gif, gltf (the motion as a glTF "
                   "binary, <scene>.glb) and html (a page that replays it in a browser, "
                   "<scene>.html); repeat or separate with commas (replaces [output] formats)")
      ->delimiter(',');
  command->add_flag("!--no-video", render.video, "Do not write any video");
  command->add_flag("-q,--quiet", render.quiet, "No progress and no summary");
  command->add_flag("-v,--verbose", render.verbose, "Print the OpenGL renderer in use");
  command->add_flag("--serial", render.serial,
                    "Render, write and encode on one thread (slower; same bytes)");
  add_setting_option(command, common::render_setting("backend"), line->backend);
  add_setting_option(command, common::render_setting("egl_device"), render.egl_device);
  command
      ->add_option("--png-compression", line->png_compression,
                   "fast (zlib 1, no filter), default (libpng's: zlib 6, adaptive filter) or "
                   "small (zlib 9, adaptive filter)")
      ->check(CLI::IsMember({"fast", "default", "small"}))
      ->capture_default_str();
  CLI::Option* golden =
      command
          ->add_option(
              "--golden", line->golden.first_path,
              "Then compare the render with this golden render (its folder, a folder of "
              "frames or a video) as `tumble diff` does: exit 0 match, 1 mismatch, 2 error")
          ->check(not_empty());
  add_comparison_options(command, line->golden, line->golden_comparison, golden);
  commands.push_back({command, [line] { return run_command_line(*line); }});
}

}  // namespace tumble::cli
