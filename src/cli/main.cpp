// The command line: parses arguments and hands them to the commands in src/app/.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstdio>
#include <cstring>
#include <optional>
#include <utility>
#include <vector>

#include "bench/jobs/bench_contact.hpp"
#include "bench/jobs/bench_pipeline.hpp"
#include "cli/bench_command.hpp"
#include "cli/check_command.hpp"
#include "cli/join_command.hpp"
#include "cli/plan_command.hpp"
#include "cli/render_command.hpp"
#include "cli/simulate_command.hpp"
#include "diff/diff_command.hpp"
#include "io/png_io.hpp"
#include "render/offscreen_context.hpp"
#include "scene/limits.hpp"
#include "sys/process.hpp"

namespace {

// A whole number from `min` to `max`, with a message a person can read (CLI11's own ranges print
// DBL_MAX); `range` says which in words.
CLI::Validator whole_number_in(long long min, long long max, const std::string& range) {
  return CLI::Validator(
      [=](std::string& value) {
        long long parsed = 0;
        const auto [end, error] =
            std::from_chars(value.data(), value.data() + value.size(), parsed);
        const bool whole = error == std::errc() && end == value.data() + value.size();
        return whole && parsed >= min && parsed <= max
                   ? std::string()
                   : "expected a whole number " + range + ", got " + value;
      },
      range);
}

// "A:B" as two whole numbers, each within long long; nothing else.
std::optional<std::pair<long long, long long>> parse_range(const std::string& text) {
  const char* const end = text.data() + text.size();
  long long first = 0, last = 0;
  const auto [colon, first_error] = std::from_chars(text.data(), end, first);
  if (first_error != std::errc() || colon == end || *colon != ':') return std::nullopt;
  const auto [after, last_error] = std::from_chars(colon + 1, end, last);
  if (last_error != std::errc() || after != end) return std::nullopt;
  return std::make_pair(first, last);
}

// A file or folder name given on the command line: "" would mean the current folder or nothing.
const CLI::Validator kNotEmpty(
    [](std::string& value) {
      return value.empty() ? std::string("expected a name, got \"\"") : "";
    },
    "NAME");

// How frames are compared and what is written of the comparison: `tumble diff` and
// `tumble render --golden` take the same options. Returns --ignore-antialiasing, whose default
// depends on the metric (applied when it was not given). With `needs`, each is refused without it.
CLI::Option* add_comparison_options(CLI::App* command, tumble::diff::DiffCommandOptions& diff,
                                    bool& ignore_antialiasing, CLI::Option* needs = nullptr) {
  const std::size_t before = command->get_options().size();
  command
      ->add_option("--metric", diff.metric,
                   "max (channel levels), rms (levels), perceptual (YIQ distance 0-1, as "
                   "pixelmatch), ssim (0-1) or psnr (dB)")
      ->check(CLI::IsMember({"max", "rms", "perceptual", "ssim", "psnr"}))
      ->capture_default_str();
  command->add_option(
      "--threshold", diff.threshold,
      "In the metric's unit: a pixel differs beyond it (max: 0-255, default 0; perceptual: 0-1, "
      "default 0.1); a frame differs beyond it (rms: 0-255, default 1; ssim below it: 0-1, "
      "default 0.99; psnr below it: dB, default 40)");
  CLI::Option* antialiasing = command->add_flag(
      "--ignore-antialiasing,!--count-antialiasing", ignore_antialiasing,
      "Do not count pixels on anti-aliased edges (Vyšniauskas 2009, as pixelmatch); default on "
      "for perceptual only");
  CLI::Option* max_pixels =
      command
          ->add_option("--max-pixels", diff.max_pixels,
                       "A frame matches when at most this many pixels differ (default 0)")
          ->check(whole_number_in(0, LLONG_MAX, ">= 0"));
  command
      ->add_option("--max-percent", diff.max_percent,
                   "A frame matches when at most this share of its pixels differ (%)")
      ->check(CLI::Range(0.0, 100.0))
      ->excludes(max_pixels);
  command
      ->add_option("--report", diff.report,
                   "Write an HTML report (index.html and images) into this folder")
      ->check(kNotEmpty);
  command->add_option("--junit", diff.junit, "Write JUnit XML, one test case per frame")
      ->check(kNotEmpty);
  command->add_option("--json", diff.json, "Write every figure as JSON")->check(kNotEmpty);
  const std::vector<CLI::Option*> added = command->get_options();
  for (std::size_t i = before; needs && i < added.size(); ++i) added[i]->needs(needs);
  return antialiasing;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tumble::cli;
  using namespace tumble::diff;
  using namespace tumble::bench;
  using namespace tumble::job;
  using tumble::sys::set_up_process;
  tumble::sys::set_up_process();
  CLI::App app{"tumble: rigid-body scenes to frames and video, headless"};
  app.require_subcommand(1);

  SimulateOptions simulate;
  CLI::App* simulate_command =
      app.add_subcommand("simulate", "Run a scene's physics and write the states as CSV");
  simulate_command->add_option("scene", simulate.scene_path, "Scene file (TOML)")->required();
  simulate_command->add_option("--out", simulate.out, "CSV file to write, or - for stdout")
      ->check(kNotEmpty)
      ->capture_default_str();
  simulate_command->add_option("--every", simulate.every, "Write a row every N steps")
      ->check(whole_number_in(1, LLONG_MAX, ">= 1"))
      ->capture_default_str();

  tumble::job::RenderOptions render;
  std::string frame_range;
  CLI::App* render_command = app.add_subcommand(
      "render", "Render a scene to PNG frames and videos (MP4, WebM, GIF), off-screen");
  render_command->add_option("scene", render.scene_path, "Scene file (TOML)")->required();
  render_command
      ->add_option("-o,--output", render.output_root,
                   "Output folder; files go to OUTPUT/<scene name>/")
      ->check(kNotEmpty)
      ->capture_default_str();
  render_command->add_option("--width", render.width, "Image width (pixels)")
      ->check(CLI::Range(tumble::scene::kMinImageSide, tumble::scene::kMaxImageSide));
  render_command->add_option("--height", render.height, "Image height (pixels)")
      ->check(CLI::Range(tumble::scene::kMinImageSide, tumble::scene::kMaxImageSide));
  render_command->add_option("--fps", render.fps, "Frames per second")->check(CLI::Range(1, 240));
  CLI::Option* frames_option =
      render_command->add_option("--frames", frame_range, "Render frames A to B-1 only (A:B)")
          ->check(kNotEmpty);
  std::string chunk_index;
  render_command
      ->add_option("--chunk", chunk_index,
                   "Render chunk I of N (I/N, from 1): the frames of line I of `tumble plan "
                   "--chunks N`, into OUTPUT/<scene output directory>.chunk-I-of-N/")
      ->check(kNotEmpty)
      ->excludes(frames_option);
  render_command->add_flag("!--no-frames", render.frames, "Do not write PNG frames");
  render_command->add_option(
      "--quality", render.quality,
      "Size and frame rate: low (854x480, 15 fps), medium (1280x720, 30), high (1920x1080, 60), "
      "production (2560x1440, 60), 4k (3840x2160, 60); --width, --height, --fps win");
  render_command
      ->add_option("--format", render.formats,
                   "Video formats to write, mp4, webm or gif: repeat or separate with commas "
                   "(replaces [output] formats)")
      ->delimiter(',');
  render_command->add_flag("!--no-video", render.video, "Do not write any video");
  render_command->add_flag("-q,--quiet", render.quiet, "No progress and no summary");
  render_command->add_flag("-v,--verbose", render.verbose, "Print the OpenGL renderer in use");
  render_command->add_flag("--serial", render.serial,
                           "Render, write and encode on one thread (slower; same bytes)");
  std::string backend;
  render_command
      ->add_option(
          "--backend", backend,
          "Off-screen OpenGL: osmesa, egl (a GPU's EGL device, else surfaceless) or auto (EGL "
          "on a GPU, else OSMesa if built in); "
          "replaces the scene's [render] backend")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
  render_command
      ->add_option("--egl-device", render.egl_device,
                   "Draw with EGL on device N of EGL's list (EGL_EXT_platform_device; a wrong N "
                   "lists them); replaces the scene's [render] egl_device")
      ->check(CLI::Range(0, tumble::common::kMaxEglDevice));
  std::string png_compression = "fast";
  render_command
      ->add_option("--png-compression", png_compression,
                   "fast (zlib 1, no filter), default (libpng's: zlib 6, adaptive filter) or "
                   "small (zlib 9, adaptive filter)")
      ->check(CLI::IsMember({"fast", "default", "small"}))
      ->capture_default_str();
  tumble::diff::DiffCommandOptions golden;
  CLI::Option* golden_option =
      render_command
          ->add_option(
              "--golden", golden.first_path,
              "Then compare the render with this golden render (its folder, a folder of "
              "frames or a video) as `tumble diff` does: exit 0 match, 1 mismatch, 2 error")
          ->check(kNotEmpty);
  bool golden_antialiasing = false;
  CLI::Option* golden_antialiasing_option =
      add_comparison_options(render_command, golden, golden_antialiasing, golden_option);

  PlanOptions plan;
  CLI::App* plan_command = app.add_subcommand(
      "plan", "Print the frame ranges of a render cut into chunks, one A:B per line");
  plan_command->add_option("scene", plan.render.scene_path, "Scene file (TOML)")->required();
  CLI::Option* plan_chunks =
      plan_command->add_option("--chunks", plan.chunks, "Cut into N chunks, as even as possible")
          ->check(whole_number_in(1, LLONG_MAX, ">= 1"));
  plan_command
      ->add_option("--chunk-frames", plan.chunk_frames,
                   "Cut into as few chunks of at most K frames as cover the scene, as even as "
                   "possible")
      ->check(whole_number_in(1, LLONG_MAX, ">= 1"))
      ->excludes(plan_chunks);
  plan_command->add_option("--fps", plan.render.fps, "Frames per second (as render --fps)")
      ->check(CLI::Range(1, 240));
  plan_command->add_option("--quality", plan.render.quality,
                           "Size and frame rate preset (as render --quality): the frame count "
                           "follows its rate");
  plan_command->add_flag("--json", plan.json, "Print the plan as JSON");

  JoinOptions join;
  CLI::App* join_command = app.add_subcommand(
      "join", "Join the chunk folders of one render into one render folder (frames, MP4, report)");
  join_command->add_option("out", join.out, "Render folder to write (replaced as a whole)")
      ->required()
      ->check(kNotEmpty);
  join_command->add_option("chunks", join.chunks, "Chunk folders, in any order")
      ->required()
      ->check(kNotEmpty);
  join_command->add_flag("-q,--quiet", join.quiet, "No summary");

  tumble::diff::DiffCommandOptions diff;
  std::string diff_frames;
  CLI::App* diff_command = app.add_subcommand(
      "diff",
      "Compare two PNGs, folders of frames, renders or videos: exit 0 if they match within the "
      "tolerance, 1 if not, 2 on error");
  diff_command->add_option("first", diff.first_path, "A, the expected: PNG, folder or video")
      ->required();
  diff_command->add_option("second", diff.second_path, "B, the actual: PNG, folder or video")
      ->required();
  bool diff_antialiasing = false;
  CLI::Option* antialiasing = add_comparison_options(diff_command, diff, diff_antialiasing);
  diff_command->add_option("--frames", diff_frames, "Compare frames A to B-1 only (A:B)")
      ->check(kNotEmpty);
  diff_command->add_option("--out", diff.out, "Two PNGs: write an image of the differences here")
      ->check(kNotEmpty);

  CLI::App* bench_command = app.add_subcommand("bench", "Measure tumble's speed");
  bench_command->require_subcommand(1);
  tumble::bench::BenchPipelineOptions bench_pipeline;
  CLI::App* bench_pipeline_command = bench_command->add_subcommand(
      "pipeline", "Render one scene the naive ways and tumble's way, in one run, and compare");
  bench_pipeline_command->add_option(
      "--scene", bench_pipeline.scene_path,
      "Scene to render (default: a built-in lit cube with ground and shadow)");
  bench_pipeline_command->add_option("--width", bench_pipeline.width, "Image width")
      ->check(CLI::Range(tumble::scene::kMinImageSide, tumble::scene::kMaxImageSide))
      ->capture_default_str();
  bench_pipeline_command->add_option("--height", bench_pipeline.height, "Image height")
      ->check(CLI::Range(tumble::scene::kMinImageSide, tumble::scene::kMaxImageSide))
      ->capture_default_str();
  bench_pipeline_command->add_option("--frames", bench_pipeline.frames, "Frames per path")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{100000}))
      ->capture_default_str();
  bench_pipeline_command
      ->add_option("--msaa", bench_pipeline.msaa,
                   "Samples per pixel (default: the scene's [render] msaa, as tumble render)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16}));
  bench_pipeline_command
      ->add_option("--chunks", bench_pipeline.chunks,
                   "Instead: the whole render against N chunks, each a process of its own "
                   "(per-chunk overhead and total CPU)")
      ->check(whole_number_in(1, 100000, "from 1 to 100000"));
  bench_pipeline_command->add_option("--out", bench_pipeline.out, "Folder for pipeline.md")
      ->check(kNotEmpty)
      ->capture_default_str();

  BenchAccuracyOptions bench_accuracy;
  CLI::App* bench_accuracy_command = bench_command->add_subcommand(
      "accuracy", "Error against cost of every integrator on hard cases: CSV, Markdown, chart");
  bench_accuracy_command
      ->add_option("--out", bench_accuracy.out, "Folder for accuracy.csv, .md and .png")
      ->check(kNotEmpty)
      ->capture_default_str();
  bench_accuracy_command->add_flag("--quick", bench_accuracy.quick,
                                   "A reduced sweep (3 cases, 2 step sizes, 1 timing) for tests");

  tumble::bench::BenchContactOptions bench_contact;
  CLI::App* bench_contact_command = bench_command->add_subcommand(
      "contact",
      "The pile of issue 12 in tumble and in Bullet 3.24 (through contact_bench), in one run");
  bench_contact_command->add_option("--bodies", bench_contact.bodies, "Boxes in the pile")
      ->check(whole_number_in(0, 100000, "from 0 to 100000"))
      ->capture_default_str();
  bench_contact_command
      ->add_option("--seconds", bench_contact.seconds, "Simulated time (s), in steps of 1/60 s")
      ->check(CLI::Range(0.0, 3600.0))
      ->capture_default_str();
  bench_contact_command
      ->add_option("--seed", bench_contact.seed,
                   "Seed of the boxes' sizes, orientations and velocities")
      ->capture_default_str();
  bench_contact_command
      ->add_option("--out", bench_contact.out,
                   "An existing folder for contact_bench.json and contact_bench.csv")
      ->check(kNotEmpty);
  bench_contact_command->add_flag("-q,--quiet", bench_contact.quiet, "No progress");

  CheckOptions check;
  CLI::App* check_command = app.add_subcommand(
      "check", "Validate a scene and warn about its step: exit 0 if valid, 2 if not");
  check_command->add_option("scene", check.scene_path, "Scene file (TOML)")->required();

  if (argc < 2) {
    std::fputs(app.help().c_str(), stderr);
    return tumble::kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? tumble::kExitOk : tumble::kExitBadInput;
  }

  const auto run_parsed = [&]() -> int {
    if (simulate_command->parsed()) return run_simulate(simulate, stderr);
    if (bench_pipeline_command->parsed())
      return tumble::bench::run_bench_pipeline(bench_pipeline, stdout, stderr);
    if (bench_accuracy_command->parsed()) return run_bench_accuracy(bench_accuracy, stdout, stderr);
    if (bench_contact_command->parsed())
      return tumble::bench::run_bench_contact(bench_contact, stdout, stderr);
    if (check_command->parsed()) return run_check(check, stdout, stderr);
    if (plan_command->parsed()) return run_plan(plan, stdout, stderr);
    if (join_command->parsed()) return run_join(join, stderr);
    if (diff_command->parsed()) {
      if (!diff_frames.empty()) {
        diff.frames = parse_range(diff_frames);
        if (!diff.frames) {
          std::fprintf(stderr, "tumble: --frames: expected A:B (frames A to B-1), got %s\n",
                       diff_frames.c_str());
          return tumble::kExitBadInput;
        }
      }
      if (antialiasing->count() > 0) diff.ignore_antialiasing = diff_antialiasing;
      return tumble::diff::run_diff(diff, stdout, stderr);
    }
    if (render_command->parsed()) {
      if (!frame_range.empty()) {
        const std::optional<std::pair<long long, long long>> range = parse_range(frame_range);
        if (!range) {
          std::fprintf(stderr, "tumble: --frames: expected A:B (frames A to B-1), got %s\n",
                       frame_range.c_str());
          return tumble::kExitBadInput;
        }
        render.first_frame = range->first;
        render.end_frame = range->second;
      }
      if (!chunk_index.empty()) {
        render.chunk = tumble::job::parse_chunk_index(chunk_index);
        if (!render.chunk) {
          std::fprintf(stderr,
                       "tumble: --chunk: expected I/N (chunk I of N, 1 <= I <= N), got %s\n",
                       chunk_index.c_str());
          return tumble::kExitBadInput;
        }
      }
      render.png = *tumble::io::png_settings_named(png_compression);  // checked by IsMember
      for (const auto each : tumble::common::kAllBackends) {
        if (backend == tumble::render::backend_name(each)) render.backend = each;
      }
      std::optional<tumble::diff::DiffCommandOptions> compare;
      if (!golden.first_path.empty()) {
        if (golden_antialiasing_option->count() > 0) {
          golden.ignore_antialiasing = golden_antialiasing;
        }
        compare = golden;
      }
      return run_render(render, compare, stdout, stderr);
    }
    return tumble::kExitBadInput;
  };
  try {
    const int code = run_parsed();
    // What a command printed must have reached standard output (`tumble check s.toml >
    // /dev/full` must not succeed, nor `diff` report a mismatch nobody saw). A command that
    // failed otherwise has said why already.
    const bool flushed = std::fflush(stdout) == 0;
    const int reason = errno;
    if ((!flushed || std::ferror(stdout)) &&
        (code == tumble::kExitOk || code == tumble::kExitMismatch)) {
      std::fprintf(stderr, "tumble: error writing to standard output%s%s\n", flushed ? "" : ": ",
                   flushed ? "" : std::strerror(reason));
      return tumble::kExitBadInput;
    }
    return code;
  } catch (const std::bad_alloc&) {
    std::fputs("tumble: out of memory\n", stderr);
  } catch (const std::exception& error) {  // a last resort: each command reports its own errors
    std::fprintf(stderr, "tumble: %s\n", error.what());
  }
  return tumble::kExitBadInput;
}
