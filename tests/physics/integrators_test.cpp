#include "physics/integrators.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>

#include "support/closed_forms.hpp"

namespace tumble::physics {
namespace {

using testing::ArticleCube;
using testing::DampedSpinUp;
using testing::SpinningProjectile;

BodyState run(Integrator integrator, const BodyModel& model, BodyState state, double duration,
              int steps) {
  const double dt = duration / steps;
  for (int n = 0; n < steps; ++n) state = step(integrator, model, state, n * dt, dt);
  return state;
}

// A box hanging from a corner on a damped spring under gravity, released with a twist: every
// coupling between translation and rotation is active and the motion is smooth.
struct BoxOnSpring {
  BodyModel model{.constants = box_constants(1.0, Vec3(0.5, 1.0, 1.5)),
                  .forces = {Gravity{}, Spring{.anchor = Vec3(0, 2, 0),
                                               .attachment = Vec3(0.25, 0.5, 0.75),
                                               .stiffness = 40.0,
                                               .damping = 0.5,
                                               .rest_length = 1.0}}};
  BodyState start = make_state(model.constants, Vec3(0.3, 0, 0.2), Vec3(0, 0, 0.5),
                               Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ())), Vec3(0.5, 1.0, -0.3));
};

TEST(Integrators, NamesRoundTrip) {
  for (const Integrator integrator : kAllIntegrators) {
    EXPECT_EQ(integrator_from_name(integrator_name(integrator)), integrator);
  }
  EXPECT_FALSE(integrator_from_name("rk5").has_value());
}

// Fiedler's example at the article's dt = 0.01 for 20 s, against the closed form.
TEST(Integrators, Rk4FollowsTheArticleCubeClosedForm) {
  const ArticleCube cube;
  const BodyState end = run(Integrator::rk4, cube.model, cube.start, 20.0, 2000);
  EXPECT_NEAR(end.angular_velocity().x(), cube.exact.angular_velocity(20.0), 1e-9);
  EXPECT_NEAR(end.angular_velocity().y(), 0.0, 1e-15);
  EXPECT_NEAR(end.angular_velocity().z(), 0.0, 1e-15);
  // Measured 3.2e-6 rad after turning through 183 rad.
  EXPECT_LT(angle_between(end.orientation(), cube.exact.orientation(20.0)), 5e-6);
  EXPECT_EQ(end.position(), Vec3::Zero());
}

TEST(Integrators, Rk4FollowsASpinningProjectile) {
  const SpinningProjectile exact;
  const BodyModel model{.constants = cube_constants(1.0, 1.0),
                        .forces = {Gravity{.acceleration = exact.gravity}}};
  const BodyState start = make_state(model.constants, exact.position, exact.velocity,
                                     exact.orientation, exact.angular_velocity);
  const BodyState end = run(Integrator::rk4, model, start, 2.0, 120);
  // A parabola is integrated exactly by RK4; only round-off remains.
  EXPECT_LT((end.position() - exact.position_at(2.0)).norm(), 1e-12);
  EXPECT_LT((end.velocity() - exact.velocity_at(2.0)).norm(), 1e-12);
  EXPECT_LT((end.angular_velocity() - exact.angular_velocity).norm(), 1e-12);
  EXPECT_LT(angle_between(end.orientation(), exact.orientation_at(2.0)), 1e-5);
}

// Measured order from three step sizes, each half the one before: log2(e(h) / e(h/2)).
struct ConvergenceCase {
  Integrator integrator;
  int coarsest_steps;  // over the case's duration; chosen inside the asymptotic range
  double expected_order;
};

// Names the case in test listings (GoogleTest would print its bytes).
std::ostream& operator<<(std::ostream& out, const ConvergenceCase& c) {
  return out << integrator_name(c.integrator);
}

void expect_order(const ConvergenceCase& c, const std::function<double(int)>& error_at) {
  const double e1 = error_at(c.coarsest_steps);
  const double e2 = error_at(2 * c.coarsest_steps);
  const double e3 = error_at(4 * c.coarsest_steps);
  const double order12 = std::log2(e1 / e2);
  const double order23 = std::log2(e2 / e3);
  ::testing::Message trace;
  trace << integrator_name(c.integrator) << " errors " << e1 << ", " << e2 << ", " << e3;
  trace << "; orders " << order12 << ", " << order23;
  SCOPED_TRACE(trace);
  std::cout << "[ measured ] " << trace << '\n';
  EXPECT_NEAR(order12, c.expected_order, 0.3);
  EXPECT_NEAR(order23, c.expected_order, 0.3);
}

class ConvergenceOrder : public ::testing::TestWithParam<ConvergenceCase> {};

TEST_P(ConvergenceOrder, OnTheArticleCubeAgainstItsClosedForm) {
  const ArticleCube cube;
  const double duration = 2.0;
  expect_order(GetParam(), [&](int steps) {
    const BodyState end = run(GetParam().integrator, cube.model, cube.start, duration, steps);
    return angle_between(end.orientation(), cube.exact.orientation(duration)) +
           std::abs(end.angular_velocity().x() - cube.exact.angular_velocity(duration));
  });
}

TEST_P(ConvergenceOrder, OnABoxOnASpringAgainstAFineReference) {
  const BoxOnSpring box;
  const double duration = 1.0;
  // RK4 with 64× more steps than the finest RK4 run measured (error ~ 6e-7 / 64⁴ ≈ 4e-14).
  static const BodyState reference = run(Integrator::rk4, box.model, box.start, duration, 12800);
  expect_order(GetParam(), [&](int steps) {
    const BodyState end = run(GetParam().integrator, box.model, box.start, duration, steps);
    return (end.position() - reference.position()).norm() +
           angle_between(end.orientation(), reference.orientation());
  });
}

INSTANTIATE_TEST_SUITE_P(Integrators, ConvergenceOrder,
                         ::testing::Values(ConvergenceCase{Integrator::euler, 400, 1.0},
                                           ConvergenceCase{Integrator::symplectic_euler, 400, 1.0},
                                           ConvergenceCase{Integrator::rk4, 50, 4.0}),
                         [](const auto& info) {
                           return std::string(integrator_name(info.param.integrator));
                         });

// With no forces, momentum and angular momentum are constants of every method.
TEST(Integrators, TorqueFreeMotionKeepsMomenta) {
  const BoxOnSpring box;
  const BodyModel free{.constants = box.model.constants, .forces = {}};
  for (const Integrator integrator : kAllIntegrators) {
    const BodyState end = run(integrator, free, box.start, 1.0, 100);
    EXPECT_EQ(end.momentum(), box.start.momentum()) << integrator_name(integrator);
    EXPECT_EQ(end.angular_momentum(), box.start.angular_momentum()) << integrator_name(integrator);
    EXPECT_NEAR(end.orientation().norm(), 1.0, 1e-15) << integrator_name(integrator);
  }
}

}  // namespace
}  // namespace tumble::physics
