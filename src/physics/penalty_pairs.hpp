// Penalty contact between bodies (contact = "penalty" with bodies that collide): at each point
// where two boxes overlap, the PenaltyContact law's damped spring and regularised Coulomb friction
// (physics/forces.hpp, Fiedler's "Spring Physics"), equal and opposite on the two boxes, acting
// inside every integrator's evaluations (physics/integrators.hpp, Coupling).
#pragma once

#include <span>
#include <vector>

#include "physics/broad_phase.hpp"
#include "physics/contact.hpp"
#include "physics/integrators.hpp"
#include "physics/joint_solve.hpp"

namespace tumble::physics {

// The springs between boxes: per overlapping point, as PenaltyContact's per corner.
struct PairSprings {
  double stiffness = 0.0;    // k (N/m)
  double damping = 0.0;      // c (N s/m)
  double slip_speed = 0.05;  // v_s (m/s), as PenaltyContact's
};

// The wrenches of the springs between the pairs of bodies given. At each point of the pair's
// box_box_manifold with separation −d < 0 (normal n from A to B, relative velocity
// v = v_B − v_A at the point, v_n = n·v, slip v_t = v − v_n n), B is pushed by
// F = F_n n − μ F_n v_t / sqrt(|v_t|² + v_s²), F_n = max(0, k d − c v_n), and A by −F, both at
// the midpoint of the point's two anchors; μ from the two materials (combine).
class PenaltyPairs final : public Coupling {
 public:
  PenaltyPairs(std::span<const BodyModel> models, const PairSprings& springs,
               std::span<const BodyPair> pairs)
      : models_(models), springs_(springs), pairs_(pairs) {}
  void add(std::span<const BodyState> states, double t, std::span<Wrench> wrenches) const override;

 private:
  std::span<const BodyModel> models_;
  PairSprings springs_;
  std::span<const BodyPair> pairs_;
};

// What step_penalty_world keeps between calls (scratch only: penalty contact has no memory).
struct PenaltyWorld {
  std::vector<std::uint32_t> colliders;  // the bodies that collide, by index
  std::vector<Bounds> bounds;            // of each collider
  std::vector<std::uint32_t> order;
  std::vector<BodyPair> candidates;  // indices into colliders
  std::vector<BodyPair> pairs;       // indices into the bodies
};

// Advances every body from `in` at t to t + dt (s) into `out` with penalty contact between
// bodies: the pairs of colliding bodies (both models' `collides`, and settings.collide_bodies)
// whose bounds, grown by how far each body's points move in the step at its starting speeds
// plus kPenaltyReach, overlap at the start of the step are coupled by PenaltyPairs through the
// whole step (step_coupled); with no such pair, each body takes its own step as `step` gives it.
// Penalty contact with planes is each body's own PenaltyContact law, as without pairs. With
// `joints`, their forces couple the bodies too (JointForces, after the springs'), their limits,
// motors and projection follow the step (hold_joint_members), and a joint's two bodies collide
// only if it says so.
void step_penalty_world(Integrator integrator, std::span<const BodyModel> models,
                        std::span<const BodyState> in, double t, double dt,
                        const ContactSettings& settings, PenaltyWorld& scratch,
                        std::span<BodyState> out, JointWorld* joints = nullptr);

// How much further than its motion at the start of a step a body's bounds reach (m): a pair that
// comes within it over a step (pushed there by springs, say) is found at the next step, a fraction
// of a millimetre deep.
inline constexpr double kPenaltyReach = 2e-3;

}  // namespace tumble::physics
