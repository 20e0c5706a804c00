// The pile of issue 12 (bench/pile.hpp) run by each engine in one process, one column each:
//   build/contact_bench [--bodies 1000] [--seconds 20] [--seed 1]
// tumble's column, then Bullet's, and their ratio of median step time. A separate executable and
// not `tumble bench contact`: that would link Bullet into the tumble executable, and Bullet is a
// benchmark peer only.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/pile.hpp"
#include "bench/pile_run.hpp"
#include "bench/tumble_pile.hpp"
#ifdef TUMBLE_HAVE_BULLET
#include "bench/bullet_pile.hpp"
#endif

namespace {

using tumble::bench::PileRun;

// One line of the table: a label, and one engine's value as text.
struct Row {
  const char* label;
  std::string (*value)(const PileRun& run, double dt);
};

std::string fixed(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// The largest box speed at t = 10 s (m/s), where the earlier Bullet figure was taken.
std::string speed_at_10_s(const PileRun& run, double dt) {
  const auto step = static_cast<std::size_t>(10.0 / dt + 0.5);  // steps done at t = 10 s
  return step >= 1 && step <= run.top_speed.size() ? fixed(run.top_speed[step - 1], 3) : "-";
}

const std::vector<Row> kRows = {
    {"median ms/step", [](const PileRun& r, double) { return fixed(median_step_ms(r), 2); }},
    {"median cpu ms/step",
     [](const PileRun& r, double) { return fixed(median_step_cpu_ms(r), 2); }},
    {"ms/step at peak contacts",
     [](const PileRun& r, double) { return fixed(ms_at_peak_contacts(r), 2); }},
    {"peak contacts",
     [](const PileRun& r, double) {
       return r.contacts.empty() ? std::string("-")
                                 : std::to_string(r.contacts[peak_contact_step(r)]);
     }},
    {"peak at t (s)",
     [](const PileRun& r, double dt) { return fixed((peak_contact_step(r) + 1) * dt, 2); }},
    {"contacts at end",
     [](const PileRun& r, double) {
       return r.contacts.empty() ? std::string("-") : std::to_string(r.contacts.back());
     }},
    {"largest penetration (m)",
     [](const PileRun& r, double) { return fixed(r.largest_penetration_m, 4); }},
    {"boxes out of the bin", [](const PileRun& r, double) { return std::to_string(r.escaped); }},
    {"largest speed at 10 s (m/s)", speed_at_10_s},
    {"largest speed at end (m/s)",
     [](const PileRun& r, double) { return fixed(r.largest_final_speed, 3); }},
};

void print_table(const std::vector<PileRun>& runs, double dt) {
  std::printf("%-30s", "");
  for (const PileRun& run : runs) std::printf("  %-20s", run.engine.c_str());
  std::printf("\n");
  for (const Row& row : kRows) {
    std::printf("%-30s", row.label);
    for (const PileRun& run : runs) std::printf("  %-20s", row.value(run, dt).c_str());
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  int bodies = 1000;
  double seconds = 20.0;
  std::uint64_t seed = 1;
  CLI::App app("The pile of issue 12, in each engine, in one run");
  app.add_option("--bodies", bodies, "Boxes in the pile")->check(CLI::Range(0, 100000));
  app.add_option("--seconds", seconds, "Simulated time (s)")->check(CLI::Range(0.0, 3600.0));
  app.add_option("--seed", seed, "Seed of the pile's sizes, orientations and velocities");
  CLI11_PARSE(app, argc, argv);

  const tumble::bench::Pile pile = tumble::bench::make_pile(bodies, seed, seconds);
  std::printf("pile: %s, one thread\n", pile.summary.c_str());
  std::vector<PileRun> runs;
  runs.push_back(tumble::bench::run_pile_in_tumble(pile));
#ifdef TUMBLE_HAVE_BULLET
  runs.push_back(tumble::bench::run_pile_in_bullet(pile));
#else
  std::printf("bullet: not built in (libbullet-dev was not found when CMake ran)\n");
#endif
  print_table(runs, pile.dt);
  if (runs.size() == 2) {
    std::printf("tumble / bullet, median ms/step: %.2f (cpu %.2f)\n",
                median_step_ms(runs[0]) / median_step_ms(runs[1]),
                median_step_cpu_ms(runs[0]) / median_step_cpu_ms(runs[1]));
  }
  return 0;
}
