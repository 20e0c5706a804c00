// The chain of issue "Joints": N links of 0.1 m (boxes 0.02 × 0.1 × 0.02 m, 0.1 kg) on ball
// joints, the first pinned to the world, let go from horizontal under gravity; links do not
// collide with each other. Run by tumble here and by Bullet 3.24 in bullet_chain.cpp, each timed
// per step and judged by how far its joints open.
#pragma once

#include <cstdint>
#include <string>

#include "physics/integrators.hpp"

namespace tumble::bench {

struct ChainRun {
  std::string engine;
  std::int64_t steps = 0;
  double ms_per_step = 0.0;       // wall clock over the whole run / steps
  double widest_gap = 0.0;        // m: the largest distance between a joint's two anchors
  double final_widest_gap = 0.0;  // m: at the end
  bool blew_up = false;
};

inline constexpr double kChainLinkLength = 0.1;  // m
inline constexpr double kChainLinkMass = 0.1;    // kg

ChainRun run_chain_in_tumble(int links, double seconds, double dt, physics::Integrator integrator);

}  // namespace tumble::bench
