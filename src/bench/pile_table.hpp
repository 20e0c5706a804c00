// The table of the pile's figures, one column per engine, as `tumble bench contact` and
// `contact_bench` print it: one function, so that the two cannot drift apart.
#pragma once

#include <cstdio>
#include <vector>

#include "bench/pile_run.hpp"

namespace tumble::bench {

// Prints a row per figure and a column per run, and, for two runs (tumble first, then its peer),
// a last line with the ratios of their step times. `dt` is the pile's step (s).
void print_pile_table(std::FILE* out, const std::vector<PileRun>& runs, double dt);

}  // namespace tumble::bench
