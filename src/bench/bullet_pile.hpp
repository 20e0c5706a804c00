// Bullet 3.24 as a benchmark peer: runs the pile of bench/pile.hpp through Bullet's own
// btDiscreteDynamicsWorld with its defaults, and measures it as `tumble bench contact` will
// measure tumble. This header names no Bullet type, so callers need neither Bullet's headers nor
// its precision flag; only the target tumble_bullet_peer links Bullet.
#pragma once

#include <string>

#include "bench/pile.hpp"
#include "bench/pile_run.hpp"

namespace tumble::bench {

// "bullet 3.24 float64" or "... float32": the version and precision this binary was built with.
std::string bullet_engine_name();

// Runs the whole pile in Bullet: pile.steps calls of stepSimulation(pile.dt, 0), one thread,
// sleeping on (Bullet's default), materials combined by tumble's rule (physics::combine).
// `observer`, if any, is called after each step (pile_run.hpp).
PileRun run_pile_in_bullet(const Pile& pile, const StepObserver& observer = {});

}  // namespace tumble::bench
