// The true equations of motion of one rigid body, integrated far more accurately than any
// fixed-step method under test: Boost.Odeint's Runge-Kutta-Fehlberg 7(8) with adaptive steps, in
// long double, at a tight tolerance. It shares no code with physics/integrators.cpp or
// physics/forces.cpp: the force laws are evaluated again here, so a mistake in either shows up as
// a disagreement.
#pragma once

#include "physics/integrators.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::bench {

// The primary state at the end of a run, and the kinetic energy that goes with it.
struct FinalState {
  physics::Vec3 position = physics::Vec3::Zero();         // centre of mass, world frame (m)
  physics::Vec3 momentum = physics::Vec3::Zero();         // world frame (kg m/s)
  physics::Quat orientation = physics::Quat::Identity();  // body-to-world, unit
  physics::Vec3 angular_momentum =
      physics::Vec3::Zero();  // about the centre, world frame (kg m²/s)
  double energy = 0.0;        // kinetic, ½ p·v + ½ L·ω (J)
};

FinalState final_state_of(const physics::BodyState& state);

// Integrates dx/dt = p/m, dp/dt = F, dq/dt = ½ (0, ω) q, dL/dt = τ with ω = R I⁻¹ Rᵀ L from
// `initial` over `duration` (s). q is normalised only where R and ω are evaluated, so this is the
// exact ODE, not a projected one. `tolerance` is both the absolute and the relative error
// allowed per step for every component. The run is integrated in pieces between the times where
// a law starts or ends or a moving anchor turns, each piece a smooth ODE.
FinalState solve_reference(const physics::BodyModel& model, const physics::BodyState& initial,
                           double duration /* s */, double tolerance);

// The largest difference between two final states, each part made dimensionless: the angle
// between the orientations (rad), and |a - b| of position, momentum, angular momentum and energy
// relative to the largest of |a|, |b| and |start| of that quantity (0 when all three are 0).
double relative_difference(const FinalState& a, const FinalState& b, const FinalState& start);

}  // namespace tumble::bench
