#include "bench/jobs/bench_chunks.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <sstream>
#include <vector>

#include "sys/interrupt.hpp"

namespace tumble::bench {
namespace {

namespace fs = std::filesystem;

// What a forked run sends back through its pipe: plain bytes, no pointers.
struct RunFigures {
  double framing = 0.0, renderer = 0.0, seek = 0.0;  // s, CPU (RenderResult)
  std::int64_t seek_steps = 0;
  char error[480] = {};  // "" on success
};

struct Run {
  std::string name;
  job::FrameRange frames;
  RunFigures figures;
  double cpu = 0.0;   // s, user + system of the whole process (every thread)
  double wall = 0.0;  // s
};

double seconds(const timeval& time) {
  return static_cast<double>(time.tv_sec) + static_cast<double>(time.tv_usec) * 1e-6;
}

// The child's side: render, report, exit without running the parent's destructors.
[[noreturn]] void render_in_child(const job::RenderJob& job, const fs::path& folder, int pipe_out) {
  RunFigures figures;
  std::error_code ignored;
  fs::create_directories(folder, ignored);
  job::RenderResult result;
  const Result<void> rendered = job::render_scene(
      job, folder, [] { return sys::interrupt_signal() != 0; }, [](std::int64_t) {}, result);
  figures.framing = result.framing_seconds;
  figures.renderer = result.renderer_seconds;
  figures.seek = result.seek_seconds;
  figures.seek_steps = result.seek_steps;
  if (!rendered) std::strncpy(figures.error, rendered.error().c_str(), sizeof figures.error - 1);
  const bool sent = ::write(pipe_out, &figures, sizeof figures) == sizeof figures;
  ::_exit(sent && rendered ? 0 : 1);
}

// One render of `job` in a process of its own, timed.
Result<Run> run_forked(const job::RenderJob& job, const fs::path& folder) {
  int pipe_ends[2];
  if (::pipe(pipe_ends) != 0) return Error{std::string("pipe: ") + std::strerror(errno)};
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  if (child < 0) return Error{std::string("fork: ") + std::strerror(errno)};
  if (child == 0) {
    ::close(pipe_ends[0]);
    render_in_child(job, folder, pipe_ends[1]);
  }
  ::close(pipe_ends[1]);
  Run run;
  const bool received = ::read(pipe_ends[0], &run.figures, sizeof run.figures) ==
                        static_cast<ssize_t>(sizeof run.figures);
  ::close(pipe_ends[0]);
  int status = 0;
  rusage usage{};
  while (::wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  run.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.cpu = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  if (!received || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return Error{run.figures.error[0]
                     ? std::string(run.figures.error)
                     : "a benchmark run died (status " + std::to_string(status) + ")"};
  }
  run.frames = {job.first, job.end};
  return run;
}

std::string table(const std::vector<Run>& runs, const job::RenderJob& job, std::int64_t chunks) {
  const Run& whole = runs.front();
  double cpu = 0.0, wall = 0.0, overhead = 0.0;
  for (std::size_t i = 1; i < runs.size(); ++i) {
    cpu += runs[i].cpu;
    wall += runs[i].wall;
    overhead += runs[i].figures.framing + runs[i].figures.renderer + runs[i].figures.seek;
  }
  std::ostringstream out;
  out.precision(3);
  out << std::fixed << "Chunk benchmark: " << job.frame_count << " frames at "
      << job.scene.render.width << "x" << job.scene.render.height
      << ", antialiasing: " << job::antialiasing_name(job.scene.render.msaa) << ", whole and as "
      << chunks << " chunks, each a process of its own, one after another\n\n"
      << "| run | frames | CPU s | wall s | framing pass CPU s | context + shaders CPU s | physics "
         "to first frame CPU s (steps) |\n| --- | --- | ---: | ---: | ---: | ---: | ---: |\n";
  for (const Run& run : runs) {
    out << "| " << run.name << " | " << job::range_text(run.frames) << " | " << run.cpu << " | "
        << run.wall << " | " << run.figures.framing << " | " << run.figures.renderer << " | "
        << run.figures.seek << " (" << run.figures.seek_steps << ") |\n";
  }
  out << "| all " << chunks << " chunks | 0:" << job.frame_count << " | " << cpu << " | " << wall
      << " | | | |\n\n"
      << "CPU of the " << chunks << " chunks / CPU of the whole render: " << cpu / whole.cpu << " ("
      << (cpu / whole.cpu - 1.0) * 100.0 << " %); overhead per chunk (framing, context "
      << "and shaders, physics to its first frame; CPU): " << overhead / static_cast<double>(chunks)
      << " s\n";
  return out.str();
}

}  // namespace

Result<std::string> bench_chunks(const job::RenderJob& job, std::int64_t chunks,
                                 const fs::path& scratch, std::FILE* err) {
  const Result<std::vector<job::FrameRange>> plan = job::plan_chunks(job.frame_count, chunks);
  if (!plan) return Error{"--chunks: " + plan.error()};
  std::vector<Run> runs;
  for (std::size_t i = 0; i <= plan->size(); ++i) {
    job::RenderJob variant = job;
    std::string name = "whole";
    if (i > 0) {
      variant.first = (*plan)[i - 1].first;
      variant.end = (*plan)[i - 1].end;
      name = "chunk " + std::to_string(i) + "/" + std::to_string(chunks);
    }
    std::fprintf(err, "bench: %s ...\n", name.c_str());
    Result<Run> run = run_forked(variant, scratch / ("run-" + std::to_string(i)));
    if (!run) return Error{name + ": " + run.error()};
    if (sys::interrupt_signal() != 0) return Error{"stopped"};
    run->name = name;
    runs.push_back(*run);
  }
  return table(runs, job, chunks);
}

}  // namespace tumble::bench
