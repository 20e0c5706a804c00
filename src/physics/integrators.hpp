// Interchangeable time integrators for one rigid body over one fixed step.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "physics/forces.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::physics {

// Everything about a body that does not change while it moves.
struct BodyModel {
  BodyConstants constants;
  std::vector<ForceLaw> forces;
};

enum class Integrator {
  euler,             // explicit Euler: every derivative from the start of the step (order 1)
  symplectic_euler,  // semi-implicit Euler: momenta first, then positions from new velocities
  rk4,               // classical Runge-Kutta as in Fiedler's "Physics in 3D" (order 4)
};

// The integrators in the order they are listed to users.
inline constexpr Integrator kAllIntegrators[] = {Integrator::euler, Integrator::symplectic_euler,
                                                 Integrator::rk4};

// The scene-file name of an integrator ("euler", "symplectic_euler", "rk4").
std::string_view integrator_name(Integrator integrator);
std::optional<Integrator> integrator_from_name(std::string_view name);

// Advances `state` from time t to t + dt (s).
BodyState step(Integrator integrator, const BodyModel& model, const BodyState& state, double t,
               double dt);

}  // namespace tumble::physics
