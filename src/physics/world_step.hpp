// One step of the whole world: every body's free step (with its impacts on planes at their
// times), then the contacts between bodies and with planes solved together, island by island.
// Contact between bodies makes the step the world's, not each body's alone.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/box_box.hpp"
#include "physics/broad_phase.hpp"
#include "physics/contact_island.hpp"
#include "physics/plane_contact_step.hpp"
#include "physics/substep_island.hpp"

namespace tumble::physics {

// Two bodies touching: their manifold, found at the start of the step.
struct PairContact {
  BodyPair bodies;        // (A, B), A < B: the manifold's A and B
  PairManifold manifold;  // its points' impulses warm-start the next step's
};

// A pair's place in an island's lists (world_step.cpp): its points in `slots` slots from
// `first`, its friction patch, and how far its bodies can close on each other in the step.
struct PairRows {
  std::uint32_t pair = 0;   // index into WorldContacts::found
  std::uint32_t first = 0;  // of its points (and positions)
  std::uint32_t slots = 0;
  std::uint32_t patch = 0;
  double reach = 0.0;  // m
};

// What the world step keeps between steps (warm starting), and scratch space kept so that a
// warm step allocates little.
struct WorldContacts {
  std::vector<PlaneContacts> planes;  // per body
  std::vector<PairContact> pairs;     // of the last step, sorted by bodies
  // Scratch.
  std::vector<PlaneAdvance> advances;  // per body
  std::vector<double> reaches;         // per body: how far it can move towards anything (m)
  std::vector<Mat3> start_rotations;   // per body
  std::vector<std::uint32_t> colliders;
  std::vector<Bounds> bounds;
  std::vector<std::uint32_t> order;
  std::vector<BodyPair> candidates;
  std::vector<PairContact> found;
  std::vector<std::uint32_t> root;                      // union-find over bodies
  std::vector<std::uint32_t> local;                     // a body's index within its island
  std::vector<std::uint32_t> island_of;                 // per body: its island, or none
  std::vector<char> paired;                             // per body: whether it touches another
  std::vector<std::uint32_t> members, member_offsets;   // bodies by island
  std::vector<std::uint32_t> pair_order, pair_offsets;  // indices into `found` by island
  std::vector<IslandBody> island_bodies;
  std::vector<BodyState> island_out;
  std::vector<SubstepBody> substep_bodies;
  std::vector<SolverBody> solver;
  std::vector<ContactConstraint> points;
  std::vector<PositionPoint> positions;
  std::vector<FrictionPatch> patches;
  SubstepScratch substep;
  std::vector<PairRows> rows;  // of the island's pairs found again at each sub-step
};

// Advances every body from `in` at t to t + dt (s) into `out`: the free steps, impacts with the
// planes at their times (plane_contact_step.hpp), then every touching pair of bodies (found by
// sweep and prune and the box-box narrow phase at the start of the step, with speculative points
// as far as the pair moves in the step, so a fast body cannot pass through another) and every
// resting contact with a plane, solved island by island: a body alone on planes as
// step_with_planes does; a small, slow island (a tower, a pyramid) to convergence after the free
// steps (physics/contact_island.hpp); a large or fast one (a pile, a pour, a strike) in sub-steps
// from the start of the step (physics/substep_island.hpp), finding fast pairs' points again
// before each. Bodies collide when settings.collide_bodies and both models' `collides` say so. A
// world where nothing touches gives exactly each body's free step.
void step_world(Integrator integrator, std::span<const BodyModel> models,
                std::span<const BodyState> in, double t /* s */, double dt /* s */,
                const std::vector<Plane>& planes, const ContactSettings& settings,
                WorldContacts& contacts, std::span<BodyState> out);

}  // namespace tumble::physics
