// The resolution of one island: bodies that touch each other (or planes) through contact points,
// solved together after their free steps. Both the step of one body among planes and the world
// step of many bodies end here, so resting, sliding and stacking share one solve, one pose update
// and one projection.
#pragma once

#include <span>
#include <vector>

#include "physics/contact.hpp"
#include "physics/contact_solver.hpp"
#include "physics/integrators.hpp"

namespace tumble::physics {

// The most passes of the velocity solver over the points of an island: a budget of point passes,
// within [kFewestPasses, kMostPasses]. A warm-started island ends after a pass or two (the
// solve's tolerance); a new stack needs many: a tower of ten cubes built at rest drifts 1 cm
// sideways in its first second with 100 passes, 3 mm with 300, and a pyramid of 55 (about 400
// points) moves 1.1 cm in 30 s with 30 passes, 3 mm with 100. A large island (a pile) gets the
// budget spread over its points, down to 30 passes from 1300 points on: more cost time there and
// change little (contact_bench, 200 boxes: 30 or 300 passes gave 21 and 13 cm deepest, both at
// rest by 6 s).
inline constexpr int kMostPasses = 300;
inline constexpr int kFewestPasses = 30;
inline constexpr int kPointPassBudget = 40000;
int solver_passes(std::size_t points);

// Passes of the position projection; each moves the bodies by what is left inside.
inline constexpr int kProjectionIterations = 4;
// A resting solve ends when a pass changes no impulse by more than this fraction of the largest:
// the velocity left is then about 1e-7 of what gravity adds in a step, far below what shows.
inline constexpr double kRestingTolerance = 1e-6;

// A resting solve ends after a pass (warm-started, its impulses change by less than the
// tolerance), so what it leaves of a velocity the physics makes exactly zero (a box at rest on a
// face) shrinks by a constant factor each step and would go on forever, into subnormal numbers,
// which the FPU handles up to 100 times slower (an awake resting cube's step took about 1.7 times
// as long). A momentum component below this size (kg m/s, or kg m²/s) is that residue and is set to
// zero, 80 orders of magnitude below anything a scene can show and below the round-off of any
// momentum above 1e-84; its square is still a normal number, so no norm of it is subnormal either.
inline constexpr double kNegligibleMomentum = 1e-100;
// The momentum with each component below kNegligibleMomentum set to zero.
Vec3 without_residue(Vec3 momentum);

// A body of an island, at the end of its free step (after any impacts of its own with planes).
struct IslandBody {
  const BodyModel* model = nullptr;
  // At the start of the step, for its energy (resolve_island); none where it is not held.
  const BodyState* start = nullptr;
  BodyState end;                     // what the solve corrects
  Mat3 rotation = Mat3::Identity();  // end's, body to world
  double weight = 0.0;  // impulse_position_weight of the step's rest after its last impact (s)
};

// A contact point at the position level, for the projection after the solve: its separation is
// base + n·(x_a + R_a anchor_a - (x_b + R_b anchor_b)) (m), the b terms absent against a static
// shape. For a plane base is -offset; for a pair of bodies it is the separation found at the
// start of the step, so a body that moved through another within the step is pushed back to the
// side it came from (the anchors' motion measures how far it went, Catto's "Solver2D" relax).
struct PositionPoint {
  std::uint32_t a = 0;           // island-local index
  std::uint32_t b = kStatic;     // likewise, or kStatic
  Vec3 anchor_a = Vec3::Zero();  // body frame of a (m)
  Vec3 anchor_b = Vec3::Zero();  // body frame of b (m)
  Vec3 normal = Vec3::UnitY();   // unit, world, from b towards a
  double base = 0.0;             // m
};

// A pose being projected, and what the projection needs of its mass.
struct ProjectedPose {
  PrimaryState primary;
  double inverse_mass = 0.0;           // 1/kg
  const SolverBody* solved = nullptr;  // its inverse inertia, world frame (SolverBody::turn)
};

// One pass of the projection: pushes the poses apart along each point still inside until its
// separation is zero, by a position-level impulse through both bodies' masses (non-linear
// Gauss-Seidel: it moves no momentum). Returns the deepest separation a point had when the pass
// reached it (m): negative when any point was inside, else 0.
double project_pass(std::span<ProjectedPose> poses, std::span<const PositionPoint> positions);

// What a solve runs on, built by the row builder (contact_rows.hpp) and scratch of the step:
// the bodies' velocities, a normal row and a position point per contact point (positions[i] is
// points[i]'s), a friction patch per manifold, and the poses of the projection.
struct ContactRows {
  std::vector<SolverBody> bodies;
  std::vector<ContactConstraint> points;
  std::vector<PositionPoint> positions;
  std::vector<FrictionPatch> patches;
  std::vector<JointConstraint> joints;  // the joints' equality rows between the island's bodies
  std::vector<ProjectedPose> poses;     // scratch of the projection, a pose per body
  void clear() {
    bodies.clear();
    points.clear();
    positions.clear();
    patches.clear();
    joints.clear();
  }
};

// Solves the island's velocity constraints (warm-started from the rows' impulses), then moves
// each body's pose by weight × its velocity change and projects the positions out of every
// PositionPoint still inside (non-linear Gauss-Seidel, Catto, Box2D 2.4 "solve position
// constraints": it moves no momentum, so it adds no kinetic energy). rows.bodies holds one
// SolverBody per body, made from its end state. The corrected states go to `out`, held to the
// island's energy at the start (hold_energy).
//
// Why the hold: the pose update and the projection lift a body that turns about a contact (its
// contact point moves on a circle, the step's correction along a line), so a box tipping over an
// edge gained energy every step, first order in dt: 0.46 % of its start by the time it landed at
// dt = 1/60 s, a 3 m rod 0.35 %. An island of passive bodies (constant_force) cannot gain
// energy: where the step ends above its start by more than kEnergySlack, the excess is taken
// from its kinetic energy, every body's velocities scaled by one factor (which keeps every
// contact's normal speed on the side it was: a speed scales with them), and what the kinetic
// energy cannot give (a body lifted in its first step from rest) from the potential, the bodies
// moved along their constant forces (a rod tipping from rest sinks 1e-6 m so, which the next
// step's projection takes back, charged to the kinetic energy it has by then).
// Explicit Euler gains energy in its free steps by itself (½ m g² dt² a step under gravity), and
// a hold would turn that into a drag that stands a tipping box on its edge: its steps are not
// held. Every other integrator's free step keeps a passive body's energy (or loses some).
inline constexpr double kEnergySlack = 1e-12;  // of the island's energy scale (J per J)
inline bool holds_energy(Integrator integrator) {
  return integrator != Integrator::euler;
}
void resolve_island(std::span<const IslandBody> bodies, ContactRows& rows,
                    const ContactSettings& settings, std::span<BodyState> out);

// Whether the body's force laws are all gravity, constant forces and damping, whose energy
// (kinetic, and the potential -F·x of the constant force F) can only fall but for the work of
// contacts; if so, that force F (N) into `force`.
bool constant_force(const BodyModel& model, Vec3& force);
bool passive(const BodyModel& model);

// The centre of the points at `arms` (m, world, from one body's centre): where a friction patch
// acts.
Vec3 mean_arm(std::span<const Vec3> arms);

// Rotates q by the rotation vector `angle` (rad, world frame): exp(angle / 2) q.
Quat rotated(const Quat& q, const Vec3& angle);

}  // namespace tumble::physics
