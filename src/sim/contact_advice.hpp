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
// `dt` (s): a restitution_threshold below kThresholdOverStepSpeed × |g| dt on a pair that
// bounces (restitution > 0), since a body resting on such a plane then bounces on every step.
std::vector<std::string> check_contact(const physics::BodyModel& model,
                                       const std::vector<physics::Plane>& planes,
                                       const physics::ContactSettings& settings, double dt);

// Past these the impulse solver of today does not hold what a scene asks (measured with
// bench/contact_hard and the cases of issue Contact III, rk4, dt = 1/60 s):
// - two touching bodies of masses 60:1 stand (0.7 mm in 30 s), 70:1 and beyond collapse;
inline constexpr double kMostMassRatio = 50.0;
// - a cube whose constant load moves it further than its smallest edge in one free step (a 1 kg
//   unit cube under 8000 N: 1.1 m) ends its steps far inside the floor, 7000 N (0.97 m) holds;
// - a stack of three or more bodies settles while |g| dt² is at most 8 mm (1/35 s under 9.81 m/s²)
//   and jitters for ever at 11 mm (1/30 s: 0.14 m/s) and beyond.
inline constexpr double kMostStackSink = 0.008;  // m: |g| dt²

// A problem of some bodies together, for the command to word with their names.
struct BodiesAdvice {
  std::vector<std::size_t> bodies;  // indices into the models, in order
  std::string message;              // one sentence, naming none of them
};

// The hard cases the impulse solver cannot fix, for bodies (`models`, starting at `initial`)
// among `planes` stepped at `dt` (s): touching bodies of a mass ratio beyond kMostMassRatio, a
// body whose constant load moves it further than its smallest edge in one step while it touches
// something, and a stack (three or more bodies touching each other and a plane) for which
// |g| dt² passes kMostStackSink. Each says what to change. Nothing for penalty contact.
std::vector<BodiesAdvice> check_contact_world(const std::vector<physics::BodyModel>& models,
                                              const std::vector<physics::BodyState>& initial,
                                              const std::vector<physics::Plane>& planes,
                                              const physics::ContactSettings& settings, double dt);

}  // namespace tumble::sim
