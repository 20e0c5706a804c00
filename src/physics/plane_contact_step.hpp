// One step of one body among static planes, with impulse contact: how the integrators compose
// with contact. Bodies touch only planes here, so each body steps on its own; contact between
// bodies will make this a step of the whole world.
#pragma once

#include <vector>

#include "physics/contact.hpp"
#include "physics/step_context.hpp"

namespace tumble::physics {

// Corners this close to a plane (m) count as touching it: they take part in the solve of an
// impact or of a resting contact, and an impact is only looked for where a corner was further.
inline constexpr double kTouchingDistance = 1e-6;
// Impacts resolved at their own time within one step; past this the rest of the step treats
// every contact as resting (a box chattering on a corner cannot stall the step).
inline constexpr int kMaxImpactsPerStep = 8;

// How far an impulse applied over a step of h moves the body in that step, as a multiple of the
// velocity change it causes: the position weight each integrator gives a force held constant over
// the step. euler 0 (its positions use the velocities from the start), symplectic_euler h (the
// new velocity carries the whole step), rk4 and the splitting methods h/2 (exact for a constant
// force: x = x₀ + v₀ h + ½ a h²). So a resting body's contact impulse, which balances the
// step's gravity, also undoes the sinking the step's gravity caused.
double impulse_position_weight(Integrator integrator, double h /* s */);

// Where an impact with a plane that does not bounce (every corner reaching it slower than the
// restitution threshold) is resolved: at its time, for the body alone (a body that touches only
// planes), or by the solve of the body's island at the step's end with all its other contacts
// (in a world of bodies that can touch each other). Solved alone, an impact at one corner of a
// thin rod resting across another sets it rolling (a 5 cm × 5 cm × 3 m rod turns 1800 times as
// easily about its length as across it), which the rod under it then stops, and the lifted corner
// falls again: two crossed rods rocked so for ever (5 mm/s, 0.03 rad/s after 5 s; at rest to
// round-off once the island solves it, build/contact_hard).
enum class SlowImpacts { at_their_time, in_the_solve };

// Steps 1 and 2 of step_with_planes for body `body` of the context, into scratch.advances[body]:
// its free step, and its impacts with the planes at their times (those that do not bounce only
// with SlowImpacts::at_their_time). memory.planes[body] keeps the last step's manifolds while it
// touches (their impulses warm-start the rest), and scratch.separations[body] the corners of the
// end.
void advance_among_planes(const StepContext& context, std::uint32_t body, SlowImpacts slow);

// Takes `end` as the body's free step, taken elsewhere (a joint's member moves with the others,
// physics/joint_solve.hpp), touching the planes or not, with no impact at its time: they are left
// to its island's solve, as SlowImpacts::in_the_solve leaves them.
void take_free_step(const StepContext& context, std::uint32_t body, BodyState end);

// A body as the rows of its plane contacts see it: its index in the world, its index among
// scratch.rows.bodies, and its rotation (body to world) at the pose the rows are for.
struct BodyInRows {
  std::uint32_t body;
  std::uint32_t solver;
  const Mat3& rotation;
};

// Onto context.scratch.rows, for each plane, the rows of the body's manifold from its corners
// closer than `margin` (m) in scratch.separations[body], warm-started from the last step's
// manifold by feature (and the same plane's friction); memory.planes[body] then holds these
// manifolds, which store_impulses writes the solve's impulses into.
void append_plane_rows(const StepContext& context, const BodyInRows& body, double margin);

// The same for the sub-stepped solve of an island (physics/substep_island.hpp): the manifolds of
// the body at its start pose (context.in, its rotation body.rotation), its corners closer than
// `margin` (m: as far as the box moves in the step) as speculative points.
void append_speculative_plane_rows(const StepContext& context, const BodyInRows& body,
                                   double margin);

// Step 3 of step_with_planes for a body whose scratch.advances entry touches planes: the island
// solve (contact_island.hpp) of that one body, as an island of one in the world step has it.
BodyState rest_on_planes(const StepContext& context, std::uint32_t body);

// Steps 1 to 3 of step_with_planes for body `body` of the context, into context.out[body];
// returns whether it touches a plane.
bool step_among_planes(const StepContext& context, std::uint32_t body);

// Advances a body from t to t + dt (s) with the integrator, then keeps it outside every plane:
// 1. the free step; if no corner ends inside a plane, that is the step (a body that touches
//    nothing runs the integrator alone);
// 2. a corner that was apart from a plane at the start and ends inside it is an impact: the step
//    goes to its time of impact (regula falsi on the corner's separation along the integrator's
//    own motion), resolves it as an instant impulse with restitution and friction, and goes on
//    with the rest of the step, for up to kMaxImpactsPerStep impacts;
// 3. corners that touched at the start and end inside are resting or sliding contact: the solve
//    corrects the free step's end velocities (normal speed >= 0, Coulomb friction), the impulse
//    moves the pose by impulse_position_weight × its velocity change, and a non-linear
//    Gauss-Seidel projection of the pose (Catto, Box2D 2.4 "solve position constraints") pushes
//    what is still inside out to the surface, moving no momentum, so it adds no kinetic energy.
// `contacts` carries the body's manifolds from step to step: this is step_world for a world of
// this one body, which does not sleep (world_step.cpp).
BodyState step_with_planes(Integrator integrator, const BodyModel& model, const BodyState& in,
                           double t /* s */, double dt /* s */, const std::vector<Plane>& planes,
                           const ContactSettings& settings, WorldContacts& contacts);

}  // namespace tumble::physics
