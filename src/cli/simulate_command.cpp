#include "cli/simulate_command.hpp"

#include <stdio_ext.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <climits>
#include <cstring>
#include <memory>
#include <variant>

#include "cli/options.hpp"
#include "common/exit_codes.hpp"
#include "io/atomic_file.hpp"
#include "io/state_csv.hpp"
#include "job/state_rows.hpp"
#include "physics/rigid_body.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "scene/stability_report.hpp"
#include "sys/interrupt.hpp"

namespace tumble::cli {
namespace {

bool write_rows(std::FILE* out, const scene::Scene& scene, const sim::Simulation& simulation) {
  bool ok = true;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    ok = io::write_state_row(out, simulation.time(), scene.bodies[i].name,
                             job::state_row(simulation.current()[i])) &&
         ok;
  }
  return ok;
}

}  // namespace

CommandResult run_simulate(const SimulateOptions& options, std::FILE* err) {
  sys::install_interrupt_handlers();  // from the start: a signal is acted on at the first step
  const Result<scene::Scene> loaded = scene::load_scene_file(options.scene_path);
  if (!loaded) return Error{loaded.error()};
  const scene::Scene& scene = *loaded;
  scene::print_stability_warnings(scene, err);

  std::unique_ptr<io::AtomicFile> file;
  const bool to_file = options.out != "-";
  double time = 0.0;  // s: how far the run got
  // Either leaves the file unwritten: AtomicFile removes its temporary file when not committed.
  const auto stopped = [&](int signal) {
    std::fprintf(err, "tumble: stopped by %s at t = %.6g of %.6g s; %s\n", sys::signal_name(signal),
                 time, scene.duration,
                 to_file ? (options.out + " was not written").c_str() : "output incomplete");
    // Rows still buffered for standard output are dropped: flushing them at exit could block
    // on the very pipe the signal cut short.
    if (!to_file) __fpurge(stdout);
    return interrupted_by(signal);
  };
  std::FILE* out = stdout;
  if (options.out != "-") {
    Result<io::AtomicFile> opened = io::AtomicFile::open(options.out);
    if (const int signal = sys::interrupt_signal())
      return stopped(signal);  // a FIFO's open, cut short
    if (!opened) return Error{opened.error()};
    file = std::make_unique<io::AtomicFile>(std::move(opened).value());
    out = file->stream();
  }

  sim::Simulation simulation = scene::build_simulation(scene);
  const std::int64_t steps = scene::step_count(scene);
  bool ok = io::write_state_header(out) && write_rows(out, scene, simulation);
  for (std::int64_t n = 1; n <= steps && ok; ++n) {
    simulation.step();
    time = simulation.time();
    if (const int signal = sys::interrupt_signal()) return stopped(signal);
    if (const auto& blow_up = simulation.blow_up()) {
      return Error{scene::blow_up_message(scene, *blow_up)};
    }
    if (job::sampled_step(n, options.every, steps)) ok = write_rows(out, scene, simulation);
  }
  // A write blocked on a full pipe and cut short by the signal fails with EINTR: a stop too,
  // before a flush could block on that pipe again.
  if (const int signal = sys::interrupt_signal()) return stopped(signal);
  // commit() also says why an earlier write failed; a failed file is never put in place.
  const Result<void> committed = file ? file->commit() : Result<void>::success();
  ok = (file ? committed.ok() : std::fflush(out) == 0) && ok;
  if (ok) return kExitOk;
  const int reason = errno;
  if (const int signal = sys::interrupt_signal()) return stopped(signal);  // during that last flush
  if (file) return Error{committed.error()};
  return Error{std::string("error writing to standard output: ") + std::strerror(reason)};
}

void add_simulate_command(CLI::App& app, Commands& commands) {
  const auto options = std::make_shared<SimulateOptions>();
  CLI::App* command =
      app.add_subcommand("simulate", "Run a scene's physics and write the states as CSV");
  command->add_option("scene", options->scene_path, "Scene file (TOML)")->required();
  command->add_option("--out", options->out, "CSV file to write, or - for stdout")
      ->check(not_empty())
      ->capture_default_str();
  command->add_option("--every", options->every, "Write a row every N steps")
      ->check(whole_number_in(1, LLONG_MAX, ">= 1"))
      ->capture_default_str();
  commands.push_back({command, [options] { return run_simulate(*options, stderr); }});
}

}  // namespace tumble::cli
