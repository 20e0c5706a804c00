// The pile of bench/pile.hpp run by tumble's world step (impulse contact, RK4, one thread),
// measured as bench/pile_run.hpp measures every engine.
#pragma once

#include "bench/pile.hpp"
#include "bench/pile_run.hpp"

namespace tumble::bench {

PileRun run_pile_in_tumble(const Pile& pile);

}  // namespace tumble::bench
