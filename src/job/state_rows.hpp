// The numbers of a body's state as `tumble simulate` writes them (io/state_csv.hpp's columns) and
// the Python module's Trajectory holds them, and which steps both sample: one definition, so that
// the two give the same numbers bit for bit.
#pragma once

#include <cstdint>

#include "io/state_csv.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::job {

// x, v, q (w, x, y, z), ω, p, L and the kinetic energy (J), in io::kStateColumns' order.
io::StateRow state_row(const physics::BodyState& state);

// Whether step n (1 .. steps) is sampled when every `every`-th is: also the last. Step 0 always
// is.
constexpr bool sampled_step(std::int64_t n, std::int64_t every, std::int64_t steps) {
  return n % every == 0 || n == steps;
}

}  // namespace tumble::job
