// Advice on impulse contact before a run: settings that make the contact behave in a way a user
// may not expect. Pure computation: the commands print it.
#pragma once

#include <optional>
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
  std::vector<std::size_t> bodies = {};  // indices into the models, in order
  std::string message = {};              // one sentence, naming none of them
  // What the message suggests, where it suggests it: a step (s), or penalty springs per point.
  std::optional<double> suggested_dt = {};
  std::optional<double> suggested_stiffness = {};  // N/m
  std::optional<double> suggested_damping = {};    // N s/m
};

// The moving bodies that start above a floor with no gravity at all (no gravity law, or laws
// that add up to 0): a floor is a plane facing up (its normal's y, up in tumble's world, above
// 0), and a body is above it when its centre is on the normal's side. Nothing brings such a body
// down to the floor, which is seldom what a scene with a floor means: most often [physics]
// gravity, or the body's gravity law, was left out. Indices into `models`, in order.
std::vector<std::size_t> weightless_above_floor(const std::vector<physics::BodyModel>& models,
                                                const std::vector<physics::BodyState>& initial,
                                                const std::vector<physics::Plane>& planes);

// Which bodies touch at the start (closer than a millimetre): each other (pairs of colliding
// bodies, when settings.collide_bodies) and planes, and the groups the pairs join.
struct TouchingAtStart {
  std::vector<bool> on_plane;                              // by body
  std::vector<bool> touches;                               // a plane or another body
  std::vector<std::size_t> group;                          // by body: one body's index per group
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (i, j), i < j, in order
};
TouchingAtStart touching_at_start(const std::vector<physics::BodyModel>& models,
                                  const std::vector<physics::BodyState>& initial,
                                  const std::vector<physics::Plane>& planes,
                                  const physics::ContactSettings& settings);

// With penalty contact between bodies, a stack may sink into its springs by no more than this
// fraction of the smallest edge among its bodies (1 cm for unit cubes).
inline constexpr double kMostPenaltySink = 0.01;

// Penalty contact between bodies (physics/penalty_pairs.hpp), for bodies that can touch each
// other (physics::pairs_possible), from the springs' linearised bounce: with four points to a
// face and the damping proportional to the stiffness, each mode has ω² = λ and a damping rate of
// (c/k) λ, λ an eigenvalue of M⁻¹K, bounded by Gershgorin's circles: for body i,
// (4k/m_i)(its plane contacts + its pairs) + Σ over its pairs 4k/sqrt(m_i m_j) (a column of
// three unit cubes: 16k/m, against 13k/m exactly). For each group touching at the start, and for
// the two lightest colliding bodies meeting (4k (1/m₁ + 1/m₂)) when no group is warned of: a
// warning when `integrator` at `dt` is unstable on that bound (a dt to use, or the stiffness and
// damping, ζ kept, that are stable at this dt, when the stack still sinks less than
// kMostPenaltySink with them); and for a group on a plane, a warning when its static sink
// (bodies in order of height along gravity, each contact below carrying the weight above it:
// Σ W_above / 4k) passes kMostPenaltySink, with the stiffness that holds it.
std::vector<BodiesAdvice> check_penalty_pairs(const std::vector<physics::BodyModel>& models,
                                              const std::vector<physics::BodyState>& initial,
                                              const std::vector<physics::Plane>& planes,
                                              const physics::ContactSettings& settings,
                                              physics::Integrator integrator, double dt);

// The hard cases the impulse solver cannot fix, for bodies (`models`, starting at `initial`)
// among `planes` stepped at `dt` (s), in groups too large for the block solve (above): touching
// bodies of a mass ratio beyond kMostMassRatio, a body whose constant load moves it further than
// its smallest edge in one step, and a stack (three or more bodies touching each other and a
// plane) for which |g| dt² passes kMostStackSink. Each says what to change. For penalty
// contact, check_penalty_pairs's advice instead.
std::vector<BodiesAdvice> check_contact_world(const std::vector<physics::BodyModel>& models,
                                              const std::vector<physics::BodyState>& initial,
                                              const std::vector<physics::Plane>& planes,
                                              const physics::ContactSettings& settings,
                                              physics::Integrator integrator, double dt);

}  // namespace tumble::sim
