// Step-size advice from a body's force laws, before a run: where an explicit integrator turns
// unstable, from the linear test equation of each stiff law, and where the body turns so far per
// step that the orientation will be inaccurate. Pure computation: the commands print it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "physics/integrators.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::sim {

// How a splitting method's kick (physics/integrators.cpp) applies a mode's damping: as the exact
// decay it computes for linear and angular damping and for a damped spring, or as the force at
// the kick's start held over the kick — an explicit Euler step of the momenta — which is how it
// takes every other law, penalty contact's damping and friction among them.
enum class KickDamping { exact, frozen };

// One linear mode the force laws give the motion: y'' + k y' + ω_n² y = 0, or, with ω_n = 0, the
// decay p' = -k p of a momentum (linear or angular damping).
struct LinearMode {
  double damping_rate = 0.0;  // k (1/s): c/m, c/I_min, or a spring's c/m_eff
  double frequency = 0.0;     // ω_n (rad/s): sqrt(stiffness / m_eff); 0 for a pure decay
  KickDamping kick_damping = KickDamping::exact;
};

// The largest dt (s) at which `integrator` keeps the mode from growing: the one-step map of the
// linear system has spectral radius <= 1 for every step up to it. For a pure decay this is
// k dt <= 2 for euler and symplectic_euler and k dt <= 2.785 for rk4; for an undamped oscillator
// ω dt <= 2 for symplectic_euler and 2√2 for rk4, and 0 for euler (it gains energy at any
// step). The splitting methods kick springs like Störmer-Verlet (ω dt <= 2 for splitting;
// splitting4, Yoshida's triple jump of it, has a smaller limit) and apply damping exactly (no
// limit on a pure decay) or, for KickDamping::frozen, by explicit kicks (k dt <= 4 for
// splitting's two half kicks). +infinity when no step is unstable; nullopt for an integrator
// this model does not know.
std::optional<double> stability_limit(physics::Integrator integrator, const LinearMode& mode);

// Above this rotation per step (rad) the integrators that advance q along a straight line in
// quaternion space (euler, symplectic_euler, rk4) lose the orientation's accuracy.
inline constexpr double kMaxRotationPerStep = 0.5;
// A suggested step is this fraction of the limit it must respect.
inline constexpr double kSuggestedFractionOfLimit = 0.8;

struct StepWarning {
  std::string message;                 // one sentence: the cause, its numbers and the limit
  std::optional<double> suggested_dt;  // s; absent when no step would do (euler on a spring)
  // An integrator without this problem at the current dt, when one exists.
  std::optional<physics::Integrator> suggested_integrator;
  // The problem is penalty contact's: contact = "impulse" is suggested too.
  bool suggests_impulse_contact = false;
};

// A mode with the words a warning gives it.
struct NamedMode {
  LinearMode mode;
  std::string cause;  // what makes the mode, with its numbers: the warning's first clause
  std::string outcome = "the motion will blow up";  // what a step beyond the limit does
  // The mode is penalty contact's: contact = "impulse" has no such limit.
  bool penalty_contact = false;
};

// A warning when `dt` (s) is beyond the stability limit of `integrator` on the mode: its cause,
// ω_n dt (or k dt) against the limit, the outcome, and what to use instead (a dt, another
// integrator, impulse contact).
std::optional<StepWarning> check_mode(physics::Integrator integrator, const NamedMode& named,
                                      double dt);

// The warnings for one body stepped by `integrator` at `dt` (s) for `duration` (s): one per
// stiff law beyond its stability limit (linear damping: k = c/m; angular damping: k = c/I_min;
// a spring at attachment r: ω_n² = stiffness μ and k = damping μ + c_linear/m with
// μ = 1/m + |r|²/I_min, the lightest the body can seem to it; penalty contact: the box bouncing
// and rocking on four corners and, under gravity, the decay of its slip by the regularised
// friction, sim/penalty_modes.hpp) and one when the fastest spin expected (from the initial
// spin, the energy and the constant torques; springs and pushes are not predicted) turns the
// body more than kMaxRotationPerStep per step. Modes are checked one at a time; where laws
// interact the limit is an estimate.
std::vector<StepWarning> check_step(const physics::BodyModel& model,
                                    const physics::BodyState& initial,
                                    physics::Integrator integrator, double dt, double duration);

}  // namespace tumble::sim
