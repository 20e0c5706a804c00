#include "cli/render_command.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <variant>

#include "cli/join_command.hpp"
#include "cli/options.hpp"
#include "common/exit_codes.hpp"
#include "job/kept_files.hpp"
#include "job/render_folder.hpp"
#include "job/render_golden.hpp"
#include "job/render_job.hpp"
#include "pipeline/progress.hpp"
#include "scene/scene_loader.hpp"
#include "scene/stability_report.hpp"
#include "sys/child_process.hpp"
#include "sys/interrupt.hpp"

namespace tumble::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

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
  Result<std::string> text = scene::read_scene_text(options.scene_path);
  if (!text) return Error{text.error()};
  const Result<job::PreparedRender> prepared =
      job::prepare_render(std::move(text).value(), options, start);
  if (!prepared) return Error{prepared.error()};
  const job::RenderJob& job = prepared->job;
  if (golden) {
    if (const Result<void> usable = job::check_golden(*golden, job); !usable) {
      return Error{usable.error()};
    }
  }
  if (!options.quiet) scene::print_stability_warnings(job.scene, err);
  if (!options.quiet && prepared->earlier.kind == job::EarlierRender::Kind::other_scene) {
    std::fprintf(err, "tumble: %s holds %s: it is replaced as a whole, nothing of it kept\n",
                 job.directory.c_str(), prepared->earlier.why.c_str());
  }
  pipeline::Progress progress(job.end - job.first, options.quiet, err);
  job::RenderOutcome outcome;
  const Result<void> rendered = job::render_to_folder(
      *prepared, [] { return sys::interrupt_signal() != 0; },
      [&](std::int64_t done) { progress.update(done); }, outcome);
  progress.finish();
  const job::RenderResult& result = outcome.result;
  if (!options.quiet) {
    for (const std::string& line : result.warnings) {
      std::fprintf(err, "tumble: warning: %s\n", line.c_str());
    }
  }
  if (options.verbose && !result.renderer.empty()) {
    std::fprintf(err, "tumble: renderer %s\n", result.renderer.c_str());
  }
  if (const int signal = sys::interrupt_signal()) {
    const std::string why = std::string("stopped by ") + sys::signal_name(signal);
    std::fprintf(err, "tumble: %s\n", job::stopped_message(job, result, why).c_str());
    return interrupted_by(signal);
  }
  // Two lines, each "tumble: ...": what failed, then what became of the output.
  if (!rendered) return Error{rendered.error()};
  if (!outcome.leftover.empty())
    std::fprintf(err, "tumble: warning: %s\n", outcome.leftover.c_str());
  if (!options.quiet) {
    print_summary(job, result, outcome.written, outcome.kept, outcome.total_seconds, err);
  }
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
  std::int64_t jobs = 1;  // --jobs N: chunks rendered in N processes, then joined
};

// The arguments of `tumble render` for chunk I of N of `line`'s render into `root`: every
// setting `line` gives, so that each chunk draws the frames one process would.
std::vector<std::string> chunk_arguments(const RenderCommandLine& line, const fs::path& root,
                                         std::int64_t index, std::int64_t count) {
  const job::RenderOptions& render = line.render;
  std::vector<std::string> args = {
      "render",      render.scene_path,   "-o",
      root.string(), "--chunk",           std::to_string(index) + "/" + std::to_string(count),
      "-q",          "--png-compression", line.png_compression};
  const auto add = [&](const char* option, const std::string& value) {
    args.push_back(option);
    args.push_back(value);
  };
  if (render.quality) add("--quality", *render.quality);
  if (render.width) add("--width", std::to_string(*render.width));
  if (render.height) add("--height", std::to_string(*render.height));
  if (render.fps) add("--fps", std::to_string(*render.fps));
  for (const std::string& format : render.formats) add("--format", format);
  if (!render.frames) args.push_back("--no-frames");
  if (!render.video) args.push_back("--no-video");
  if (render.serial) args.push_back("--serial");
  if (!line.backend.empty()) add("--backend", line.backend);
  if (render.egl_device) add("--egl-device", std::to_string(*render.egl_device));
  return args;
}

// `tumble render --jobs N`: the render's frames in N chunks (as `tumble plan --chunks N` cuts
// them), each rendered by a `tumble render --chunk I/N` process of its own, all at once, into a
// hidden folder beside the output; then joined into the render's folder as `tumble join` joins
// them (frames merged, videos joined by stream copy) and the hidden folder removed. The frames
// are a one-process render's, byte for byte.
CommandResult run_in_jobs(const RenderCommandLine& line,
                          const std::optional<diff::DiffCommandOptions>& golden) {
  const job::RenderOptions& options = line.render;
  sys::install_interrupt_handlers();
  Result<std::string> text = scene::read_scene_text(options.scene_path);
  if (!text) return Error{text.error()};
  const Result<job::PreparedRender> prepared =
      job::prepare_render(std::move(text).value(), options, Clock::now());
  if (!prepared) return Error{prepared.error()};
  const job::RenderJob& job = prepared->job;
  if (const Result<void> joinable = job::check_joinable_formats(job.scene, "--jobs"); !joinable) {
    return Error{joinable.error()};
  }
  if (golden) {
    if (const Result<void> usable = job::check_golden(*golden, job); !usable) {
      return Error{usable.error()};
    }
  }
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (error) return Error{"--jobs: cannot find tumble's own executable: " + error.message()};
  const std::int64_t count = std::min<std::int64_t>(line.jobs, job.frame_count);
  // Hidden, beside the final folder: on the same file system, so that join links the frames.
  const fs::path root = job.output_root / (".jobs-" + job.directory.filename().string() + "-" +
                                           std::to_string(::getpid()));
  fs::create_directories(root, error);
  if (error) return Error{"cannot create " + root.string() + ": " + error.message()};
  std::vector<sys::ProgramRun> runs;
  JoinOptions join{.out = job.directory.string(), .chunks = {}, .quiet = options.quiet};
  for (std::int64_t i = 1; i <= count; ++i) {
    runs.push_back({executable.string(), chunk_arguments(line, root, i, count)});
    join.chunks.push_back((root / (job.scene.output.directory + ".chunk-" + std::to_string(i) +
                                   "-of-" + std::to_string(count)))
                              .string());
  }
  if (!options.quiet) {
    std::fprintf(stderr, "tumble: rendering %lld frames in %lld processes (--jobs)\n",
                 static_cast<long long>(job.frame_count), static_cast<long long>(count));
  }
  const Result<void> ran = sys::run_together(
      runs, [] { return sys::interrupt_signal() != 0; },
      [&](std::size_t i) {
        if (!options.quiet)
          std::fprintf(stderr, "tumble: chunk %zu of %lld done\n", i + 1,
                       static_cast<long long>(count));
      });
  CommandResult joined = kExitOk;
  if (const int signal = sys::interrupt_signal()) {
    std::fprintf(stderr, "tumble: stopped by %s; %s was left as it was\n", sys::signal_name(signal),
                 job.directory.c_str());
    joined = interrupted_by(signal);
  } else if (!ran) {
    joined = Error{"--jobs: a chunk's render failed: " + ran.error() + "; " +
                   job.directory.string() + " was left as it was"};
  } else {
    joined = run_join(join, stderr);
  }
  fs::remove_all(root, error);
  if (!joined || *joined != kExitOk) return joined;
  return golden ? job::compare_with_golden(*golden, job, stdout) : kExitOk;
}

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
  if (line.jobs > 1) return run_in_jobs(line, compare);
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
  CLI::Option* chunk = command->get_option("--chunk");
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
  CLI::Option* jobs =
      command
          ->add_option(
              "--jobs", line->jobs,
              "Render in N processes at once, each a chunk of the frames (as --chunk I/N), "
              "then join them: the same frames, for machines with more cores than "
              "llvmpipe uses")
          ->check(whole_number_in(1, 1024, "1 to 1024"))
          ->capture_default_str();
  command->add_flag("--serial", render.serial,
                    "Render, write and encode on one thread (slower; same bytes)");
  add_setting_option(command, common::render_setting("backend"), line->backend);
  add_setting_option(command, common::render_setting("egl_device"), render.egl_device);
  command
      ->add_option("--png-compression", line->png_compression,
                   "fast (tumble's own encoder), default (libpng's: zlib 6, adaptive filter) or "
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
  jobs->excludes(frames)->excludes(chunk);
  commands.push_back({command, [line] { return run_command_line(*line); }});
}

}  // namespace tumble::cli
