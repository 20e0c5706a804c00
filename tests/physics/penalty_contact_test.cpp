// Penalty contact (physics/penalty_contact.cpp) tends to rigid contact as it stiffens: the apex of
// a flat cube's first bounce approaches the closed form e² h₀ that impulse contact gives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "physics/forces.hpp"
#include "physics/integrators.hpp"
#include "sim/penalty_modes.hpp"
#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;          // m/s²
constexpr double kDropHeight = 1.0;  // of the bottom face above the floor at the start (m)

// A 1 kg unit cube, flat, its bottom face kDropHeight above a frictionless floor at y = 0.
BodyModel dropped_cube() {
  return {.constants = cube_constants(1.0, 1.0),
          .forces = {Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
          .shape = box_shape(Vec3::Constant(0.5)),
          .material = {.restitution = 0.5, .friction = 0.0}};
}

BodyState drop_start(const BodyModel& model) {
  return make_state(model.constants, Vec3(0.0, 0.5 + kDropHeight, 0.0), Vec3::Zero(),
                    Quat::Identity(), Vec3::Zero());
}

// The bottom face's height at the first apex after the first bounce (m): the vertex of the
// parabola through the highest step and its two neighbours, all in free flight, so that the
// sampling adds nothing (the flight under gravity is a parabola). 0 if it never rises.
double first_apex(sim::Simulation& world, double until) {
  std::vector<double> heights;  // of the bottom face (m)
  bool rising = false;
  while (world.time() < until) {
    world.step();
    const BodyState& state = world.current().front();
    rising = rising || state.velocity().y() > 0.0;
    if (!rising) continue;
    heights.push_back(state.position().y() - 0.5);
    const std::size_t n = heights.size();
    if (n >= 3 && heights[n - 1] < heights[n - 2]) {
      const double a = heights[n - 3], b = heights[n - 2], c = heights[n - 1];
      return b + (a - c) * (a - c) / (8.0 * (2.0 * b - a - c));
    }
  }
  return 0.0;
}

// The apex (m) of the bottom face after a flat landing at the speed of the drop, sqrt(2 g h₀),
// with penalty contact of stiffness k and damping c per corner, RK4 at 1/50 of the bounce's
// 1/ω_n = sqrt(m/(4k)). The run starts at the touch, the face 1 nm inside: the fall before it is
// a parabola, and starting there puts the damping force's jump from 0 to 4c v₀ (450 N at
// k = 1e4 N/m, against a weight of 9.81 N) at the start of a step, where the first stage sees it,
// rather than inside one, which would cost that step O(4c v₀ dt / m) (measured: the apex off by
// 1e-3 m at any k, more than the stiffness's own error at k = 1e6). The apex is ballistic from
// the first step with every corner out and rising.
double penalty_apex(double stiffness, double damping) {
  BodyModel model = dropped_cube();
  model = with_penalty_contact(model, {Plane{.material = model.material}}, stiffness, damping);
  const double dt = 0.02 * std::sqrt(model.constants.mass / (4.0 * stiffness));
  const double landing_speed = std::sqrt(2.0 * kG * kDropHeight);  // m/s
  sim::Simulation world(
      {model},
      {make_state(model.constants, Vec3(0.0, 0.5 - 1e-9, 0.0), Vec3(0.0, -landing_speed, 0.0),
                  Quat::Identity(), Vec3::Zero())},
      Integrator::rk4, dt);
  while (world.time() < 1.0) {
    world.step();
    const BodyState& state = world.current().front();
    const double height = state.position().y() - 0.5, rise = state.velocity().y();
    if (height > 0.0 && rise > 0.0) return height + rise * rise / (2.0 * kG);
  }
  return 0.0;
}

double impulse_apex() {
  const BodyModel model = dropped_cube();
  sim::Simulation world({model}, {drop_start(model)}, Integrator::rk4, 1.0 / 600.0,
                        {Plane{.material = model.material}});
  return first_apex(world, 1.5);
}

// The penalty apex falls short of the rigid one by about 0.85 m / sqrt(k / (N/m)) (gravity acts
// during a contact of a few 1/ω_n, ω_n = sqrt(4k/m)): the error shrinks by sqrt(10) per decade of
// stiffness (asserted within 10%) to 0.85 mm at k = 1e6 N/m (asserted below 1 mm, 0.4%). Had the
// damping come from the linear damped spring's e = exp(-ζπ / sqrt(1 - ζ²)), ζ = 0.2154 for
// e = 0.5, the apex would tend to penalty_restitution(0.2154)² h₀ = 0.303 m instead: the law only
// pushes and lets go early.
TEST(PenaltyContact, BounceApexConvergesToTheRigidAnswerAsStiffnessGrows) {
  constexpr double kRestitution = 0.5;
  const double rigid = kRestitution * kRestitution * kDropHeight;  // m
  const double impulse = impulse_apex();
  std::printf("[ measured ] impulse contact: apex %.6f m, closed form e² h₀ = %.6f m\n", impulse,
              rigid);
  EXPECT_NEAR(impulse, rigid, 0.01 * rigid);
  double previous_error = 0.0;
  for (const double stiffness : {1e4, 1e5, 1e6}) {
    const double damping = sim::penalty_damping_for_restitution(kRestitution, stiffness, 1.0);
    const double apex = penalty_apex(stiffness, damping);
    const double error = std::abs(apex - rigid);
    std::printf("[ measured ] penalty k = %.0e N/m, c = %.4g N s/m: apex %.6f m, error %.3e m\n",
                stiffness, damping, apex, error);
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, std::sqrt(10.0), 0.1 * std::sqrt(10.0))
          << "k = " << stiffness;
    }
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-3);  // m, at k = 1e6 N/m

  const double naive_zeta = 0.2154;  // exp(-ζπ / sqrt(1 - ζ²)) = 0.5
  const double naive = penalty_apex(1e6, naive_zeta * std::sqrt(1e6 * 1.0));
  const double tends_to = std::pow(sim::penalty_restitution(naive_zeta), 2) * kDropHeight;
  std::printf(
      "[ measured ] damping from the linear spring's formula: apex %.6f m (tends to %.6f)\n", naive,
      tends_to);
  EXPECT_NEAR(naive, tends_to, 0.01 * tends_to);
}

}  // namespace
}  // namespace tumble::physics
