// The restitution of a flat landing under penalty contact, against the law itself run by RK4 at
// a step far finer than the contact, and the damping chosen for a wanted restitution.
#include "sim/penalty_modes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "physics/integrators.hpp"

namespace tumble::sim {
namespace {

using physics::BodyModel;
using physics::BodyState;
using physics::Quat;
using physics::Vec3;

TEST(PenaltyRestitution, IsOneUndampedEToTheMinusTwoAtCriticalAndContinuousThere) {
  EXPECT_EQ(penalty_restitution(0.0), 1.0);
  EXPECT_DOUBLE_EQ(penalty_restitution(1.0), std::exp(-2.0));
  EXPECT_NEAR(penalty_restitution(1.0 - 1e-7), std::exp(-2.0), 1e-6);
  EXPECT_NEAR(penalty_restitution(1.0 + 1e-7), std::exp(-2.0), 1e-6);
  // Far overdamped it falls as 1/(4ζ²) (2 ζ acosh ζ / sqrt(ζ² - 1) -> 2 ln 2ζ).
  EXPECT_NEAR(penalty_restitution(1e4) * 4e8, 1.0, 1e-3);
}

// The speed a flat landing leaves with, over the speed it came in with: a 1 kg unit cube at
// 1 m/s onto a floor with no gravity, RK4 at 0.2 µs (the contact lasts 2 to 5 ms here). The
// damping force jumps from 0 to c v at the touch, which costs the step across it O(c dt / m):
// 3e-5 at 1 µs, measured.
double measured_restitution(double stiffness, double damping) {
  BodyModel model{.constants = physics::cube_constants(1.0, 1.0), .forces = {}};
  model.forces.push_back(physics::PenaltyContact{
      .planes = {physics::Plane{}}, .stiffness = stiffness, .damping = damping});
  BodyState state = physics::make_state(model.constants, Vec3(0, 0.5, 0), Vec3(0, -1, 0),
                                        Quat::Identity(), Vec3::Zero());
  constexpr double kStep = 2e-7;
  for (int n = 0; state.position().y() <= 0.5 && n < 10000000; ++n) {
    state = physics::step(physics::Integrator::rk4, model, state, n * kStep, kStep);
  }
  return state.velocity().y();
}

// ζ = c / sqrt(k m) for four corners (4c over 2 sqrt(4k m)), and the law that only pushes lets
// the box go early: the restitution is above the linear spring's exp(-ζπ / sqrt(1 - ζ²)).
TEST(PenaltyRestitution, IsTheFlatLandingsOwn) {
  const double stiffness = 1e5, mass = 1.0;
  for (const double zeta : {0.1, 0.2154, 0.5, 0.9, 1.5, 3.0}) {
    const double damping = zeta * std::sqrt(stiffness * mass);
    const double measured = measured_restitution(stiffness, damping);
    const double linear_spring =
        zeta < 1.0 ? std::exp(-zeta * std::numbers::pi / std::sqrt(1.0 - zeta * zeta)) : 0.0;
    std::printf(
        "[ measured ] ζ = %.4g: restitution %.6f, closed form %.6f (linear spring's %.6f)\n", zeta,
        measured, penalty_restitution(zeta), linear_spring);
    EXPECT_NEAR(measured, penalty_restitution(zeta), 1e-5) << "ζ = " << zeta;
    EXPECT_GT(measured, linear_spring + 0.01);
  }
}

TEST(PenaltyRestitution, TheDampingForARestitutionGivesIt) {
  for (const double e : {0.9, 0.5, 0.3, std::exp(-2.0), 0.05}) {
    const double damping = penalty_damping_for_restitution(e, 1e5, 2.0);
    EXPECT_NEAR(penalty_restitution(damping / std::sqrt(1e5 * 2.0)), e, 1e-12) << e;
  }
}

}  // namespace
}  // namespace tumble::sim
