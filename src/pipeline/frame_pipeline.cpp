#include "pipeline/frame_pipeline.hpp"

#include <sys/resource.h>
#include <time.h>

#include <atomic>
#include <chrono>
#include <deque>
#include <mutex>
#include <system_error>
#include <thread>

#include "common/bounded_queue.hpp"

namespace tumble::pipeline {
namespace {

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Times one piece of work on the current thread into `into`.
template <typename Work>
auto timed(StageTime& into, Work&& work) {
  const double cpu = thread_cpu_seconds();
  const double wall = wall_seconds();
  struct Add {
    StageTime& into;
    double cpu, wall;
    ~Add() {
      into.cpu += thread_cpu_seconds() - cpu;
      into.wall += wall_seconds() - wall;
    }
  } add{into, cpu, wall};
  return work();
}

struct Slot {
  io::Image image;
  std::int64_t frame = 0;
  std::atomic<std::size_t> pending{0};  // sinks that have not finished with this frame
};

// Pulls frame k from the source and draws it into `image`, or says why the run must stop.
Result<void> draw_frame(FrameSource& source, render::Renderer& renderer, std::int64_t k,
                        io::Image& image, PipelineReport& report) {
  const Result<render::FrameView> view = timed(report.simulate, [&] { return source.view(k); });
  if (!view) return Error{view.error()};
  timed(report.render, [&] { renderer.draw(*view, image); });
  return Result<void>::success();
}

void finish_times(PipelineReport& report, double start_wall, double start_cpu) {
  report.wall = wall_seconds() - start_wall;
  report.process_cpu = process_cpu_seconds() - start_cpu;
  // The renderer's own threads (llvmpipe) are not the calling thread: count every CPU second no
  // other stage claimed as rendering.
  double claimed = report.simulate.cpu;
  for (const StageTime& sink : report.sinks) claimed += sink.cpu;
  report.render.cpu = std::max(0.0, report.process_cpu - claimed);
}

Result<void> run_serial(std::int64_t first, std::int64_t end, FrameSource& source,
                        render::Renderer& renderer, const std::vector<FrameSink*>& sinks,
                        const std::function<void(std::int64_t done)>& on_frame_done,
                        PipelineReport& report) {
  io::Image image;
  for (std::int64_t k = first; k < end; ++k) {
    Result<void> done = draw_frame(source, renderer, k, image, report);
    for (std::size_t i = 0; i < sinks.size() && done; ++i) {
      done = timed(report.sinks[i], [&] { return sinks[i]->write(k, image); });
    }
    if (!done) return done;
    on_frame_done(++report.frames_done);
  }
  return Result<void>::success();
}

Result<void> run_pipelined(std::int64_t first, std::int64_t end, FrameSource& source,
                           render::Renderer& renderer, const std::vector<FrameSink*>& sinks,
                           const std::function<void(std::int64_t done)>& on_frame_done,
                           PipelineReport& report) {
  // Frames in flight: one being drawn, one with each sink, and one spare so that the drawing
  // thread never waits for a slot while every sink is busy. 4 × 2.8 MB at 1280×720 for PNG + MP4.
  const std::size_t slot_count = sinks.size() + 2;
  std::vector<Slot> slots(slot_count);
  common::BoundedQueue<std::size_t> free_slots(slot_count);
  std::deque<common::BoundedQueue<std::size_t>> queues;  // one per sink; a queue cannot move
  for (std::size_t i = 0; i < sinks.size(); ++i) queues.emplace_back(slot_count);
  for (std::size_t i = 0; i < slot_count; ++i) free_slots.push(i);

  std::mutex done_mutex;  // guards failure, report.frames_done and on_frame_done
  std::string failure;    // the first error, "" while there is none
  const auto fail = [&](const std::string& error) {
    {
      std::lock_guard lock(done_mutex);
      if (failure.empty()) failure = error;
    }
    free_slots.abort();
    for (common::BoundedQueue<std::size_t>& queue : queues) queue.abort();
  };
  const auto release = [&](std::size_t slot) {
    if (slots[slot].pending.fetch_sub(1) != 1) return;
    {
      std::lock_guard lock(done_mutex);
      on_frame_done(++report.frames_done);
    }
    free_slots.push(slot);
  };
  // One worker per sink; each times its work into its own StageTime.
  const auto worker = [&](std::size_t i) {
    while (const std::optional<std::size_t> slot = queues[i].pop()) {
      Slot& s = slots[*slot];
      const Result<void> written =
          timed(report.sinks[i], [&] { return sinks[i]->write(s.frame, s.image); });
      if (!written) {
        fail(written.error());
        return;
      }
      release(*slot);
    }
  };
  std::vector<std::thread> threads;
  threads.reserve(sinks.size());
  try {
    for (std::size_t i = 0; i < sinks.size(); ++i) threads.emplace_back(worker, i);
  } catch (const std::system_error& error) {  // out of memory or of threads (ulimit -v, -u)
    fail(std::string("cannot start a worker thread: ") + error.what());
    for (std::thread& thread : threads) thread.join();  // the aborted queues let it finish
    return Error{failure};
  }

  for (std::int64_t k = first; k < end; ++k) {
    const std::optional<std::size_t> slot = free_slots.pop();
    if (!slot) break;  // a worker failed
    Slot& s = slots[*slot];
    if (const Result<void> drawn = draw_frame(source, renderer, k, s.image, report); !drawn) {
      fail(drawn.error());
      break;
    }
    s.frame = k;
    s.pending = sinks.empty() ? 1 : sinks.size();
    if (sinks.empty()) {  // drawing only, as when measuring the renderer alone
      release(*slot);
      continue;
    }
    bool queued = true;
    for (common::BoundedQueue<std::size_t>& queue : queues) queued = queued && queue.push(*slot);
    if (!queued) break;
  }
  for (common::BoundedQueue<std::size_t>& queue : queues) queue.close();
  for (std::thread& thread : threads) thread.join();
  if (!failure.empty()) return Error{failure};
  return Result<void>::success();
}

}  // namespace

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

Result<void> run_frames(std::int64_t first, std::int64_t end, FrameSource& source,
                        render::Renderer& renderer, const std::vector<FrameSink*>& sinks,
                        bool serial, const std::function<void(std::int64_t done)>& on_frame_done,
                        PipelineReport& report) {
  report = PipelineReport{};
  report.sinks.resize(sinks.size());
  const double start_wall = wall_seconds();
  const double start_cpu = process_cpu_seconds();
  Result<void> ran =
      serial ? run_serial(first, end, source, renderer, sinks, on_frame_done, report)
             : run_pipelined(first, end, source, renderer, sinks, on_frame_done, report);
  finish_times(report, start_wall, start_cpu);
  return ran;
}

}  // namespace tumble::pipeline
