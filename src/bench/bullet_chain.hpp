// Bullet 3.24 as the peer of the chain of bench/chain.hpp (only tumble_bullet_peer links it).
#pragma once

#include "bench/chain.hpp"

namespace tumble::bench {

// The chain in Bullet: stepSimulation(dt, 0) for `seconds`, its joints' widest opening.
ChainRun run_chain_in_bullet(int links, double seconds, double dt /* s */);

}  // namespace tumble::bench
