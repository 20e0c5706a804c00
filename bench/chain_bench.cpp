// The chain of issue "Joints" (bench/chain.hpp) in tumble and in Bullet 3.24, in one run:
//   build/chain_bench [--links 1000] [--seconds 5] [--hz 60] [--integrator symplectic_euler]
// Each engine's ms per step (the wall clock inside its steps) and how far its joints opened.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "bench/chain.hpp"
#ifdef TUMBLE_HAVE_BULLET
#include "bench/bullet_chain.hpp"
#endif

int main(int argc, char** argv) {
  int links = 1000;
  double seconds = 5.0;
  double hz = 60.0;
  std::string integrator = "symplectic_euler";
  CLI::App app("The chain of issue \"Joints\" in tumble and Bullet, one run");
  app.add_option("--links", links, "Links of 0.1 m")->check(CLI::Range(1, 100000));
  app.add_option("--seconds", seconds, "Simulated time (s)")->check(CLI::Range(0.0, 3600.0));
  app.add_option("--hz", hz, "Steps per second")->check(CLI::Range(1.0, 100000.0));
  app.add_option("--integrator", integrator, "tumble's integrator");
  CLI11_PARSE(app, argc, argv);
  const auto chosen = tumble::physics::integrator_from_name(integrator);
  if (!chosen) {
    std::fprintf(stderr, "chain_bench: unknown integrator %s\n", integrator.c_str());
    return 2;
  }
  std::vector<tumble::bench::ChainRun> runs = {
      tumble::bench::run_chain_in_tumble(links, seconds, 1.0 / hz, *chosen)};
#ifdef TUMBLE_HAVE_BULLET
  runs.push_back(tumble::bench::run_chain_in_bullet(links, seconds, 1.0 / hz));
#else
  std::puts("chain_bench: built without Bullet (libbullet-dev): tumble's column only");
#endif
  std::printf("%d links of 0.1 m on ball joints, let go from horizontal, %g s at 1/%g s\n\n", links,
              seconds, hz);
  std::puts("| engine | steps | ms/step | widest joint opening (m) | at the end (m) |");
  std::puts("| --- | ---: | ---: | ---: | ---: |");
  for (const auto& run : runs) {
    std::printf("| %s%s | %lld | %.3f | %.3g | %.3g |\n", run.engine.c_str(),
                run.blew_up ? " (blew up)" : "", static_cast<long long>(run.steps), run.ms_per_step,
                run.widest_gap, run.final_widest_gap);
  }
  if (runs.size() == 2 && runs[1].ms_per_step > 0.0) {
    std::printf("\ntumble / Bullet, ms per step: %.2f\n",
                runs[0].ms_per_step / runs[1].ms_per_step);
  }
  return 0;
}
