// The solve of one island of the world step (physics/world_step.hpp): its bodies' free steps
// corrected for the contacts between them and with the planes, either converged in one solve
// (small, slow islands) or sub-stepped from the start of the step (large or fast ones). Here are
// the rows each writes from the manifolds, and the helpers the world step shares with them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/world_step.hpp"

namespace tumble::physics {

// A pair whose two bodies can close on each other by more than this in a step (m) has its
// manifold found again before each sub-step: points fixed in the bodies at the start of the step
// stand for the contact only while the bodies stay near where they were (a box falling at 4 m/s
// past another's edge meets its face, which the edge's point knew nothing of: the pile of `tumble
// bench contact` sank 30 cm so while pouring). Box2D's speculative distance is 2 cm.
inline constexpr double kRefindReach = 0.02;

// World position of a body point (body frame, m).
inline Vec3 world_point(const BodyState& state, const Mat3& rotation, const Vec3& body_point) {
  return state.position() + rotation * body_point;
}

inline BoxPose pose_of(const BodyState& state, const Mat3& rotation, const Vec3& half_size) {
  return {.position = state.position(), .rotation = rotation, .half_size = half_size};
}

// The members of an island.
inline std::span<const std::uint32_t> members_of(std::uint32_t island,
                                                 const WorldContacts& contacts) {
  return {contacts.members.data() + contacts.member_offsets[island],
          contacts.member_offsets[island + 1] - contacts.member_offsets[island]};
}

// A small island (a tower, a pyramid, a few boxes knocking): every body's free step, then one
// solve over all its points to convergence within its pass budget, the poses moved by the
// impulses, and a projection (physics/contact_island.hpp).
void solve_converged(Integrator integrator, std::span<const BodyModel> models,
                     std::span<const BodyState> in, double dt, std::uint32_t island,
                     const std::vector<Plane>& planes, const ContactSettings& settings,
                     WorldContacts& contacts, std::span<BodyState> out);

// A large island (a pile): the sub-stepped solve from the start of the step
// (physics/substep_island.hpp), with every point found at the start pose.
void solve_substepped(Integrator integrator, std::span<const BodyModel> models,
                      std::span<const BodyState> in, double t, double dt, std::uint32_t island,
                      const std::vector<Plane>& planes, const ContactSettings& settings,
                      WorldContacts& contacts, std::span<BodyState> out);

}  // namespace tumble::physics
