// The pile of issue 12 (bench/pile.hpp) run by each engine in one process, one column each:
//   build/contact_bench [--bodies 1000] [--seconds 20] [--seed 1] [--engine both|tumble|bullet]
// tumble's column, then Bullet's, and their ratios of step time. `tumble bench contact` prints the
// same table but may not link Bullet (a benchmark peer only), so it runs Bullet's column here, in
// a child process: `--engine bullet --stream` writes that one run on standard output as the lines
// of bench/pile_run_stream.hpp, step by step, instead of the table.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "bench/pile.hpp"
#include "bench/pile_run.hpp"
#include "bench/pile_run_stream.hpp"
#include "bench/pile_table.hpp"
#include "bench/tumble_pile.hpp"
#ifdef TUMBLE_HAVE_BULLET
#include "bench/bullet_pile.hpp"
#endif

namespace {

using tumble::bench::Pile;
using tumble::bench::PileRun;

constexpr int kExitFailed = 2;  // as tumble's kExitBadInput: the run could not be done or written

#ifdef TUMBLE_HAVE_BULLET
constexpr bool kHaveBullet = true;
#else
constexpr bool kHaveBullet = false;
#endif

PileRun run_engine(const std::string& engine, const Pile& pile,
                   const tumble::bench::StepObserver& observer) {
#ifdef TUMBLE_HAVE_BULLET
  if (engine == "bullet") return tumble::bench::run_pile_in_bullet(pile, observer);
#endif
  return tumble::bench::run_pile_in_tumble(pile, observer);
}

std::string engine_name(const std::string& engine) {
#ifdef TUMBLE_HAVE_BULLET
  if (engine == "bullet") return tumble::bench::bullet_engine_name();
#endif
  return tumble::bench::tumble_engine_name();
}

// One engine's run as stream lines on standard output. A reader that goes away ends the run: the
// figures would have nowhere to go.
int stream_run(const std::string& engine, const Pile& pile) {
  const auto check = [](bool written) {
    if (written) return;
    std::fputs("contact_bench: cannot write to standard output; stopping\n", stderr);
    std::exit(kExitFailed);
  };
  const bool started = tumble::bench::write_run_start(stdout, engine_name(engine), pile);
  check(started);
  const PileRun run = run_engine(engine, pile, [&](const PileRun& so_far) {
    check(tumble::bench::write_run_step(stdout, so_far));
  });
  check(tumble::bench::write_run_end(stdout, run));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int bodies = 1000;
  double seconds = 20.0;
  std::uint64_t seed = 1;
  std::string engine = "both";
  bool stream = false;
  tumble::bench::PileShapes shapes = tumble::bench::PileShapes::boxes;
  CLI::App app("The pile of issue 12, in each engine, in one run");
  app.add_option("--bodies", bodies, "Boxes in the pile")->check(CLI::Range(0, 100000));
  app.add_option("--seconds", seconds, "Simulated time (s)")->check(CLI::Range(0.0, 3600.0));
  app.add_option("--seed", seed, "Seed of the pile's sizes, orientations and velocities");
  app.add_option("--shape", shapes, "What the pile is poured of: boxes or balls")
      ->transform(CLI::CheckedTransformer(tumble::bench::kPileShapesByName));
  app.add_option("--engine", engine, "Which engines to run")
      ->check(CLI::IsMember({"both", "tumble", "bullet"}))
      ->capture_default_str();
  app.add_flag("--stream", stream,
               "Write the one engine's run as lines of bench/pile_run_stream.hpp on standard "
               "output, step by step, instead of the table (for tumble bench contact)");
  CLI11_PARSE(app, argc, argv);

  if (engine != "tumble" && !kHaveBullet) {
    std::fputs("contact_bench: bullet: not built in (libbullet-dev was not found when CMake ran)\n",
               engine == "bullet" ? stderr : stdout);
    if (engine == "bullet") return kExitFailed;
  }
  if (stream && engine == "both") {
    std::fputs("contact_bench: --stream writes one engine's run: add --engine tumble or bullet\n",
               stderr);
    return kExitFailed;
  }
  const Pile pile = tumble::bench::make_pile(bodies, seed, seconds, shapes);
  if (stream) return stream_run(engine, pile);

  std::printf("pile: %s, one thread\n", pile.summary.c_str());
  std::vector<PileRun> runs;
  if (engine != "bullet") runs.push_back(run_engine("tumble", pile, {}));
  if (engine != "tumble" && kHaveBullet) runs.push_back(run_engine("bullet", pile, {}));
  tumble::bench::print_pile_table(stdout, runs, pile.dt);
  return 0;
}
