// What every stage of a step of the world reads and writes, passed to each as one context (as
// Box2D's b2StepContext) rather than as positional arguments: the step's givens, the memory the
// last step left (contact_memory.hpp), the scratch of this step, and where the states go.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/broad_phase.hpp"
#include "physics/contact_island.hpp"
#include "physics/contact_memory.hpp"
#include "physics/integrators.hpp"
#include "physics/joint_solve.hpp"
#include "physics/substep_island.hpp"

namespace tumble::physics {

// A point of the body's shape (rounded_point, contact.hpp) that may hit a plane within a step.
struct ImpactCorner {
  std::size_t plane = 0;
  Vec3 body_point = Vec3::Zero();  // its core, body frame (m)
  double radius = 0.0;             // its rounding (m): the touching point is radius inside
};

// A body's step among planes up to its resting contacts: steps 1 and 2 of step_with_planes.
struct PlaneAdvance {
  BodyState end;                     // the free step's end after the impacts
  Mat3 rotation = Mat3::Identity();  // end's, when touching
  double remaining = 0.0;            // s: the part of the step after the last impact
  // A corner of `end` touches a plane: StepScratch::separations holds the body's corners.
  bool touching = false;
  // An impact that did not bounce was resolved at its time (SlowImpacts::at_their_time).
  bool slow_impact = false;
};

// A pair's place in an island's rows (island_solve.cpp): its points in `slots` slots from
// `first`, its friction patch, and how far its bodies can close on each other in the step.
struct PairRows {
  std::uint32_t pair = 0;   // index into StepScratch::found
  std::uint32_t first = 0;  // of its points (and positions)
  std::uint32_t slots = 0;
  std::uint32_t patch = 0;
  double reach = 0.0;  // m
};

// A body's place against one plane in a fast island's rows (island_solve.cpp):
// kMaxManifoldPoints slots from `first`, and its friction patch, found again at each sub-step.
struct PlaneRows {
  std::uint32_t body = 0;   // the body's index in the world
  std::uint32_t plane = 0;  // index into the planes
  std::uint32_t first = 0;  // of its points (and positions)
  std::uint32_t patch = 0;
};

// Scratch of a step, kept from step to step so that a warm step allocates little.
struct StepScratch {
  std::vector<PlaneAdvance> advances;  // per body
  // Per body, per plane: the corner separations (m) of the pose being looked at.
  std::vector<std::vector<CornerSeparations>> separations;
  std::vector<ImpactCorner> impact_corners;
  std::vector<double> reaches;        // per body: how far it can move towards anything (m)
  std::vector<Mat3> start_rotations;  // per body
  std::vector<std::uint32_t> colliders;
  std::vector<Bounds> bounds;
  std::vector<std::uint32_t> order;
  std::vector<BodyPair> candidates;
  std::vector<PairContact> found;                       // this step's pairs
  std::vector<std::uint32_t> root;                      // union-find over bodies
  std::vector<std::uint32_t> local;                     // a body's index within its island
  std::vector<std::uint32_t> island_of;                 // per body: its island, or none
  std::vector<char> paired;                             // per body: whether it touches another
  std::vector<std::uint32_t> members, member_offsets;   // bodies by island
  std::vector<std::uint32_t> pair_order, pair_offsets;  // indices into `found` by island
  std::vector<std::uint32_t> next_slot;                 // per island, while bucketing
  std::vector<IslandBody> island_bodies;
  std::vector<BodyState> island_out;
  std::vector<SubstepBody> substep_bodies;
  ContactRows rows;  // of the island being solved
  SubstepScratch substep;
  std::vector<PairRows> pair_rows;    // of the island's pairs found again at each sub-step
  std::vector<PlaneRows> plane_rows;  // of a fast island's bodies near planes, likewise
};

// What the world step keeps between steps: its memory, and its scratch.
struct WorldContacts {
  ContactMemory memory;
  StepScratch scratch;
};

// The context of one step from t to t + dt.
struct StepContext {
  Integrator integrator;
  std::span<const BodyModel> models;
  std::span<const BodyState> in;  // at t
  double t = 0.0;                 // s
  double dt = 0.0;                // s
  std::span<const Plane> planes;
  const ContactSettings& settings;
  ContactMemory& memory;
  StepScratch& scratch;
  std::span<BodyState> out;      // at t + dt
  JointWorld* joints = nullptr;  // the world's joints, if it has any
};

// Whether body i is held by a joint: it moves with the joint's other body (its free step is
// theirs together) and its energy is not its own to hold.
inline bool held_by_joints(const StepContext& context, std::uint32_t i) {
  return context.joints && context.joints->holds(i);
}

// The members of an island.
inline std::span<const std::uint32_t> members_of(std::uint32_t island, const StepScratch& scratch) {
  return {scratch.members.data() + scratch.member_offsets[island],
          scratch.member_offsets[island + 1] - scratch.member_offsets[island]};
}

}  // namespace tumble::physics
