// The pile in tumble's own world step: the sub-stepped solve of large, fast islands
// (physics/substep_island.hpp) pours, settles and holds it.
#include "bench/tumble_pile.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "bench/pile.hpp"

namespace tumble::bench {
namespace {

// 300 boxes poured into the bin for 16 s: none leaves it, and once settled (the last second) the
// pile is at most 2 mm inside itself or the floor and its fastest box below 0.05 m/s. While
// pouring, a box can end a step far inside another (5.9 cm here, measured at each step's end
// from the poses, bench/pile.hpp's PileDepth): a landing box stops and a neighbour falling beside
// it, which the step's start did not pair with it, goes on into it; the next step finds the pair
// and pushes it out. Contact III's aim is 1 cm; this bound (8 cm) only holds what is measured.
// When the last box stops is chaotic: over seeds 1 to 10 the last second with a box faster than
// 0.05 m/s was the 3rd to the 15th (before the block solve and the impacts at once, over seeds 1
// to 8, the 3rd to the 15th too).
TEST(TumblePile, ThreeHundredBoxesPourSettleAndHold) {
  const Pile pile = make_pile(300, 1, 16.0);
  const PileRun run = run_pile_in_tumble(pile);
  ASSERT_EQ(run.depth_m.size(), static_cast<std::size_t>(pile.steps));
  const std::size_t settled = run.depth_m.size() - 60;
  const double depth = *std::max_element(run.depth_m.begin() + settled, run.depth_m.end());
  const double speed = *std::max_element(run.top_speed.begin() + settled, run.top_speed.end());
  std::printf(
      "[ measured ] 300 boxes, last second: deepest %.2e m, fastest %.3f m/s; whole run "
      "deepest %.3f m, %d out\n",
      depth, speed, run.largest_penetration_m, run.escaped);
  EXPECT_EQ(run.escaped, 0);
  EXPECT_LT(run.largest_penetration_m, 0.08);  // m
  EXPECT_LT(depth, 2e-3);                      // m
  EXPECT_LT(speed, 0.05);                      // m/s
}

}  // namespace
}  // namespace tumble::bench
