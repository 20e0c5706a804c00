// The solve of one island of the world step (physics/world_step.hpp): its bodies' free steps
// corrected for the contacts between them and with the planes, either converged in one solve
// (small, slow islands) or sub-stepped from the start of the step (large or fast ones), their
// rows built by physics/contact_rows.hpp; and the helpers the world step shares with them.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "physics/pair_contact.hpp"
#include "physics/world_step.hpp"

namespace tumble::physics {

// A pair whose two bodies can close on each other by more than this in a step (m) has its
// manifold found again before each sub-step: points fixed in the bodies at the start of the step
// stand for the contact only while the bodies stay near where they were (a box falling at 4 m/s
// past another's edge meets its face, which the edge's point knew nothing of: the pile of `tumble
// bench contact` sank 30 cm so while pouring). Box2D's speculative distance is 2 cm.
inline constexpr double kRefindReach = 0.02;

// How far a shape's surface can swing about its centre in a step of h (s) from `start` to `end`:
// its fastest turn times its core's reach (m): a box's half diagonal, a capsule's half length; a
// sphere's surface turns in place.
inline double corner_swing(const BodyState& start, const BodyState& end, const Shape& shape,
                           double h) {
  if (shape.kind == ShapeKind::sphere) return 0.0;
  return h * std::max(start.angular_velocity().norm(), end.angular_velocity().norm()) *
         core_reach(shape);
}

inline ShapePose pose_of(const BodyState& state, const Mat3& rotation, const Shape& shape) {
  return {.position = state.position(), .rotation = rotation, .shape = &shape};
}

// A small island (a tower, a pyramid, a few boxes knocking): every body's free step, then one
// solve over all its points to convergence within its pass budget, the poses moved by the
// impulses, and a projection (physics/contact_island.hpp).
void solve_converged(const StepContext& context, std::uint32_t island);

// A large island (a pile): the sub-stepped solve from the start of the step
// (physics/substep_island.hpp), with every point found at the start pose.
void solve_substepped(const StepContext& context, std::uint32_t island);

}  // namespace tumble::physics
