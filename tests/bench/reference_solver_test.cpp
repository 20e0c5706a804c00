// The long-double twin of the force laws (bench/reference_solver.cpp), on a law the hard cases do
// not exercise: a spring whose anchor moves, damped relative to the anchor, acting for a while.
#include "bench/reference_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "support/closed_forms.hpp"

namespace tumble::bench {
namespace {

using physics::Vec3;

// Fiedler's drag against its closed form (support/closed_forms.hpp), through both kinks of the
// anchor's path. RKF 7(8) at 1e-12 per step, integrated piece by piece between the keys: measured
// within 1e-14 m and 2e-13 kg m/s (stepping across the kinks, 7e-8 m; without the anchor's
// velocity in the damper, 9 mm).
TEST(ReferenceSolver, FollowsTheDraggedBodysClosedForm) {
  const testing::CriticallyDampedDrag drag;
  for (const double t : {0.2, 0.3, 1.0, 2.25, 2.3, 3.0}) {
    SCOPED_TRACE(t);
    const FinalState end = solve_reference(drag.model(), drag.at_rest(), t, 1e-12);
    EXPECT_NEAR(end.position.x(), drag.position_at(t), 1e-12);
    EXPECT_NEAR(end.momentum.x(), drag.mass * drag.velocity_at(t), 1e-12);
    EXPECT_EQ(end.position.tail<2>(), Eigen::Vector2d::Zero());
  }
}

// The spring pulls only while start <= t < end: the body rests until start, then the critically
// damped spring, 1 m stretched, pulls it for one time constant 1/ω, from which
// x = 1 − (1 + ωτ) e^{−ωτ} and v = ω² τ e^{−ωτ}; then it lets go and the body flies on (measured
// within 7e-13 m and 5e-13 kg m/s).
TEST(ReferenceSolver, SpringActsOnlyFromStartUntilEnd) {
  const testing::CriticallyDampedDrag drag;
  physics::BodyModel model = drag.model();
  auto& spring = std::get<physics::Spring>(model.forces.front());
  spring.anchor_keys = {};
  spring.anchor = Vec3(1, 0, 0);
  spring.start = 0.5;
  spring.end = 0.5 + 1.0 / drag.frequency;
  const FinalState before = solve_reference(model, drag.at_rest(), 0.5, 1e-12);
  EXPECT_EQ(before.momentum, Vec3::Zero());
  EXPECT_EQ(before.position, Vec3::Zero());
  const double speed = drag.frequency * std::exp(-1.0);   // ω² τ e^{−ωτ} at τ = 1/ω (m/s)
  const double released_at = 1.0 - 2.0 * std::exp(-1.0);  // m
  const FinalState released = solve_reference(model, drag.at_rest(), spring.end, 1e-12);
  EXPECT_NEAR(released.momentum.x(), drag.mass * speed, 5e-12);
  EXPECT_NEAR(released.position.x(), released_at, 5e-12);
  const FinalState later = solve_reference(model, drag.at_rest(), 2.0, 1e-12);
  EXPECT_NEAR(later.momentum.x(), drag.mass * speed, 5e-12);
  EXPECT_NEAR(later.position.x(), released_at + speed * (2.0 - spring.end), 5e-12);
}

}  // namespace
}  // namespace tumble::bench
