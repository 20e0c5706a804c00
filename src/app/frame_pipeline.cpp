#include "app/frame_pipeline.hpp"

#include <sys/resource.h>
#include <time.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "app/bounded_queue.hpp"

namespace tumble::app {
namespace {

// Frames in flight: one being drawn, one being written, one being encoded, one spare so that the
// drawing thread never waits for a slot while both workers are busy. 4 × 2.8 MB at 1280×720.
constexpr std::size_t kSlots = 4;

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
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
  std::atomic<int> pending{0};  // sinks that have not finished with this frame
};

// Simulates and draws frame k into `image`: "" or the error the source threw (a blow-up, an
// interruption, a renderer failure).
std::string draw_frame(const FrameSource& source, std::int64_t k, io::Image& image,
                       PipelineReport& report) {
  try {
    const render::FrameView view = timed(report.simulate, [&] { return source.view(k); });
    timed(report.render, [&] { source.draw(view, image); });
    return {};
  } catch (const std::exception& error) {
    return error.what();
  }
}

}  // namespace

PipelineReport run_frames(std::int64_t first, std::int64_t end, const FrameSource& source,
                          const FrameSinks& sinks, bool serial,
                          const std::function<void(std::int64_t done)>& on_frame_done) {
  PipelineReport report;
  const double start_wall = wall_seconds();
  const double start_cpu = process_cpu_seconds();
  const auto finish = [&] {
    report.wall = wall_seconds() - start_wall;
    report.process_cpu = process_cpu_seconds() - start_cpu;
    // The renderer's own threads (llvmpipe) are not the calling thread: count every CPU second
    // no other stage claimed as rendering.
    report.render.cpu =
        std::max(0.0, report.process_cpu - report.simulate.cpu - report.png.cpu - report.video.cpu);
    return report;
  };

  if (serial) {
    io::Image image;
    for (std::int64_t k = first; k < end; ++k) {
      std::string error = draw_frame(source, k, image, report);
      if (error.empty() && sinks.png)
        error = timed(report.png, [&] { return sinks.png(k, image); });
      if (error.empty() && sinks.video) {
        error = timed(report.video, [&] { return sinks.video(image); });
      }
      if (!error.empty()) {
        report.error = error;
        return finish();
      }
      on_frame_done(++report.frames_done);
    }
    return finish();
  }

  std::vector<Slot> slots(kSlots);
  BoundedQueue<std::size_t> free_slots(kSlots), png_queue(kSlots), video_queue(kSlots);
  for (std::size_t i = 0; i < kSlots; ++i) free_slots.push(i);
  const int sinks_per_frame = (sinks.png ? 1 : 0) + (sinks.video ? 1 : 0);

  std::mutex done_mutex;  // guards report.error, report.frames_done and on_frame_done
  const auto fail = [&](const std::string& error) {
    {
      std::lock_guard lock(done_mutex);
      if (report.error.empty()) report.error = error;
    }
    free_slots.abort();
    png_queue.abort();
    video_queue.abort();
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
  const auto worker = [&](BoundedQueue<std::size_t>& queue, StageTime& time, auto&& work) {
    while (const std::optional<std::size_t> slot = queue.pop()) {
      const std::string error = timed(time, [&] { return work(slots[*slot]); });
      if (!error.empty()) {
        fail(error);
        return;
      }
      release(*slot);
    }
  };
  std::vector<std::thread> threads;
  threads.reserve(2);
  try {
    if (sinks.png) {
      threads.emplace_back([&] {
        worker(png_queue, report.png,
               [&](Slot& slot) { return sinks.png(slot.frame, slot.image); });
      });
    }
    if (sinks.video) {
      threads.emplace_back([&] {
        worker(video_queue, report.video, [&](Slot& slot) { return sinks.video(slot.image); });
      });
    }
  } catch (const std::system_error& error) {  // out of memory or of threads (ulimit -v, -u)
    fail(std::string("cannot start a worker thread: ") + error.what());
    for (std::thread& thread : threads) thread.join();  // the aborted queues let it finish
    return finish();
  }

  for (std::int64_t k = first; k < end; ++k) {
    const std::optional<std::size_t> slot = free_slots.pop();
    if (!slot) break;  // a worker failed
    Slot& s = slots[*slot];
    if (const std::string error = draw_frame(source, k, s.image, report); !error.empty()) {
      fail(error);
      break;
    }
    s.frame = k;
    s.pending = sinks_per_frame;
    if (sinks_per_frame == 0) {  // drawing only, as when measuring the renderer alone
      s.pending = 1;
      release(*slot);
      continue;
    }
    if ((sinks.png && !png_queue.push(*slot)) || (sinks.video && !video_queue.push(*slot))) break;
  }
  png_queue.close();
  video_queue.close();
  for (std::thread& thread : threads) thread.join();
  return finish();
}

}  // namespace tumble::app
