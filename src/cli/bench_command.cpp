#include "cli/bench_command.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench/accuracy.hpp"
#include "bench/hard_cases.hpp"
#include "bench/jobs/bench_contact.hpp"
#include "bench/jobs/bench_pipeline.hpp"
#include "cli/options.hpp"
#include "common/printed.hpp"
#include "io/atomic_file.hpp"
#include "scene/limits.hpp"

extern char** environ;

namespace tumble::cli {
namespace {

namespace fs = std::filesystem;
using bench::AccuracyRow;
using bench::HardCase;

// "1/60" for the benchmarked steps, the plain number otherwise.
std::string step_label(double dt) {
  const double per_second = 1.0 / dt;
  if (std::abs(per_second - std::round(per_second)) < 1e-9 * per_second) {
    return printed("1/%.0f", per_second);
  }
  return printed("%g", dt);
}

// Writes a file atomically with `write` filling it; on failure prints why and returns false.
bool write_file(const fs::path& path, const std::function<void(std::FILE*)>& write,
                std::FILE* err) {
  Result<io::AtomicFile> file = io::AtomicFile::open(path.string());
  if (file) write(file->stream());
  if (const Result<void> written = file ? file->commit() : Result<void>(Error{file.error()});
      !written) {
    std::fprintf(err, "tumble: %s\n", written.error().c_str());
    return false;
  }
  return true;
}

// The rows of one case (with one contact method, for a contact case), in sweep order.
std::vector<const AccuracyRow*> rows_of(const std::vector<AccuracyRow>& rows,
                                        const std::string& case_name,
                                        const std::string& contact = "none") {
  std::vector<const AccuracyRow*> out;
  for (const AccuracyRow& row : rows) {
    if (row.case_name == case_name && row.contact == contact) out.push_back(&row);
  }
  return out;
}

const char* headline_label(const HardCase& c) {
  return c.headline == bench::HeadlineError::orientation ? "orientation error (rad)"
                                                         : "position error (m)";
}

// A number for the CSV, or an empty cell where the row does not measure it.
std::string csv_number(double value, bool measured) {
  return measured ? printed("%.9g", value) : "";
}

void write_csv(std::FILE* out, const std::vector<AccuracyRow>& rows) {
  std::fputs(
      "case,contact,integrator,dt,steps,blew_up,measure,error,second_measure,second_error,"
      "orientation_error_rad,position_error_m,angular_momentum_error,energy_error,ns_per_step,"
      "ns_per_simulated_second\n",
      out);
  for (const AccuracyRow& r : rows) {
    const bool final_state = r.contact == "none";  // hard cases measure the final state
    std::fprintf(
        out, "%s,%s,%s,%.17g,%lld,%d,%s,%.9g,%s,%s,%s,%s,%s,%s,%.6g,%.6g\n", r.case_name.c_str(),
        r.contact.c_str(), r.integrator.c_str(), r.dt, static_cast<long long>(r.steps),
        r.blew_up ? 1 : 0, r.measure.c_str(), r.error, r.second_measure.c_str(),
        csv_number(r.second_error, !r.second_measure.empty()).c_str(),
        csv_number(r.orientation_error, final_state).c_str(),
        csv_number(r.position_error, final_state).c_str(),
        csv_number(r.angular_momentum_error, final_state).c_str(),
        csv_number(r.energy_error, final_state).c_str(), r.ns_per_step, r.ns_per_simulated_second);
  }
}

std::string reference_note(const bench::Reference& reference) {
  if (reference.closed_form) {
    return printed(
        "closed form (the Boost.Odeint RKF78 solution in long double at tolerance %.0e agrees "
        "with it to %.1e, and with a run at %.0e to %.1e)",
        bench::kReferenceTolerance, reference.closed_form_difference.value_or(0.0),
        bench::kCrossCheckTolerance, reference.tolerance_difference);
  }
  return printed(
      "Boost.Odeint RKF78 in long double at tolerance %.0e (a run at %.0e differs by %.1e)",
      bench::kReferenceTolerance, bench::kCrossCheckTolerance, reference.tolerance_difference);
}

std::string error_cell(const AccuracyRow& row, double value) {
  return row.blew_up ? "blew up" : printed("%.2e", value);
}

void write_hard_case_tables(std::FILE* out, const bench::AccuracySelection& selection,
                            const std::vector<AccuracyRow>& rows) {
  for (const HardCase* c : selection.hard) {
    const bench::Reference& reference = c->reference();
    std::fprintf(out, "\n## %s\n\n%s.\n\nReference: %s.\n\n", c->name.c_str(), c->summary.c_str(),
                 reference_note(reference).c_str());
    const char* momentum = c->conserves_angular_momentum ? "\\|L\\| drift" : "L error";
    const char* energy = c->conserves_energy ? "energy drift" : "energy error";
    std::fprintf(out,
                 "| integrator | dt (s) | orientation error (rad) | position error (m) | %s | %s "
                 "| ns/step | ns per simulated s |\n"
                 "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n",
                 momentum, energy);
    for (const AccuracyRow* row : rows_of(rows, c->name)) {
      std::fprintf(out, "| %s | %s | %s | %s | %s | %s | %.0f | %.3g |\n", row->integrator.c_str(),
                   step_label(row->dt).c_str(), error_cell(*row, row->orientation_error).c_str(),
                   error_cell(*row, row->position_error).c_str(),
                   error_cell(*row, row->angular_momentum_error).c_str(),
                   error_cell(*row, row->energy_error).c_str(), row->ns_per_step,
                   row->ns_per_simulated_second);
    }
  }
}

void write_contact_case_tables(std::FILE* out, const bench::AccuracySelection& selection,
                               const std::vector<AccuracyRow>& rows) {
  for (const bench::ContactCase* c : selection.contact) {
    std::fprintf(out,
                 "\n## %s\n\n%s.\n\nError: %s. Penalty contact: k = %.3g N/m and "
                 "c = %.4g N s/m per corner, the damping for the case's restitution on a flat "
                 "landing (`sim/penalty_modes.hpp`).\n\n| contact | integrator | dt (s) |",
                 c->name.c_str(), c->summary.c_str(), c->measure_note.c_str(), c->penalty.stiffness,
                 c->penalty.damping);
    for (const bench::ContactMeasure& measure : c->measures) {
      std::fprintf(out, " %s |", measure.label.c_str());
    }
    std::fputs(" ns/step | ns per simulated s |\n| --- | --- | --- |", out);
    for (std::size_t i = 0; i < c->measures.size(); ++i) std::fputs(" ---: |", out);
    std::fputs(" ---: | ---: |\n", out);
    for (const char* contact : {"impulse", "penalty"}) {
      for (const AccuracyRow* row : rows_of(rows, c->name, contact)) {
        std::fprintf(out, "| %s | %s | %s | %s |", contact, row->integrator.c_str(),
                     step_label(row->dt).c_str(), error_cell(*row, row->error).c_str());
        if (c->measures.size() > 1) {
          std::fprintf(out, " %s |", error_cell(*row, row->second_error).c_str());
        }
        std::fprintf(out, " %.0f | %.3g |\n", row->ns_per_step, row->ns_per_simulated_second);
      }
    }
  }
}

void write_joint_case_tables(std::FILE* out, const bench::AccuracySelection& selection,
                             const std::vector<AccuracyRow>& rows) {
  for (const bench::JointCase* c : selection.joint) {
    std::fprintf(out, "\n## %s (joints)\n\n%s.\n\nError: %s.\n\n| integrator | dt (s) |",
                 c->name.c_str(), c->summary.c_str(), c->measure_note.c_str());
    for (const bench::ContactMeasure& measure : c->measures) {
      std::fprintf(out, " %s |", measure.label.c_str());
    }
    std::fputs(" ns/step | ns per simulated s |\n| --- | --- |", out);
    for (std::size_t i = 0; i < c->measures.size(); ++i) std::fputs(" ---: |", out);
    std::fputs(" ---: | ---: |\n", out);
    for (const AccuracyRow* row : rows_of(rows, c->name)) {
      std::fprintf(out, "| %s | %s | %s |", row->integrator.c_str(), step_label(row->dt).c_str(),
                   error_cell(*row, row->error).c_str());
      if (c->measures.size() > 1) {
        std::fprintf(out, " %s |", error_cell(*row, row->second_error).c_str());
      }
      std::fprintf(out, " %.0f | %.3g |\n", row->ns_per_step, row->ns_per_simulated_second);
    }
  }
}

void write_markdown(std::FILE* out, const bench::AccuracySettings& settings,
                    const bench::AccuracySelection& selection, bool quick,
                    const std::vector<AccuracyRow>& rows) {
  std::fprintf(out,
               "# Speed against error\n\n"
               "Every integrator on every hard case (`src/bench/hard_cases.cpp`), where errors are "
               "of the final state against the case's reference, and with impulse and with "
               "penalty contact on every contact case (`src/bench/contact_cases.cpp`), and on "
               "every joint case (`src/bench/joint_cases.cpp`), where each case names its own "
               "errors. A hard case's run *blew up* when its state left a "
               "million times the true motion's size, a contact case's when its energy above "
               "rest doubled (contact only takes energy away). Cost is the median of %d timing%s "
               "of the whole run, in the same process, on one thread of this machine "
               "(%u hardware threads)%s. Written by `tumble bench accuracy%s`.\n",
               settings.timing.samples, settings.timing.samples == 1 ? "" : "s",
               std::thread::hardware_concurrency(),
#ifdef NDEBUG
               "",
#else
               ", in a build with assertions (timings are not representative)",
#endif
               quick ? " --quick" : "");
  write_hard_case_tables(out, selection, rows);
  write_contact_case_tables(out, selection, rows);
  write_joint_case_tables(out, selection, rows);
}

// gnuplot's single-quoted strings double a quote to escape it.
std::string gnuplot_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// One panel of the chart: a case, what its headline error is, and the contact methods it ran
// with ("none" for a hard case).
struct Panel {
  std::string name;
  std::string error_label;
  std::vector<std::string> contacts;
};

std::vector<Panel> panels(const bench::AccuracySelection& selection) {
  std::vector<Panel> out;
  for (const HardCase* c : selection.hard) {
    out.push_back({c->name, headline_label(*c), {"none"}});
  }
  for (const bench::ContactCase* c : selection.contact) {
    out.push_back({c->name, c->measures.front().label, {"impulse", "penalty"}});
  }
  for (const bench::JointCase* c : selection.joint) {
    out.push_back({c->name, c->measures.front().label, {"none"}});
  }
  return out;
}

// The chart's data, one block per (case, contact, integrator) with something to plot, and the
// script that draws one panel per case: a colour per integrator, penalty contact dashed. Log axes
// cannot show a zero error or a blown-up run: those points are left out.
struct Plot {
  std::string data;
  std::string script;
};

// The panel's series, each a block added to plot.data from number `block` on.
std::vector<std::string> panel_series(const Panel& panel, const std::vector<AccuracyRow>& rows,
                                      Plot& plot, int& block) {
  std::vector<std::string> series;
  for (const std::string& contact : panel.contacts) {
    for (std::size_t i = 0; i < std::size(physics::kAllIntegrators); ++i) {
      const std::string name(physics::integrator_name(physics::kAllIntegrators[i]));
      std::string points;
      for (const AccuracyRow* row : rows_of(rows, panel.name, contact)) {
        if (row->integrator != name || row->blew_up || !(row->error > 0.0)) continue;
        points += printed("%.6g %.6g\n", row->ns_per_simulated_second, row->error);
      }
      if (points.empty()) continue;
      const std::string title = contact == "none" ? name : contact + " " + name;
      plot.data += "# " + panel.name + " " + title + "\n" + points + "\n\n";
      series.push_back(printed(
          "'accuracy.dat' index %d using 1:2 with linespoints lc %zu dt %d title %s noenhanced",
          block++, i + 1, contact == "penalty" ? 2 : 1, gnuplot_quoted(title).c_str()));
    }
  }
  return series;
}

Plot make_plot(const bench::AccuracySettings& settings, const bench::AccuracySelection& selection,
               const std::vector<AccuracyRow>& rows, const std::string& png_name) {
  Plot plot;
  const std::vector<Panel> all = panels(selection);
  const int columns = all.size() >= 5 ? 3 : 2;
  const int panel_rows = static_cast<int>((all.size() + columns - 1) / columns);
  plot.script = printed(
      "# Draws accuracy.png from accuracy.dat: gnuplot accuracy.gp (written by tumble bench "
      "accuracy)\n"
      "set terminal pngcairo size %d,%d font ',10'\n"
      "set output %s\n"
      "set multiplot layout %d,%d title 'Error against cost: one line per integrator (and "
      "contact method), dt = %s ... %s s'\n"
      "set format x '10^{%%L}'\nset format y '10^{%%L}'\nset key bottom left\nset grid\n",
      600 * columns, 450 * panel_rows, gnuplot_quoted(png_name).c_str(), panel_rows, columns,
      step_label(settings.steps.front()).c_str(), step_label(settings.steps.back()).c_str());
  int block = 0;
  for (const Panel& panel : all) {
    const std::vector<std::string> series = panel_series(panel, rows, plot, block);
    plot.script += printed("set title %s noenhanced\n", gnuplot_quoted(panel.name).c_str());
    if (series.empty()) {
      // A panel with only a note: nothing can be drawn on log axes.
      plot.script +=
          "unset logscale\nunset border\nunset tics\nunset xlabel\nunset ylabel\nunset grid\n"
          "set label 1 'every run blew up or had no error' at graph 0.5, 0.5 center\n"
          "plot [0:1] [0:1] 2 notitle\nunset label 1\n";
      continue;
    }
    plot.script += printed(
        "set logscale xy\nset border\nset tics\nset grid\nset xlabel 'ns per simulated "
        "second'\nset ylabel %s\nplot ",
        gnuplot_quoted(panel.error_label).c_str());
    for (std::size_t i = 0; i < series.size(); ++i) {
      plot.script += (i == 0 ? "" : ", \\\n     ") + series[i];
    }
    plot.script += "\n";
  }
  plot.script += "unset multiplot\n";
  return plot;
}

// Runs `gnuplot -e "cd DIR" SCRIPT`; returns an error message, empty on success.
std::string run_gnuplot(const fs::path& directory, const fs::path& script) {
  const std::string cd = "cd " + gnuplot_quoted(directory.string());
  const std::string script_path = script.string();
  char* argv[] = {const_cast<char*>("gnuplot"), const_cast<char*>("-e"),
                  const_cast<char*>(cd.c_str()), const_cast<char*>(script_path.c_str()), nullptr};
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, "gnuplot", nullptr, nullptr, argv, environ);
  if (spawned == ENOENT) {
    return "gnuplot not found on PATH: install it (Debian: apt-get install gnuplot-nox) to draw "
           "accuracy.png";
  }
  if (spawned != 0) return std::string("cannot start gnuplot: ") + std::strerror(spawned);
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return "waiting for gnuplot failed";
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return printed("gnuplot failed (%s %d) on %s", WIFEXITED(status) ? "exit status" : "signal",
                   WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status), script_path.c_str());
  }
  return "";
}

}  // namespace

CommandResult run_bench_accuracy(const BenchAccuracyOptions& options, std::FILE* out,
                                 std::FILE* err) {
  std::error_code error_code;
  const fs::path directory = fs::absolute(options.out, error_code);
  if (error_code) return Error{"--out: expected a folder name, got \"" + options.out + "\""};
  fs::create_directories(directory, error_code);
  if (error_code) return Error{"cannot create " + directory.string() + ": " + error_code.message()};
  // The sweep takes over a minute: find an unwritable folder before it, not after.
  if (const auto probe = io::AtomicFile::open((directory / ".tumble-write-test").string());
      !probe) {
    return Error{probe.error()};
  }

  const bench::AccuracySettings settings =
      options.quick ? bench::quick_accuracy_settings() : bench::AccuracySettings{};
  const Result<bench::AccuracySelection> selection = bench::select_accuracy_cases(settings);
  if (!selection) return Error{selection.error()};
  const std::size_t runs =
      (selection->hard.size() + 2 * selection->contact.size() + selection->joint.size()) *
      std::size(physics::kAllIntegrators);
  std::size_t started = 0;
  const Result<std::vector<AccuracyRow>> measured = bench::measure_accuracy(
      settings, [&](const std::string& run, physics::Integrator integrator) {
        std::fprintf(
            err, "tumble: bench accuracy: [%zu/%zu] %s with %s at dt = %s ... %s s\n", ++started,
            runs, run.c_str(), std::string(physics::integrator_name(integrator)).c_str(),
            step_label(settings.steps.front()).c_str(), step_label(settings.steps.back()).c_str());
        std::fflush(err);
      });
  if (!measured) return Error{measured.error()};
  const std::vector<AccuracyRow>& rows = *measured;

  bool ok = write_file(
      directory / "accuracy.csv", [&](std::FILE* f) { write_csv(f, rows); }, err);
  ok = write_file(
           directory / "accuracy.md",
           [&](std::FILE* f) { write_markdown(f, settings, *selection, options.quick, rows); },
           err) &&
       ok;
  const std::string png_temporary = printed("accuracy.png.tmp-%d", static_cast<int>(::getpid()));
  const Plot plot = make_plot(settings, *selection, rows, png_temporary);
  ok = write_file(
           directory / "accuracy.dat", [&](std::FILE* f) { std::fputs(plot.data.c_str(), f); },
           err) &&
       ok;
  ok = write_file(
           directory / "accuracy.gp", [&](std::FILE* f) { std::fputs(plot.script.c_str(), f); },
           err) &&
       ok;
  if (!ok) return kExitBadInput;
  std::fprintf(out, "%s\n%s\n", (directory / "accuracy.csv").c_str(),
               (directory / "accuracy.md").c_str());

  const std::string gnuplot_error = run_gnuplot(directory, directory / "accuracy.gp");
  const fs::path png = directory / "accuracy.png";
  if (gnuplot_error.empty()) fs::rename(directory / png_temporary, png, error_code);
  if (!gnuplot_error.empty() || error_code) {
    fs::remove(directory / png_temporary, error_code);
    fs::remove(png, error_code);  // an earlier run's chart would not match the new figures
    return Error{
        (gnuplot_error.empty() ? "cannot rename the chart into " + png.string() : gnuplot_error) +
        " (accuracy.csv and accuracy.md are written; there is no accuracy.png)"};
  }
  std::fprintf(out, "%s\n", png.c_str());
  return kExitOk;
}

namespace {

void add_bench_pipeline(CLI::App& bench, Commands& commands) {
  const auto options = std::make_shared<bench::BenchPipelineOptions>();
  CLI::App* command = bench.add_subcommand(
      "pipeline", "Render one scene the naive ways and tumble's way, in one run, and compare");
  command->add_option("--scene", options->scene_path,
                      "Scene to render (default: a built-in lit cube with ground and shadow)");
  command->add_option("--width", options->width, "Image width")
      ->check(CLI::Range(scene::kMinImageSide, scene::kMaxImageSide))
      ->capture_default_str();
  command->add_option("--height", options->height, "Image height")
      ->check(CLI::Range(scene::kMinImageSide, scene::kMaxImageSide))
      ->capture_default_str();
  command->add_option("--frames", options->frames, "Frames per path")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{100000}))
      ->capture_default_str();
  command
      ->add_option("--msaa", options->msaa,
                   "Samples per pixel (default: the scene's [render] msaa, as tumble render)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16}));
  command
      ->add_option("--chunks", options->chunks,
                   "Instead: the whole render against N chunks, each a process of its own "
                   "(per-chunk overhead and total CPU)")
      ->check(whole_number_in(1, 100000, "from 1 to 100000"));
  command->add_option("--out", options->out, "Folder for pipeline.md")
      ->check(not_empty())
      ->capture_default_str();
  commands.push_back(
      {command, [options] { return bench::run_bench_pipeline(*options, stdout, stderr); }});
}

void add_bench_accuracy(CLI::App& bench, Commands& commands) {
  const auto options = std::make_shared<BenchAccuracyOptions>();
  CLI::App* command = bench.add_subcommand(
      "accuracy", "Error against cost of every integrator on hard cases: CSV, Markdown, chart");
  command->add_option("--out", options->out, "Folder for accuracy.csv, .md and .png")
      ->check(not_empty())
      ->capture_default_str();
  command->add_flag("--quick", options->quick,
                    "A reduced sweep (3 cases, 2 step sizes, 1 timing) for tests");
  commands.push_back({command, [options] { return run_bench_accuracy(*options, stdout, stderr); }});
}

void add_bench_contact(CLI::App& bench, Commands& commands) {
  const auto options = std::make_shared<bench::BenchContactOptions>();
  CLI::App* command = bench.add_subcommand(
      "contact",
      "The pile of issue 12 in tumble and in Bullet 3.24 (through contact_bench), in one run");
  command->add_option("--bodies", options->bodies, "Boxes in the pile")
      ->check(whole_number_in(0, 100000, "from 0 to 100000"))
      ->capture_default_str();
  command->add_option("--seconds", options->seconds, "Simulated time (s), in steps of 1/60 s")
      ->check(CLI::Range(0.0, 3600.0))
      ->capture_default_str();
  command
      ->add_option("--seed", options->seed, "Seed of the boxes' sizes, orientations and velocities")
      ->capture_default_str();
  command
      ->add_option("--shape", options->shapes,
                   "What the pile is poured of: boxes, balls, or mixed (box, ball, capsule)")
      ->transform(CLI::CheckedTransformer(bench::kPileShapesByName))
      ->capture_default_str();
  command
      ->add_option("--out", options->out,
                   "An existing folder for contact_bench.json and contact_bench.csv")
      ->check(not_empty());
  command->add_flag("-q,--quiet", options->quiet, "No progress");
  commands.push_back(
      {command, [options] { return bench::run_bench_contact(*options, stdout, stderr); }});
}

}  // namespace

void add_bench_command(CLI::App& app, Commands& commands) {
  CLI::App* bench = app.add_subcommand("bench", "Measure tumble's speed");
  bench->require_subcommand(1);
  add_bench_pipeline(*bench, commands);
  add_bench_accuracy(*bench, commands);
  add_bench_contact(*bench, commands);
}

}  // namespace tumble::cli
