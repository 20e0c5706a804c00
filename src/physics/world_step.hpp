// One step of the whole world: every body's free step (with its impacts on planes at their
// times), then the contacts between bodies and with planes solved together, island by island.
// Contact between bodies makes the step the world's, not each body's alone.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/plane_contact_step.hpp"
#include "physics/step_context.hpp"

namespace tumble::physics {

// A pair whose bodies have moved less than this relative to each other (m: B's centre in A's
// frame, plus B's turn in A's frame times its half diagonal, which bounds how far any point of B
// moved relative to A) since the narrow phase found its manifold keeps that manifold's points,
// each point's separation measured anew from where its two anchors are now. The narrow phase
// looks this much further than the step needs, so no point missing from a kept manifold can come
// within the step's reach. A settled pile's pairs move 1e-5 to 1e-4 m a step relative to each
// other (contact_bench's pile, t = 4 to 20 s). At 1e-4 m the 1000-box pile's median step fell
// from 13.1 to 10.6 ms in one run, its deepest point and final speed as good or better; at 3e-4
// and 1e-3 m as fast, but its boxes settled worse (0.11 and 0.044 m/s at 20 s, against 0.032).
inline constexpr double kReuseDistance = 1e-4;

// Sleeping (ContactSettings::sleep), as Box2D and Bullet sleep islands: an island of touching
// bodies all of whose points have moved slower than kSleepSpeed at the end of every step for
// kTimeToSleep falls asleep. Its bodies' momenta are set to zero there, and from then on each
// step gives each body its pose unchanged, with no free step and no solve, until a body that is
// awake touches one of them: then the whole island wakes within that step, and steps as before.
// A body with a force law that switches on or off or moves in time (a push with start or end
// times, a spring with them or with anchor keys) never sleeps, for nothing else would wake it.
// A still body moves less than kSleepSpeed × kTimeToSleep = 2.5 mm while it waits, and a box
// decelerated by friction (μ g = 4.9 m/s² at μ = 0.5) passes from kSleepSpeed to rest in 1 ms:
// sleeping takes nothing from what a video shows. A box tipping from balance on an edge would be
// put to sleep only if it stayed within 5 mm/s for half a second, that is balanced to ~1e-4 rad.
inline constexpr double kSleepSpeed = 5e-3;  // m/s: |v| + |ω| × half diagonal
inline constexpr double kTimeToSleep = 0.5;  // s

// Whether two of the bodies can touch each other: both collide (BodyModel::collides), and
// settings.collide_bodies. If not, every body touching planes is an island of its own.
bool pairs_possible(std::span<const BodyModel> models, const ContactSettings& settings);

// Advances every body from `in` at t to t + dt (s) into `out`: the free steps, impacts with the
// planes at their times (plane_contact_step.hpp), then every touching pair of bodies (found by
// sweep and prune and the box-box narrow phase at the start of the step, with speculative points
// as far as the pair moves in the step, so a fast body cannot pass through another) and every
// resting contact with a plane, solved island by island: a body alone on planes as
// step_with_planes does; a small, slow island (a tower, a pyramid) to convergence after the free
// steps (physics/contact_island.hpp); a large or fast one (a pile, a pour, a strike) in sub-steps
// from the start of the step (physics/substep_island.hpp), finding fast pairs' points again
// before each. Bodies collide when settings.collide_bodies and both models' `collides` say so.
// With settings.sleep, still islands sleep (kSleepSpeed). A world where nothing touches gives
// exactly each body's free step. A world in which no two bodies can touch (fewer than two that
// collide, or settings.collide_bodies false) steps each body alone among the planes, as its
// island of one would be, with no broad phase and no islands: a scene of one box pays for
// neither. `contacts` carries the world's ContactMemory from step to step, and its scratch.
// With `joints`, their members take their free steps together under the joints
// (advance_joint_members, physics/joint_solve.hpp) and leave their impacts with planes to the
// solve; an island holding one is solved to convergence from there, and after the islands'
// solves the members are projected onto their joints again. They never sleep, and a joint's two
// bodies collide only if it says so.
void step_world(Integrator integrator, std::span<const BodyModel> models,
                std::span<const BodyState> in, double t /* s */, double dt /* s */,
                const std::vector<Plane>& planes, const ContactSettings& settings,
                WorldContacts& contacts, std::span<BodyState> out, JointWorld* joints = nullptr);

}  // namespace tumble::physics
