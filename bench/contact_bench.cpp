// The pile of issue 12 (bench/pile.hpp) run by each engine in one process, one column each:
//   build/contact_bench [--bodies 1000] [--seconds 20] [--seed 1]
// tumble's column, then Bullet's, and their ratios of step time. A separate executable and
// not `tumble bench contact`: that would link Bullet into the tumble executable, and Bullet is a
// benchmark peer only.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/pile.hpp"
#include "bench/pile_run.hpp"
#include "bench/pile_table.hpp"
#include "bench/tumble_pile.hpp"
#ifdef TUMBLE_HAVE_BULLET
#include "bench/bullet_pile.hpp"
#endif

using tumble::bench::PileRun;

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
  tumble::bench::print_pile_table(stdout, runs, pile.dt);
  return 0;
}
