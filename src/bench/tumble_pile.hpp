// The pile of bench/pile.hpp run by tumble's world step (impulse contact, RK4, one thread),
// measured as bench/pile_run.hpp measures every engine.
#pragma once

#include <string>

#include "bench/pile.hpp"
#include "bench/pile_run.hpp"

namespace tumble::bench {

// "tumble (impulse, rk4)": the engine as the pile's table names it.
std::string tumble_engine_name();

// `observer`, if any, is called after each step (pile_run.hpp).
PileRun run_pile_in_tumble(const Pile& pile, const StepObserver& observer = {});

}  // namespace tumble::bench
