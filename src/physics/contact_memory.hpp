// What one step of the world hands the next: each body's manifolds with the planes and each
// touching pair's manifold, with their points' impulses by feature (warm starting), and the
// bodies' sleep. A value of its own, apart from the step's scratch (step_context.hpp).
#pragma once

#include <array>
#include <vector>

#include "physics/box_box.hpp"
#include "physics/broad_phase.hpp"
#include "physics/contact.hpp"

namespace tumble::physics {

// Where a pair's bodies stood when its manifold was found by the narrow phase, and what with: a
// later step whose bodies have moved less than kReuseDistance relative to each other since keeps
// its points (world_step.cpp).
struct PairStamp {
  bool valid = false;
  Vec3 offset = Vec3::Zero();    // B's centre relative to A's, A's body frame (m)
  Quat turn = Quat::Identity();  // B's orientation relative to A's
  Vec3 normal = Vec3::Zero();    // the manifold's normal, A's body frame
  double margin = 0.0;           // the narrow phase's (m)
  std::array<double, kMaxManifoldPoints> separation{};  // each point's then (m)
};

// Two bodies touching: their manifold, found at the start of the step.
struct PairContact {
  BodyPair bodies;        // (A, B), A < B: the manifold's A and B
  PairManifold manifold;  // its points' impulses warm-start the next step's
  PairStamp stamp;
};

struct ContactMemory {
  // Per body, its last manifold with each plane, in the planes' order.
  std::vector<std::vector<Manifold>> planes;
  std::vector<PairContact> pairs;  // of the last step, sorted by bodies
  // Sleeping, per body: how long it has been still in an island (s), and whether it sleeps.
  std::vector<double> still_for;
  std::vector<char> asleep;
};

// Calls matched(k, j) for each point k of `now` whose feature point j of `then` has: a
// manifold's points are matched by feature from step to step (and sub-step to sub-step), so a
// point keeps its impulses while the same corner (or pair of features) stays in touch.
template <class Now, class Then, class Matched>
void for_each_match(const Now& now, const Then& then, Matched&& matched) {
  for (int k = 0; k < now.count; ++k) {
    for (int j = 0; j < then.count; ++j) {
      if (then.points[static_cast<std::size_t>(j)].feature ==
          now.points[static_cast<std::size_t>(k)].feature) {
        matched(k, j);
      }
    }
  }
}

// Each point of `now` takes the impulses of the point of `then` with its feature.
template <class Now, class Then>
void keep_impulses(Now& now, const Then& then) {
  for_each_match(now, then, [&](int k, int j) {
    now.points[static_cast<std::size_t>(k)].impulses =
        then.points[static_cast<std::size_t>(j)].impulses;
  });
}

}  // namespace tumble::physics
