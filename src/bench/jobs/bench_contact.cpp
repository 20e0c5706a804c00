#include "bench/jobs/bench_contact.hpp"

#include <unistd.h>

#include <cstdio>
#include <string_view>
#include <system_error>
#include <vector>

#include "bench/pile.hpp"
#include "bench/pile_run.hpp"
#include "bench/pile_run_stream.hpp"
#include "bench/pile_table.hpp"
#include "bench/tumble_pile.hpp"
#include "io/atomic_file.hpp"
#include "io/json_text.hpp"
#include "pipeline/progress.hpp"
#include "sys/child_process.hpp"

namespace tumble::bench {
namespace {

namespace fs = std::filesystem;
using bench::Pile;
using bench::PileRun;

// The folder of --out, checked before a run that may take minutes: an error unless it can be
// written.
Result<void> check_folder(const fs::path& folder) {
  std::error_code error;
  if (!fs::exists(folder, error)) {
    return Error{"--out: no folder " + folder.string() + " (create it first)"};
  }
  if (!fs::is_directory(folder, error)) {
    return Error{"--out: " + folder.string() + " is not a folder"};
  }
  // A file opened and dropped unrenamed: AtomicFile removes it again.
  const Result<io::AtomicFile> probe =
      io::AtomicFile::open((folder / ".tumble-write-test").string());
  if (!probe) return Error{probe.error()};
  return {};
}

// "0.5" for 0.5 s: 17 digits, so that contact_bench parses the double tumble has.
std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// Bullet's column, from contact_bench; an error unless it ran whole.
Result<PileRun> run_peer(const fs::path& peer, const BenchContactOptions& options, const Pile& pile,
                         pipeline::Progress& progress) {
  bench::PileRunReader reader(pile);
  std::string unreadable;  // why a line could not be read
  const Result<void> ended = sys::run_reading_lines(
      peer.string(),
      {"--engine", "bullet", "--stream", "--bodies", std::to_string(options.bodies), "--seconds",
       exact(options.seconds), "--seed", std::to_string(options.seed), "--shape",
       pile_shapes_name(options.shapes)},
      [&](std::string_view line) {
        if (const Result<void> read = reader.read(line); !read) {
          unreadable = read.error();
          return false;
        }
        progress.update(pile.steps + static_cast<std::int64_t>(reader.run().step_ms.size()));
        return true;
      });
  if (!unreadable.empty()) {
    return Error{peer.string() + " wrote what tumble cannot read: " + unreadable};
  }
  if (!ended) return Error{ended.error()};
  if (!reader.complete()) return Error{peer.string() + " ended before its run was whole"};
  return reader.run();
}

std::string engine_json(const PileRun& run, double dt) {
  const std::size_t peak = bench::peak_contact_step(run);
  return "{\n    \"engine\": " + io::json_string(run.engine) +
         ",\n    \"steps\": " + std::to_string(run.step_ms.size()) +
         ",\n    \"mean_ms_per_step\": " + io::json_number(bench::mean_step_ms(run)) +
         ",\n    \"mean_cpu_ms_per_step\": " + io::json_number(bench::mean_step_cpu_ms(run)) +
         ",\n    \"median_ms_per_step\": " + io::json_number(bench::median_step_ms(run)) +
         ",\n    \"median_cpu_ms_per_step\": " + io::json_number(bench::median_step_cpu_ms(run)) +
         ",\n    \"ms_per_step_at_peak_contacts\": " +
         io::json_number(bench::ms_at_peak_contacts(run)) + ",\n    \"peak_contacts\": " +
         (run.contacts.empty() ? "null" : std::to_string(run.contacts[peak])) +
         ",\n    \"peak_contacts_t_s\": " + io::json_number(bench::peak_contact_time(run, dt)) +
         ",\n    \"contacts_at_end\": " +
         (run.contacts.empty() ? "null" : std::to_string(run.contacts.back())) +
         ",\n    \"largest_penetration_m\": " + io::json_number(run.largest_penetration_m) +
         ",\n    \"boxes_out_of_bin\": " + std::to_string(run.escaped) +
         ",\n    \"largest_speed_at_end_m_per_s\": " + io::json_number(run.largest_final_speed) +
         ",\n    \"step_ms\": " + io::json_array(run.step_ms) +
         ",\n    \"step_cpu_ms\": " + io::json_array(run.step_cpu_ms) +
         ",\n    \"contacts\": " + io::json_array(run.contacts) +
         ",\n    \"depth_m\": " + io::json_array(run.depth_m) +
         ",\n    \"top_speed_m_per_s\": " + io::json_array(run.top_speed) + "\n  }";
}

std::string report_json(const BenchContactOptions& options, const Pile& pile, const PileRun& tumble,
                        const PileRun& bullet) {
  const bench::StepTimeRatios ratios = bench::step_time_ratios(tumble, bullet);
  return "{\n  \"pile\": {\"summary\": " + io::json_string(pile.summary) +
         ", \"bodies\": " + std::to_string(options.bodies) +
         ", \"seed\": " + std::to_string(options.seed) +
         ", \"seconds\": " + io::json_number(options.seconds) +
         ", \"dt\": " + io::json_number(pile.dt) + ", \"steps\": " + std::to_string(pile.steps) +
         "},\n  \"tumble\": " + engine_json(tumble, pile.dt) +
         ",\n  \"bullet\": " + engine_json(bullet, pile.dt) +
         ",\n  \"tumble_over_bullet\": {\"mean_ms_per_step\": " + io::json_number(ratios.mean_ms) +
         ", \"mean_cpu_ms_per_step\": " + io::json_number(ratios.mean_cpu_ms) +
         ", \"median_ms_per_step\": " + io::json_number(ratios.median_ms) +
         ", \"median_cpu_ms_per_step\": " + io::json_number(ratios.median_cpu_ms) +
         ", \"ms_per_step_at_peak_contacts\": " + io::json_number(ratios.ms_at_peak_contacts) +
         "}\n}\n";
}

// One row per step: its end time and each engine's figures for it.
void write_csv(std::FILE* file, const Pile& pile, const PileRun& tumble, const PileRun& bullet) {
  std::fputs("step,t_s", file);
  for (const char* engine : {"tumble", "bullet"}) {
    std::fprintf(file, ",%s_ms,%s_cpu_ms,%s_contacts,%s_depth_m,%s_top_speed_m_per_s", engine,
                 engine, engine, engine, engine);
  }
  std::fputc('\n', file);
  for (std::size_t n = 0; n < static_cast<std::size_t>(pile.steps); ++n) {
    std::fprintf(file, "%zu,%.17g", n, static_cast<double>(n + 1) * pile.dt);
    for (const PileRun* run : {&tumble, &bullet}) {
      std::fprintf(file, ",%.17g,%.17g,%d,%.17g,%.17g", run->step_ms[n], run->step_cpu_ms[n],
                   run->contacts[n], run->depth_m[n], run->top_speed[n]);
    }
    std::fputc('\n', file);
  }
}

// Writes the JSON and the CSV, each whole or not at all, and lists them on `out`. The error says
// what failed of each, a line each ("tumble: " before the second, as main prints the first).
Result<void> write_files(const fs::path& folder, const BenchContactOptions& options,
                         const Pile& pile, const PileRun& tumble, const PileRun& bullet,
                         std::FILE* out) {
  const fs::path json = folder / "contact_bench.json";
  const fs::path csv = folder / "contact_bench.csv";
  Result<io::AtomicFile> json_file = io::AtomicFile::open(json.string());
  if (json_file) {
    std::fputs(report_json(options, pile, tumble, bullet).c_str(), json_file->stream());
  }
  Result<io::AtomicFile> csv_file = io::AtomicFile::open(csv.string());
  if (csv_file) write_csv(csv_file->stream(), pile, tumble, bullet);
  std::string errors;
  for (Result<io::AtomicFile>* file : {&json_file, &csv_file}) {
    const Result<void> written = *file ? (*file)->commit() : Result<void>(Error{file->error()});
    if (!written) errors += (errors.empty() ? "" : "\ntumble: ") + written.error();
  }
  if (!errors.empty()) return Error{errors};
  std::fprintf(out, "%s\n%s\n", json.c_str(), csv.c_str());
  return {};
}

}  // namespace

fs::path contact_bench_path() {
  std::error_code ignored;
  return fs::read_symlink("/proc/self/exe", ignored).parent_path() / "contact_bench";
}

Result<ExitCode> run_bench_contact(const BenchContactOptions& options, std::FILE* out,
                                   std::FILE* err) {
  const fs::path folder = options.out;
  if (!options.out.empty()) {
    if (const Result<void> usable = check_folder(folder); !usable) return Error{usable.error()};
  }
  const fs::path peer = contact_bench_path();
  const bool have_peer = ::access(peer.c_str(), X_OK) == 0;
  if (!have_peer) {
    // Said before the run, which can take minutes, and not only after it.
    std::fprintf(err,
                 "tumble: bench contact: no contact_bench at %s (it is built beside tumble, with "
                 "Bullet when CMake finds libbullet-dev): Bullet's column is left out and no "
                 "files are written; tumble's column is still printed\n",
                 peer.c_str());
  }

  const Pile pile = bench::make_pile(options.bodies, options.seed, options.seconds, options.shapes);
  std::fprintf(out, "pile: %s, one thread\n", pile.summary.c_str());
  std::fflush(out);
  pipeline::Progress progress(static_cast<std::int64_t>(pile.steps) * (have_peer ? 2 : 1),
                              options.quiet, err, "steps");
  std::vector<PileRun> runs;
  runs.push_back(bench::run_pile_in_tumble(pile, [&](const PileRun& so_far) {
    progress.update(static_cast<std::int64_t>(so_far.step_ms.size()));
  }));
  Result<void> peer_ran = Result<void>::success();
  if (have_peer) {
    Result<PileRun> bullet = run_peer(peer, options, pile, progress);
    if (bullet) {
      runs.push_back(std::move(bullet).value());
    } else {
      peer_ran = Error{bullet.error()};
    }
  }
  progress.finish();

  bench::print_pile_table(out, runs, pile.dt);
  if (!have_peer) return kExitBadInput;  // said before the run
  if (!peer_ran) {
    return Error{"bench contact: Bullet's column: " + peer_ran.error() +
                 "; tumble's column is printed above, no files are written"};
  }
  if (!options.out.empty()) {
    if (const Result<void> written = write_files(folder, options, pile, runs[0], runs[1], out);
        !written) {
      return Error{written.error()};
    }
  }
  return kExitOk;
}

}  // namespace tumble::bench
