// Advice on impulse contact before a run: settings that make the contact behave in a way a user
// may not expect. Pure computation: the commands print it.
#pragma once

#include <string>
#include <vector>

#include "physics/contact.hpp"
#include "physics/integrators.hpp"

namespace tumble::sim {

// Below this multiple of the speed gravity adds in one step, a resting contact's approach speed
// counts as a bounce (every step's free fall ends at |g| dt): at 1 the body would chatter.
inline constexpr double kThresholdOverStepSpeed = 1.5;

// One sentence per problem for a body (its model) among `planes` with impulse contact stepped at
// `dt` (s) with `integrator`: a restitution_threshold below kThresholdOverStepSpeed × |g| dt on a
// pair that bounces (restitution > 0), since a body resting on such a plane then bounces on every
// step (unless its steps are held to their energy, physics/contact_island.hpp: a passive body
// with any integrator but euler, which then rests); and
// a bouncing body with no gravity and a threshold above 0, whose impacts slower than it lose
// their bounce though nothing rests (two e = 1 cubes in a closed room lost 2 % of their energy
// in 60 s at 0.5 m/s, 6e-9 at 0).
std::vector<std::string> check_contact(const physics::BodyModel& model,
                                       const std::vector<physics::Plane>& planes,
                                       const physics::ContactSettings& settings,
                                       physics::Integrator integrator, double dt);

// A group of bodies touching each other at the start whose contact points (four for each
// touching pair and for each body on a plane) pass physics::kMostBlockRows is solved one row at a
// time (sequential impulses), not as one block (physics/normal_block.hpp); past these that
// solver does not hold what a scene asks (measured with columns of unit cubes, rk4, dt = 1/60 s):
// - a column of 14 (56 points) with a top 10 times as heavy as the rest drifts 3.7 cm in 30 s,
//   20 times 13 cm, 50 times collapses (one of 11, 44 points, holds 1000:1 within 1e-13 m);
inline constexpr double kMostMassRatio = 10.0;
// - a constant load that moves a body further than its smallest edge in one free step;
// - a column of 14 settles while |g| dt² is at most 8 mm (1/35 s: 7.5 mm drift in 10 s) and
//   collapses at 11 mm (1/30 s); one of 11 stands at dt = 1/10 s.
inline constexpr double kMostStackSink = 0.008;  // m: |g| dt²

// A problem of some bodies together, for the command to word with their names.
struct BodiesAdvice {
  std::vector<std::size_t> bodies;  // indices into the models, in order
  std::string message;              // one sentence, naming none of them
};

// The hard cases the impulse solver cannot fix, for bodies (`models`, starting at `initial`)
// among `planes` stepped at `dt` (s), in groups too large for the block solve (above): touching
// bodies of a mass ratio beyond kMostMassRatio, a body whose constant load moves it further than
// its smallest edge in one step, and a stack (three or more bodies touching each other and a
// plane) for which |g| dt² passes kMostStackSink. Each says what to change. Nothing for penalty
// contact.
std::vector<BodiesAdvice> check_contact_world(const std::vector<physics::BodyModel>& models,
                                              const std::vector<physics::BodyState>& initial,
                                              const std::vector<physics::Plane>& planes,
                                              const physics::ContactSettings& settings, double dt);

}  // namespace tumble::sim
