// The solve of a large island of bodies (a pile), in sub-steps of the physics step,
// after Box2D v3's "soft step" (Catto, "Solver2D", 2024; the Box2D v3 release notes), with rigid
// rows and a position projection in place of its soft ones. Each sub-step integrates the bodies'
// velocities with the scene's integrator (their forces; a body under gravity alone exactly, as
// every integrator would, without running one), warm-starts and solves the contacts
// once, moves the poses with the solved velocities, projects them out of what is still inside
// (one non-linear Gauss-Seidel pass: it moves no momentum), and solves once more at the moved
// poses (the relax pass). Impacts are resolved at once before each sub-step's solve
// (resolve_impacts, contact_solver.hpp), from the velocities before its warm start.
//
// Why sub-steps rather than passes: a pile is a long chain of contacts, and a pass of the solver
// moves an impulse one contact along it. Passes converge within a step but leave what they
// missed as penetration for the next; sub-steps let the positions follow each partial solve.
// Why rigid rows: Box2D's soft rows (30 Hz springs, twice that against the ground) hold a load
// by compressing under it, in proportion to the load over the effective mass: a 1.8 m deep pile
// of 4 to 108 kg boxes stood 5 cm inside itself, and a tower of ten unit cubes 3.7 cm shorter;
// rigid rows with the projection leave the settled pile 0.3 mm inside (contact_bench, in the
// README).
//
// The contact points are found at the start pose (with speculative points as far as the bodies
// can move in the step) and kept fixed in the bodies: each sub-step measures a point's separation
// from the bodies' moved poses (PositionPoint), which Catto names as what makes sub-stepping
// affordable. A caller may find the points of fast pairs again between sub-steps (`refresh`).
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "physics/contact_island.hpp"
#include "physics/contact_solver.hpp"
#include "physics/integrators.hpp"

namespace tumble::physics {

inline constexpr int kSubsteps = 4;  // Box2D's default for a 60 Hz step
// An island in which bodies can close on each other fast takes more sub-steps, one for each
// kSubstepReach (m) the fastest pair can close by in the step, up to kMostSubsteps: a box landing
// on a pile at 20 m/s (33 cm a step) drives the box it hits into the next one by what a sub-step
// lets it move before the solve's one pass reaches that contact. On the 1000-box pile of
// contact_bench (its first 6 s), a fixed 4 sub-steps left 846 pair points more than 1 cm deep
// and the deepest 9.9 cm, 8 left 49 and 5.5 cm, 16 left 2 and 2.9 cm (a box under an impact, in
// the floor). With this rule (and the planes' corners found again, island_solve.cpp) one sub-step
// per 2 cm up to 16 took the whole 20 s run to 1.6 cm deep at most; one per 1 cm up to 32 to
// 0.84 cm (seeds 2 and 3: 0.83 and 0.92 cm), the pour's steps costing about twice as much. Once
// the pile settles its islands take four: the median step is unchanged. (These depths are the
// manifolds', as found; from the poses at each step's end the pour goes 10-14 cm deep, a box
// falling on beside one that lands: docs/performance.md, "The depth, measured from the poses".)
inline constexpr double kSubstepReach = 0.01;
inline constexpr int kMostSubsteps = 32;

// The sub-steps for an island whose fastest pair can close by `reach` (m) in the step.
int substeps_for(double reach);

// A body of a sub-stepped island.
struct SubstepBody {
  const BodyModel* model = nullptr;
  BodyState state;  // the start of the step; the end after substep_island
};

// Scratch kept between steps so that a warm step allocates little.
struct SubstepScratch {
  std::vector<double> separations;   // per point
  std::vector<double> allowed;       // per point: its approach speed while apart (m/s)
  std::vector<Mat3> rotations;       // per body, of the pose being measured
  std::vector<ProjectedPose> poses;  // per body
  std::vector<Vec3> free_velocity, free_angular_velocity, free_angular_momentum;  // per body
  std::vector<Vec3> gravity;       // per body: its gravity, when that is all that acts on it
  std::vector<char> falls_freely;  // per body: whether gravity is all that acts on it

  // Every per-body list sized to `bodies`.
  void size_for(std::size_t bodies) {
    rotations.resize(bodies);
    free_velocity.resize(bodies);
    free_angular_velocity.resize(bodies);
    free_angular_momentum.resize(bodies);
    gravity.resize(bodies);
    falls_freely.resize(bodies);
  }
};

struct StepContext;

// Advances the island's bodies (context.scratch.substep_bodies) from context.t to t + dt, in
// `substeps` sub-steps. scratch.rows holds a SolverBody per body made at the start pose and the
// rows of its points (their rows at the start pose, and where they sit in the two bodies), every
// point in exactly one patch. The rows' accumulated impulses are over a whole step: they
// warm-start the sub-steps with a `substeps`-th of them, and are the last sub-step's times
// `substeps` after. `refresh`, if given, runs before each sub-step after the first, with its
// number: it may rewrite the rows in place (a caller finding the contacts of fast bodies again),
// keeping the lists' sizes.
void substep_island(const StepContext& context, int substeps,
                    const std::function<void(int)>& refresh = {});

}  // namespace tumble::physics
