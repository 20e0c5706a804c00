// One step of one body among static planes, with impulse contact: how the integrators compose
// with contact. Bodies touch only planes here, so each body steps on its own; contact between
// bodies will make this a step of the whole world.
#pragma once

#include <vector>

#include "physics/contact.hpp"
#include "physics/contact_island.hpp"
#include "physics/contact_solver.hpp"
#include "physics/integrators.hpp"

namespace tumble::physics {

// Corners this close to a plane (m) count as touching it: they take part in the solve of an
// impact or of a resting contact, and an impact is only looked for where a corner was further.
inline constexpr double kTouchingDistance = 1e-6;
// Impacts resolved at their own time within one step; past this the rest of the step treats
// every contact as resting (a box chattering on a corner cannot stall the step).
inline constexpr int kMaxImpactsPerStep = 8;

// A corner of the box that may hit a plane within a step.
struct ImpactCorner {
  std::size_t plane = 0;
  Vec3 body_point = Vec3::Zero();  // body frame (m)
};

// One body's contact between steps: its last manifold with each plane (warm starting), and
// scratch space kept from step to step so that a step of a touching body allocates nothing.
struct PlaneContacts {
  std::vector<Manifold> manifolds;             // one per plane, in the planes' order
  std::vector<Manifold> found;                 // scratch
  std::vector<CornerSeparations> separations;  // scratch: of the pose being looked at, per plane
  std::vector<ContactConstraint> points;       // scratch
  std::vector<PositionPoint> positions;        // scratch
  std::vector<FrictionPatch> patches;          // scratch
  std::vector<ImpactCorner> impact_corners;    // scratch
  std::vector<ProjectedPose> poses;            // scratch
};

// How far an impulse applied over a step of h moves the body in that step, as a multiple of the
// velocity change it causes: the position weight each integrator gives a force held constant over
// the step. euler 0 (its positions use the velocities from the start), symplectic_euler h (the
// new velocity carries the whole step), rk4 and the splitting methods h/2 (exact for a constant
// force: x = x₀ + v₀ h + ½ a h²). So a resting body's contact impulse, which balances the
// step's gravity, also undoes the sinking the step's gravity caused.
double impulse_position_weight(Integrator integrator, double h /* s */);

// A body's step among planes up to its resting contacts: steps 1 and 2 of step_with_planes.
struct PlaneAdvance {
  BodyState end;                     // the free step's end after the impacts
  Mat3 rotation = Mat3::Identity();  // end's, when touching
  double remaining = 0.0;            // s: the part of the step after the last impact
  bool touching = false;  // a corner of `end` touches a plane: contacts.separations holds them
};
PlaneAdvance advance_among_planes(Integrator integrator, const BodyModel& model,
                                  const BodyState& in, double t /* s */, double dt /* s */,
                                  const std::vector<Plane>& planes, const ContactSettings& settings,
                                  PlaneContacts& contacts);

// Step 3's points and friction patches of a touching body (`body`: its index among the island's
// solver bodies, whose entry is `solver_body`): each plane's manifold from contacts.separations,
// warm-started from the last step's, onto `points` (velocity) and `positions` (projection).
// contacts.manifolds then holds the new manifolds, which the solve writes its impulses into.
void add_plane_points(const BodyModel& model, std::uint32_t body, const Mat3& rotation,
                      const SolverBody& solver_body, const std::vector<Plane>& planes,
                      PlaneContacts& contacts, std::vector<ContactConstraint>& points,
                      std::vector<FrictionPatch>& patches, std::vector<PositionPoint>& positions);

// The same for the sub-stepped solve of an island (physics/substep_island.hpp): each plane's
// manifold of the box at its start pose (`start`, whose rotation is `rotation`), its corners
// closer than `margin` (m: as far as the box moves in the step) as speculative points.
void add_speculative_plane_points(const BodyModel& model, std::uint32_t body,
                                  const BodyState& start, const Mat3& rotation, double margin,
                                  const SolverBody& solver_body, const std::vector<Plane>& planes,
                                  PlaneContacts& contacts, std::vector<ContactConstraint>& points,
                                  std::vector<FrictionPatch>& patches,
                                  std::vector<PositionPoint>& positions);

// Step 3 of step_with_planes for a body that touches planes at the end of `advance`: the island
// solve (contact_island.hpp) of that one body, as an island of one in the world step has it.
BodyState rest_on_planes(Integrator integrator, const BodyModel& model, const PlaneAdvance& advance,
                         const std::vector<Plane>& planes, const ContactSettings& settings,
                         PlaneContacts& contacts);

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
// `contacts` carries the body's manifolds from step to step (sized to the planes on first use).
BodyState step_with_planes(Integrator integrator, const BodyModel& model, const BodyState& in,
                           double t /* s */, double dt /* s */, const std::vector<Plane>& planes,
                           const ContactSettings& settings, PlaneContacts& contacts);

}  // namespace tumble::physics
