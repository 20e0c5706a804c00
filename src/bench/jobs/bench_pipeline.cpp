#include "bench/jobs/bench_pipeline.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <thread>
#include <variant>
#include <vector>

#include "bench/jobs/bench_chunks.hpp"
#include "common/exit_codes.hpp"
#include "io/atomic_file.hpp"
#include "io/staged_directory.hpp"
#include "job/render_job.hpp"
#include "scene/scene_loader.hpp"
#include "sys/interrupt.hpp"

namespace tumble::bench {
namespace {

namespace fs = std::filesystem;

constexpr const char* kBenchScene = R"(name = "bench_pipeline"
duration = 5.0
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 1.0
angular_velocity = [0.8, 2.5, 1.2]
)";

struct PathResult {
  std::string name;
  std::string how;
  double seconds = 0.0;     // wall, from the first frame to the finished video
  double efficiency = 0.0;  // (CPU seconds / cores) / wall seconds; 0 when not measured
  std::string note;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The table on `out` and in OUT/pipeline.md.
Result<ExitCode> publish(const std::string& table, const BenchPipelineOptions& options,
                         std::FILE* out) {
  std::fputs(table.c_str(), out);
  const Result<void> written =
      io::write_file_atomically((fs::path(options.out) / "pipeline.md").string(), table);
  if (!written) return Error{written.error()};
  return kExitOk;
}

}  // namespace

Result<ExitCode> run_bench_pipeline(const BenchPipelineOptions& options, std::FILE* out,
                                    std::FILE* err) {
  const Result<scene::Scene> loaded = options.scene_path.empty()
                                          ? scene::parse_scene(kBenchScene, "bench_pipeline.toml")
                                          : scene::load_scene_file(options.scene_path);
  if (!loaded) return Error{loaded.error()};
  // The benchmark's sizes, rate and length override the scene's, as `tumble render`'s do, and
  // are held to the same rules (render_job.hpp).
  job::RenderOptions overrides;
  overrides.width = options.width;
  overrides.height = options.height;
  overrides.duration = static_cast<double>(options.frames) / loaded->fps;
  if (options.msaa != 0) overrides.msaa = options.msaa;
  const Result<job::RenderJob> job = job::make_render_job(*loaded, overrides);
  if (!job) return Error{job.error()};
  const scene::Scene& scene = job->scene;

  // The frames and videos, written only to be timed, go to a hidden scratch folder beside the
  // report (".pipeline.partial-<pid>"), never committed: it is removed on the way out, whatever
  // happens, and nothing of the user's is replaced.
  sys::install_interrupt_handlers();
  const Result<io::StagedDirectory> scratch =
      io::StagedDirectory::create((fs::path(options.out) / "pipeline").string());
  if (!scratch) return Error{scratch.error()};
  const fs::path root = scratch->path();
  if (options.chunks > 0) {
    const Result<std::string> chunk_table = bench_chunks(*job, options.chunks, root, err);
    if (const int signal = sys::interrupt_signal()) {
      std::fprintf(err, "tumble: bench pipeline stopped by %s\n", sys::signal_name(signal));
      return interrupted_by(signal);
    }
    if (!chunk_table) return Error{chunk_table.error()};
    return publish(*chunk_table, options, out);
  }
  std::error_code error_code;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());

  // One way of rendering: a fresh renderer and encoder, the frames, the finished video.
  const auto run = [&](const std::string& name, bool serial, bool frames, bool video,
                       const char* png, const char* preset, PathResult& result) {
    const fs::path directory = root / name;
    fs::create_directories(directory, error_code);
    // The checked job, written another way: outputs on or off (off entirely for the ceiling),
    // other PNG and x264 settings, one thread or the pipeline.
    job::RenderJob variant = *job;
    variant.scene.output.frames = frames;
    variant.scene.output.video = video;
    variant.scene.output.preset = preset;
    variant.png = *io::png_settings_named(png);
    variant.serial = serial;
    variant.stills = false;  // the paths compared write frames and an MP4, nothing else
    std::fprintf(err, "bench: %s ...\n", name.c_str());
    job::RenderResult rendered;
    const Result<void> ran = job::render_scene(
        variant, directory, [] { return sys::interrupt_signal() != 0; }, [](std::int64_t) {},
        rendered);
    result.name = name;
    result.seconds = rendered.pipeline.wall + rendered.finish_seconds;
    result.efficiency = rendered.pipeline.process_cpu / cores / rendered.pipeline.wall;
    return ran;
  };

  std::vector<PathResult> results(4);
  Result<void> ran = run("render_only", false, false, false, "fast", "veryfast", results[0]);
  results[0].how = "draw every frame, write nothing: the ceiling";
  if (ran) ran = run("pipelined", false, true, true, "fast", "veryfast", results[1]);
  results[1].how = "tumble render: PNG (own encoder) and x264 veryfast on worker threads";
  if (ran) ran = run("naive", true, true, true, "default", "medium", results[2]);
  results[2].how = "one thread: draw, libpng defaults, x264 medium in process, frame after frame";
  if (ran) ran = run("png_then_ffmpeg", true, true, false, "default", "medium", results[3]);
  results[3].how = "one thread: draw, libpng defaults; then the ffmpeg program encodes the PNGs";
  if (const int signal = sys::interrupt_signal()) {
    std::fprintf(err, "tumble: bench pipeline stopped by %s\n", sys::signal_name(signal));
    return interrupted_by(signal);
  }
  if (!ran) return Error{ran.error()};

  // The second half of the script most people write: ffmpeg stitching the PNG files.
  const fs::path stitched = root / "png_then_ffmpeg";
  const std::string command =
      "ffmpeg -nostdin -y -loglevel error -framerate " + std::to_string(scene.fps) + " -i " +
      shell_quote((stitched / "frames/frame_%05d.png").string()) +
      " -c:v libx264 -preset medium -crf " + std::to_string(scene.output.crf) +
      " -pix_fmt yuv420p " + shell_quote((stitched / "video.mp4").string());
  const auto ffmpeg_start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  if (status != 0) {
    results[3].note = "ffmpeg failed or is not installed (exit status " + std::to_string(status) +
                      "); PNG part only";
  } else {
    results[3].seconds += seconds_since(ffmpeg_start);
    results[3].efficiency = 0.0;  // a second process: not measured
  }

  const double frames = static_cast<double>(options.frames);
  const double pipelined_fps = frames / results[1].seconds;
  std::ostringstream table;
  table << "Pipeline benchmark: " << options.frames << " frames at " << options.width << "x"
        << options.height << ", antialiasing: " << job::antialiasing_name(scene.render.msaa) << ", "
        << cores << " cores\n\n"
        << "| path | frames/s | seconds | pipelined is × faster | CPU efficiency | what |\n"
        << "| --- | ---: | ---: | ---: | ---: | --- |\n";
  for (const PathResult& r : results) {
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %.1f | %.2f | %.2f | %s | %s%s%s |\n", r.name.c_str(),
                  frames / r.seconds, r.seconds, r.seconds * pipelined_fps / frames,
                  r.efficiency > 0 ? std::to_string(r.efficiency).substr(0, 4).c_str() : "-",
                  r.how.c_str(), r.note.empty() ? "" : "; ", r.note.c_str());
    table << line;
  }
  return publish(table.str(), options, out);
}

}  // namespace tumble::bench
