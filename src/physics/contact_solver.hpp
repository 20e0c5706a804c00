// The velocity solver over all contact points of a step: sequential impulses with accumulated
// clamping (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005), friction per
// manifold at its centre (a "patch": two tangent directions in a circular cone of μ times the
// manifold's normal impulse, and a twist about the normal within μ × the points' mean distance
// from the centre × that impulse, as PhysX's patch friction and Bullet's friction anchors do), a
// restitution pass after the inelastic solve, and a guard that a bounce never leaves more kinetic
// energy than the impact found. Bodies are plain velocity records; a point ties body `a` to body
// `b`, or to a static shape (a plane) when `b` is kStatic.
//
// A patch has three friction rows for a face's three in-plane degrees of freedom, where friction
// per point had eight. Stacks shaped the warm starting (a tower of ten unit cubes, measured in
// world_step_test): warm-starting the friction between bodies, per point or per patch, kept the
// tower rocking (0.1 m/s after 60 s: last step's friction is out of phase with this step's
// rocking, and the passes of one step do not undo it); without it the tower comes to rest.
// Friction against planes is still warm-started (the plane tests hold with it), and the normal
// impulses everywhere. The sub-stepped solve of large or fast islands (substep_island.hpp) does
// warm-start friction between bodies: without it the pile of contact_bench still moved at
// 0.5 m/s after 20 s, with it at 0.03 m/s.
#pragma once

#include <cstdint>
#include <span>

#include "physics/contact.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::physics {

// One body's velocities while contacts are solved, and what the solve needs of its mass.
struct SolverBody {
  Vec3 velocity = Vec3::Zero();          // world frame (m/s)
  Vec3 angular_velocity = Vec3::Zero();  // world frame (rad/s)
  double inverse_mass = 0.0;             // 1/kg
  // I_world⁻¹ at the pose the points were found at (1/(kg m²)), and I_world there (kg m²), for
  // the kinetic energy.
  Mat3 inverse_inertia = Mat3::Zero();
  Mat3 inertia = Mat3::Zero();
  // A cube's (BodyConstants::isotropic): I⁻¹ is the scalar inverse_inertia(0, 0) in every frame,
  // and a turn costs three products, not a 3 × 3 one (the rows of a resting cube and its
  // projection build about a dozen turns a step).
  bool isotropic = false;

  // I⁻¹ moment (1/(kg m) for a moment arm in m): the turn an impulse along a row gives.
  Vec3 turn(const Vec3& moment) const {
    return isotropic ? Vec3(inverse_inertia(0, 0) * moment) : Vec3(inverse_inertia * moment);
  }

  // The body as the state has it: velocities and mass at that pose, whose body-to-world
  // rotation is `rotation` (passed in: the caller has it already).
  static SolverBody from(const BodyState& state, const BodyConstants& constants,
                         const Mat3& rotation);
  double kinetic_energy() const;  // of the velocities, with the inertia above (J)
  // What the solve gave the body, from the velocities it started with: m Δv (N s) and I Δω
  // (N m s), rather than a sum kept at every push: the same momentum to rounding (through a
  // collision the total moves by ~1e-16 of itself), and half the writes of a push.
  Vec3 linear_impulse(const Vec3& velocity_before) const;
  Vec3 angular_impulse(const Vec3& angular_velocity_before) const;
};

// The index of a point's second body when it touches a static shape.
inline constexpr std::uint32_t kStatic = UINT32_MAX;

// A direction d in which a contact point pushes body a (and pushes b by -d), with what the solve
// reads and writes precomputed (the Jacobian row and its image through the inverse masses): the
// relative speed along d is v_a·d + ω_a·(r_a × d) - v_b·d - ω_b·(r_b × d), and an impulse λ along
// d changes v_a by λ d/m_a and ω_a by λ I_a⁻¹(r_a × d), and b by the opposite.
// Its fields have no default values on purpose: impulse_direction sets every one, and zeroing them
// first cost a third of building a constraint (a `rep stos` per direction).
struct ImpulseDirection {
  Vec3 linear;    // d: unit, world frame
  Vec3 moment_a;  // r_a × d (m)
  Vec3 turn_a;    // I_a⁻¹ (r_a × d) (1/(kg m))
  Vec3 moment_b;  // r_b × d (m); zero against a static shape
  Vec3 turn_b;    // I_b⁻¹ (r_b × d) (1/(kg m))
  double mass;    // 1 / (m_a⁻¹ + m_b⁻¹ + moments through inverse inertias): the pair's (kg)
};

// One contact point between bodies a and b (b may be kStatic): its normal row.
struct ContactConstraint {
  std::uint32_t a = 0;          // index into the SolverBody list
  std::uint32_t b = kStatic;    // likewise, or kStatic
  ImpulseDirection normal;      // unit, from b (or the static shape) towards a
  double restitution = 0.0;     // e of the pair
  double approach_speed = 0.0;  // normal speed before the solve (m/s; negative approaching)
  // A speculative point, apart by s at the start of a step of h, may still approach at s/h: it
  // touches by the step's end and no earlier (Catto, "Speculative contacts", 2013). 0 for a
  // point that touches (m/s).
  double speculative_speed = 0.0;
  double normal_impulse = 0.0;  // accumulated (N s, >= 0)
  // What resolve_impacts gave the point in this (sub-)step (N s, >= 0): apart from the
  // accumulated impulse, which the solve may take back, but counted in the friction's limit.
  double impact_impulse = 0.0;
};

// The manifold a patch's rows were built from, which its impulses go back to by index after the
// solve (contact_rows.hpp, store_impulses): body `owner`'s with plane `plane`, or, with plane
// kPairManifold, pair `owner`'s (an index into the step's pairs). The points [first, first +
// count) of the patch are that manifold's points 0 to count - 1.
inline constexpr std::uint32_t kPairManifold = UINT32_MAX;
struct ManifoldRef {
  std::uint32_t owner = 0;
  std::uint32_t plane = kPairManifold;
};

// The friction of one manifold: the points [first, first + count) of the constraint list, all
// between the same a and b with the same normal.
struct FrictionPatch {
  std::uint32_t a = 0;
  std::uint32_t b = kStatic;
  ImpulseDirection tangent[2];  // at the manifold's centre, normal to its normal
  ImpulseDirection twist;       // turning about the normal (angular only)
  double friction = 0.0;        // μ of the pair
  PatchMemo shape;              // its twist_arm (m): mean distance of the points from the centre
  std::uint32_t first = 0, count = 0;
  double tangent_impulse[2] = {0.0, 0.0};  // accumulated, |(t0, t1)| <= μ Σ normal (N s)
  double twist_impulse = 0.0;              // accumulated, |twist| <= μ twist arm Σ normal (N m s)
  // Rolling resistance (Material::rolling_resistance): turning about the two tangents, both
  // together within the lever arm times Σ normal (N m s); solved only where the arm is > 0. Not
  // warm-started: it starts from 0 in each solve, and in each sub-step of a sub-stepped one.
  // Its rows turn about the tangents (turning_direction of tangent[k].linear), made where they
  // are solved: a patch that rolls freely carries no more than the arm and the two impulses.
  double rolling_arm = 0.0;  // m
  double rolling_impulse[2] = {0.0, 0.0};
  ManifoldRef source;
  // Whether the friction impulses are warm-started (the row builder sets them) and go back to the
  // manifold: not between bodies in a converged solve (above).
  bool keeps_friction = false;
};

// The direction that turns a about the unit `axis` (world) and b the other way (none for a
// static shape): no linear part.
inline ImpulseDirection turning_direction(const Vec3& axis, const SolverBody& a,
                                          const SolverBody* b) {
  const Vec3 turn_a = a.turn(axis);
  double inverse = 0.0 + axis.dot(turn_a);
  Vec3 moment_b = Vec3::Zero(), turn_b = Vec3::Zero();
  if (b) {
    moment_b = axis;
    turn_b = b->turn(axis);
    inverse += 0.0 + axis.dot(turn_b);
  }
  return {.linear = Vec3::Zero(),
          .moment_a = axis,
          .turn_a = turn_a,
          .moment_b = moment_b,
          .turn_b = turn_b,
          .mass = inverse > 0.0 ? 1.0 / inverse : 0.0};
}

// Two unit vectors spanning the plane normal to the unit `normal`, from the world axis least
// along it (so the same normal always gives the same basis).
void tangent_basis(const Vec3& normal, Vec3 (&out)[2]);

// Relative speed along a direction: of a's point minus b's (m/s).
[[gnu::always_inline]] inline double relative_speed(const ImpulseDirection& d, const SolverBody& a,
                                                    const SolverBody* b) {
  double out = a.velocity.dot(d.linear) + a.angular_velocity.dot(d.moment_a);
  if (b) out -= b->velocity.dot(d.linear) + b->angular_velocity.dot(d.moment_b);
  return out;
}

// An impulse (N s) along the direction on a, and its opposite on b (none for a static shape).
[[gnu::always_inline]] inline void push(const ImpulseDirection& d, SolverBody& a, SolverBody* b,
                                        double impulse) {
  const Vec3 linear = impulse * d.linear;
  a.velocity += a.inverse_mass * linear;
  a.angular_velocity += impulse * d.turn_a;
  if (!b) return;
  b->velocity -= b->inverse_mass * linear;
  b->angular_velocity -= impulse * d.turn_b;
}

// A joint's equality row among an island's contacts (physics/joints.hpp: its rate J v is held
// at 0): solved in each pass before the contacts, so that a load a contact carries reaches the
// bodies the joint holds (a cart's weight, through its axles, to its wheels on the floor). The
// joints' own solve (physics/joint_solve.hpp) made them hold in the free step, and projects the
// bodies onto them again after the island's solve; these rows carry the contacts' impulses
// across them meanwhile. Not warm-started: they start at 0 in each solve.
struct JointConstraint {
  std::uint32_t a = 0;        // index into the SolverBody list
  std::uint32_t b = kStatic;  // likewise, or kStatic for the world or a static body
  ImpulseDirection direction;
  double impulse = 0.0;  // accumulated this solve (N s or N m s)
};

// What a solve is asked for.
struct SolveSettings {
  int iterations = 10;  // the most passes over all points
  // A pass that changes no accumulated impulse by more than this fraction of the largest one
  // ends the solve early: impacts converge in a few passes, resting stacks use all of them.
  double tolerance = 1e-12;
  double restitution_threshold = 0.5;  // m/s: slower approaches do not bounce
  // Apply the rows' accumulated impulses first (the row builder started them from the last
  // step's, contact_rows.hpp), friction only where the patch keeps_friction.
  bool warm_start = false;
  // Solve the normal rows as one block each pass (physics/normal_block.hpp), friction after them,
  // where there are at most kMostBlockRows of them; and the impacts first, by resolve_impacts,
  // rather than a bounce after the solve.
  bool block = false;
};

// Solves the points against the bodies' velocities in place: first the inelastic solve (normal
// speeds >= 0, each patch's friction within its cone), then the bounce (normal speed >= -e ×
// approach speed for points that approached faster than the threshold and pushed), then, if the
// bounce raised the kinetic energy of the bodies above its value before the solve, it is scaled
// back until it does not (sequential bounces at several points can otherwise create energy: Box3D
// issue 83). The bodies given are solved as one group: a caller with unrelated groups (islands)
// solves each alone, so that one group's bounce does not scale another's. The accumulated impulses
// of the inelastic solve stay in the rows (store_impulses takes them back to the manifolds). Every
// point belongs to exactly one patch.
void solve_contacts(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                    std::span<FrictionPatch> patches, const SolveSettings& settings,
                    std::span<JointConstraint> joints = {});

// For the sub-stepped solve of large islands (physics/substep_island.hpp).
// Applies every point's and patch's accumulated impulse to the bodies (each sub-step starts so).
void warm_start(std::span<SolverBody> bodies, std::span<const ContactConstraint> points,
                std::span<const FrictionPatch> patches);

// One pass over every patch of a sub-step of h (s): its points' normal rows, with separations[i]
// (m, negative inside) the current separation of points[i], then its friction. A point apart by
// s may still approach at s/h (speculative, as above); one inside may not approach (the
// projection, not the velocities, takes it out: that adds no kinetic energy). `by_block`: the
// normal rows as one block where there are at most kMostBlockRows (physics/normal_block.hpp).
void substep_pass(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                  std::span<const double> separations, std::span<FrictionPatch> patches,
                  double h /* s */, bool by_block);

// The impacts among the points, each resolved at once as an instant impulse, before the solve
// of the (sub-)step: a manifold with a point of restitution e > 0 that approaches faster than
// `threshold` (m/s) and closes within the (sub-)step (its speed below -allowed[i], the approach it
// may have while still apart: speculative_speed, or a sub-step's separation over its length) is
// solved alone, its closing points as one block (physics/normal_block.hpp) to leave each at
// -e × the speed it approached at, now. Manifolds are taken in turn, in rounds, each round after
// the first taking only the manifolds of bodies the last one moved, until none approaches so (up
// to kImpactRounds + 2 × the manifolds): an impact passes on along a row of touching bodies as a
// momentum pulse, pair by pair (Newton's cradle: the struck end leaves with the striker's speed,
// where one solve of every contact at once gives the three cubes -v/3, 2v/3, 2v/3; edyn's
// restitution pass, xissburg/edyn#49, walks the contact graph so). Each impact's impulse and
// velocities are of one instant at one pose, so for e = 1 it keeps the kinetic energy to
// rounding, at one point or several (the simultaneous Newton impact of a block keeps it too:
// ΔE = λ·u⁻ + ½ λ·Aλ and Aλ = -2u⁻ on the pushing rows), and for e < 1 it takes energy. The
// impulses add to each point's impact_impulse, which the friction's limit counts (the caller
// zeroes it at the start of each (sub-)step).
inline constexpr int kImpactRounds = 8;
void resolve_impacts(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                     std::span<const FrictionPatch> patches, std::span<const double> allowed,
                     double threshold);

// The kinetic energy of the bodies (J).
double total_kinetic_energy(std::span<const SolverBody> bodies);

}  // namespace tumble::physics
