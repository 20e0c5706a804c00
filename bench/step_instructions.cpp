// Steps one box run of bench/box_runs.hpp a given number of times, for callgrind to count the
// instructions of a step (Google Benchmark's own loop cannot be told how many steps to take):
//   valgrind --tool=callgrind --toggle-collect='tumble::bench::BoxRun::step()'
//            build/step_instructions RUN [STEPS]
// reports STEPS steps' instructions as "Collected"; RUN is free, resting, sliding, world_resting
// or world_sliding (a unit cube, rk4, dt = 1/60 s, awake), STEPS 1000 unless given.
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>

#include "bench/box_runs.hpp"

namespace {

using tumble::bench::BoxRun;
using tumble::bench::Stepper;

std::optional<BoxRun> run_named(std::string_view name) {
  constexpr auto kRk4 = tumble::physics::Integrator::rk4;
  if (name == "free") return BoxRun(Stepper::free, kRk4, 0);
  if (name == "resting") return BoxRun(Stepper::planes, kRk4, 0);
  if (name == "sliding") return BoxRun(Stepper::planes, kRk4, 0, 3.0);
  if (name == "world_resting") return BoxRun(Stepper::world, kRk4, 0);
  if (name == "world_sliding") return BoxRun(Stepper::world, kRk4, 0, 3.0);
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  const char* name = argc > 1 ? argv[1] : "";
  const int steps = argc > 2 ? std::atoi(argv[2]) : 1000;
  std::optional<BoxRun> run = run_named(name);
  if (!run) {
    std::fprintf(stderr,
                 "step_instructions: unknown run '%s' (free, resting, sliding, "
                 "world_resting, world_sliding)\n",
                 name);
    return 2;
  }
  for (int n = 0; n < steps; ++n) run->step();
  const auto& centre = run->state().position();
  std::printf("%s: %d steps, centre at (%.9f, %.9f, %.9f) m\n", name, steps, centre.x(), centre.y(),
              centre.z());
  return 0;
}
