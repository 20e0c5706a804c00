// The velocity solver over all contact points of a step: sequential impulses with accumulated
// clamping (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005), a circular friction
// cone per point, a restitution pass after the inelastic solve, and a guard that a bounce never
// leaves more kinetic energy than the impact found. Bodies are plain velocity records; a point
// ties one body to a static shape (a plane), and the next step of this design adds a second body.
#pragma once

#include <span>

#include "physics/contact.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::physics {

// One body's velocities while contacts are solved, and what the solve needs of its mass.
struct SolverBody {
  Vec3 velocity = Vec3::Zero();          // world frame (m/s)
  Vec3 angular_velocity = Vec3::Zero();  // world frame (rad/s)
  double inverse_mass = 0.0;             // 1/kg
  Mat3 inverse_inertia =
      Mat3::Zero();             // I_world⁻¹ at the pose the points were found at (1/(kg m²))
  Mat3 inertia = Mat3::Zero();  // I_world there (kg m²), for the kinetic energy
  Vec3 linear_impulse = Vec3::Zero();   // Σ of the impulses applied by the solve (N s)
  Vec3 angular_impulse = Vec3::Zero();  // Σ of their moments about the centre (N m s)

  // The body as the state has it: velocities and mass at that pose.
  static SolverBody from(const BodyState& state, const BodyConstants& constants);
  double kinetic_energy() const;  // of the velocities, with the inertia above (J)
};

// A direction d in which a contact point pushes its body, with what the solve reads and writes
// for it precomputed (the Jacobian row and its image through the inverse mass): the point's speed
// along d is v·d + ω·(r × d), and an impulse λ along d changes v by λ d/m and ω by λ I⁻¹(r × d).
struct ImpulseDirection {
  Vec3 linear = Vec3::Zero();  // d: unit, world frame
  Vec3 moment = Vec3::Zero();  // r × d (m)
  Vec3 turn = Vec3::Zero();    // I⁻¹ (r × d) (1/(kg m))
  double mass = 0.0;  // 1 / (m⁻¹ + (r × d)·I⁻¹(r × d)): the mass the body shows (kg)

  double speed(const SolverBody& body) const {  // m/s
    return body.velocity.dot(linear) + body.angular_velocity.dot(moment);
  }
  void push(SolverBody& body, double impulse /* N s */) const {
    body.velocity += (impulse * body.inverse_mass) * linear;
    body.angular_velocity += impulse * turn;
    body.linear_impulse += impulse * linear;
    body.angular_impulse += impulse * moment;
  }
};

// One contact point between body `body` and a static plane.
struct ContactConstraint {
  std::size_t body = 0;         // index into the SolverBody list
  ImpulseDirection normal;      // along the plane's normal, from the plane to the body
  ImpulseDirection tangent[2];  // two unit directions spanning the plane
  double friction = 0.0;        // μ of the pair
  double restitution = 0.0;     // e of the pair
  double approach_speed = 0.0;  // normal velocity before the solve (m/s; negative approaching)
  double normal_impulse = 0.0;  // accumulated (N s, >= 0)
  double tangent_impulse[2] = {0.0, 0.0};  // accumulated, |(t0, t1)| <= μ normal (N s)
  // Where the result goes back to for warm starting: a point of one manifold.
  ContactPoint* source = nullptr;
};

// A point at `arm` (m, world, from the body's centre) pushed along `normal` (unit, world), with
// its directions computed from the body.
ContactConstraint make_constraint(std::size_t body_index, const SolverBody& body, const Vec3& arm,
                                  const Vec3& normal, const Material& material);

// What a solve is asked for.
struct SolveSettings {
  int iterations = 10;  // the most passes over all points
  // A pass that changes no accumulated impulse by more than this fraction of the largest one
  // ends the solve early: impacts converge in a few passes, resting stacks use all of them.
  double tolerance = 1e-12;
  double restitution_threshold = 0.5;  // m/s: slower approaches do not bounce
  bool warm_start = false;             // apply the points' impulses first (from `source`)
};

// Solves the points against the bodies' velocities in place: first the inelastic solve (normal
// speeds >= 0, friction within the cone), then the bounce (normal speed >= -e × approach speed for
// points that approached faster than the threshold and pushed), then, per body, a bounce that
// would raise the kinetic energy above its value before the solve is scaled back until it does
// not (sequential bounces at several points can otherwise create energy: Box3D issue 83).
// Accumulated impulses are written back to each point's `source`.
void solve_contacts(std::span<SolverBody> bodies, std::span<ContactConstraint> points,
                    const SolveSettings& settings);

}  // namespace tumble::physics
