// How joints move bodies (physics/joints.hpp): a world with joints steps its bodies together.
//
// 1. The free step. The joints' equality rows hold at the acceleration level inside the
//    integrator: wherever it evaluates the bodies' forces (every RK4 stage, from that stage's
//    states of all bodies), the joint forces Jᵀλ are solved from K λ = -(J a + J̇v), K = J M⁻¹ Jᵀ,
//    a the bodies' accelerations under their own laws (with the gyroscopic term), as one sparse
//    LDLᵀ factorisation over all rows (Eigen's SimplicialLDLT: linear in a chain's or a tree's
//    length, exact at any mass ratio). The constrained motion is then integrated at the
//    integrator's order: RK4's fourth, where impulses solved after each step would be first order.
//    A sprung distance joint is a force between its anchors here. With the splitting integrators
//    the joint forces are held over each kick from its start (as Coupling is), the drift being the
//    bodies' exact free flight: order 1 in the joints, kept on them by step 3.
// 2. Limits, motors and a distance's range: rows that switch on and off (a one-sided row, a bounded
//    motor) are solved after the free step at its end, by sequential impulses with accumulated
//    clamping, warm-started from the last step (Catto, GDC 2005/2009), the equality rows among
//    them so that a stop does not pull a joint apart. A limit not yet reached is speculative: it
//    lets the coordinate approach at its gap over the step (Catto, "Predictive joint limits",
//    2020). The poses move by impulse_position_weight × the change, as contact impulses move them.
// 3. Projection: the poses are moved onto every equality row (and off every limit passed) by
//    Newton's method on C(q) = 0 with the least mass-weighted move, each iteration one solve with
//    K, and the velocities onto J v = 0 by the least kinetic-energy change (coordinate projection;
//    Hairer, Lubich and Wanner, "Geometric Numerical Integration", IV.4). The velocity projection
//    only takes kinetic energy away, and both move the state by the step's local error, so the
//    integrator's order stays.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <memory>
#include <span>
#include <vector>

#include "physics/broad_phase.hpp"
#include "physics/integrators.hpp"
#include "physics/joints.hpp"

namespace tumble::physics {

// A joint's one-sided and motor impulses of the last step (N s, N m s), which warm-start the next.
struct JointImpulses {
  double lower = 0.0;
  double upper = 0.0;
  double motor = 0.0;
};

// The rows of every joint and the factorisation of their K, kept from call to call: the pattern
// is analysed once and factorised again at each state.
class JointSystem {
 public:
  // Scratch: a copy starts afresh (the factorisation cannot be copied, and need not be).
  JointSystem() = default;
  JointSystem(const JointSystem&) {}
  JointSystem& operator=(const JointSystem&) {
    factor_.reset();
    analysed_ = false;
    return *this;
  }
  JointSystem(JointSystem&&) noexcept = default;
  JointSystem& operator=(JointSystem&&) noexcept = default;

  // The rows of every joint at `states` (b of a joint held to the world, the world).
  void build(std::span<const Joint> joints, std::span<const BodyModel> models,
             std::span<const BodyState> states);
  // With the one-sided rows of the joints whose limits or range are passed at these states, as
  // equalities at their bound: for the projection.
  void build_with_passed_limits(std::span<const Joint> joints, std::span<const BodyModel> models,
                                std::span<const BodyState> states);
  // Factorises K of the rows built; false when it cannot (not finite).
  bool factorise();
  // λ of K λ = rhs, for rhs of the rows' size.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;

  const std::vector<JointRow>& rows() const { return rows_; }
  // What an impulse λ_r along each row gives body i: Δv = m⁻¹ Σ linear λ, Δω = I⁻¹ Σ angular λ.
  double inverse_mass(std::uint32_t body) const { return inverse_masses_[body]; }
  const Mat3& inverse_inertia(std::uint32_t body) const { return inverse_inertias_[body]; }

 private:
  void masses(std::span<const BodyModel> models, std::span<const BodyState> states);
  // For a new pattern of rows: which rows meet at which body, and where in K each product goes.
  void plan();
  struct Term {  // row r's and row s's parts on one body, added into K_rs
    std::uint32_t r = 0, s = 0, body = 0;
    bool r_on_b = false, s_on_b = false;
    std::ptrdiff_t slot = 0;  // index into k_'s values
  };
  std::vector<Term> terms_;
  std::vector<std::ptrdiff_t> diagonal_slots_;
  std::vector<Vec3> turns_;  // I⁻¹ w of each row's a and b
  std::vector<JointRow> rows_;
  std::vector<double> inverse_masses_;
  std::vector<Mat3> inverse_inertias_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pattern_;  // the rows' bodies analysed
  Eigen::SparseMatrix<double> k_;
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> factor_;
  bool analysed_ = false;
};

// The joints' forces as a Coupling of the bodies (step 1 above): for `models` and `joints`.
class JointForces final : public Coupling {
 public:
  JointForces(std::span<const Joint> joints, std::span<const BodyModel> models, JointSystem& system)
      : joints_(joints), models_(models), system_(system) {}
  void add(std::span<const BodyState> states, double t, std::span<Wrench> wrenches) const override;

 private:
  std::span<const Joint> joints_;
  std::span<const BodyModel> models_;
  JointSystem& system_;
};

// A world's joints, the bodies they hold, and what they keep from step to step.
struct JointWorld {
  std::vector<Joint> joints;           // as placed: a and b index the world's bodies
  std::vector<std::uint32_t> members;  // the bodies the joints hold, ascending
  std::vector<Joint> local;            // the joints with a and b indexing `members`
  std::vector<BodyModel> models;       // the members'
  std::vector<char> held;              // per body of the world: whether it is a member
  // The pairs of bodies a joint keeps from colliding (collide_connected false), sorted.
  std::vector<BodyPair> unpaired;
  bool holds(std::uint32_t body) const { return body < held.size() && held[body]; }
  bool keeps_apart(const BodyPair& pair) const {
    return std::binary_search(unpaired.begin(), unpaired.end(), pair);
  }
  std::vector<JointImpulses> impulses;  // per joint, of the last (sub-)step
  double substep = 0.0;                 // s: the length of the last step's sub-steps
  JointSystem system;                   // of the local rows
  JointSystem whole;  // of the joints' rows over the world's bodies (penalty contact's coupling)
  std::vector<BodyState> start, end;  // scratch: the members' states
};

// The joint world of `joints` (placed on the bodies of `models`, physics/joints.hpp).
JointWorld make_joint_world(std::vector<Joint> joints, std::span<const BodyModel> models);

// The force and torque each joint applies to its body a at the world's `states` and time t (N,
// N m, world frame, about a's centre), in the joints' order: its equality rows' λ from the free
// step's solve at those states, its spring's force, and the mean force of its limit and motor
// impulses over the last sub-step.
std::vector<Wrench> joint_wrenches(const JointWorld& world, std::span<const BodyState> states,
                                   double t /* s */);

// The fastest small oscillation (rad/s) that the joints' forces at `states` give a body, from
// their geometric stiffness (Tournier et al., "Stable Constrained Dynamics", SIGGRAPH 2015): a
// force F pulling at arm r turns a body of moment I across r back at ω² = |F||r| / I, a rod's
// pull F swings a mass m on its length ℓ at F / (m ℓ), a spring k at k / m; a body's terms add.
// A light link between heavy loads oscillates fast: a 0.1 kg link of 0.1 m pulled by 550 N at
// both ends (a 10 kg ball whirled at 10 m/s on a chain) at ~800 rad/s, past what RK4 holds at
// dt = 1/240 s (ω dt < 2.8): it blew up so within three steps.
double fastest_joint_mode(std::span<const Joint> joints, std::span<const BodyModel> models,
                          std::span<const BodyState> states, double t /* s */, JointSystem& system);

// A step of dt is cut into sub-steps so that the fastest mode turns by at most kStableTurn rad
// in each, up to kMostJointSubsteps: every integrator is stable there (RK4 to 2.8 rad, the
// symplectic ones to 2), and RK4 accurate.
inline constexpr double kStableTurn = 1.0;
inline constexpr int kMostJointSubsteps = 64;
int joint_substeps(double fastest /* rad/s */, double dt /* s */);

// Newton iterations of the projection at most, and the error (m or rad) at which it stops.
inline constexpr int kJointProjectionIterations = 16;
inline constexpr double kJointProjectionTolerance = 1e-13;
// Passes of the sequential impulses over limits, motors and ranges at most; they stop earlier
// when no impulse changes by more than kJointTolerance of the largest.
inline constexpr int kJointPasses = 100;
inline constexpr double kJointTolerance = 1e-10;

// Advances the joints' members from the world's states `in` at t to t + dt (s) into `out` (the
// world's too; other bodies untouched), by steps 1 to 3 above, in joint_substeps sub-steps for
// the joints' fastest mode at the start. Static members stay where they are.
void advance_joint_members(Integrator integrator, std::span<const BodyState> in, double t,
                           double dt, JointWorld& world, std::span<BodyState> out);

// Steps 2 and 3 on the world's `states` at the end of a step of dt (s), in place: for a free
// step taken with JointForces over the world (penalty contact's).
void hold_joint_members(Integrator integrator, double dt, JointWorld& world,
                        std::span<BodyState> states);

// Step 3 alone on the world's `states`, in place: after contacts have moved the members.
void project_joint_members(JointWorld& world, std::span<BodyState> states);

// Advances every body of `models` from `in` at t to t + dt (s) into `out`: the joints' members
// by advance_joint_members, the others alone (`step`; a static body stays). No contact:
// physics/world_step.hpp adds it.
void step_joints(Integrator integrator, std::span<const BodyModel> models,
                 std::span<const BodyState> in, double t, double dt, JointWorld& world,
                 std::span<BodyState> out);

}  // namespace tumble::physics
