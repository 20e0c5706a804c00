#include "bench/accuracy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <set>
#include <string>
#include <vector>

namespace tumble::bench {
namespace {

using physics::Integrator;

const TimingSettings kUntimed{.samples = 1, .min_sample_seconds = 0.0};

TEST(Accuracy, ABlownUpRunIsFlaggedWithNoErrorsAndTimedOverTheStepsTaken) {
  // k dt = 300 / 30 = 10: explicit Euler multiplies the momentum by -9 every step.
  const AccuracyRow row = measure_accuracy(*find_hard_case("stiff_linear_damping"),
                                           Integrator::euler, 1.0 / 30, kUntimed);
  EXPECT_EQ(row.case_name, "stiff_linear_damping");
  EXPECT_EQ(row.integrator, "euler");
  EXPECT_EQ(row.steps, 30);
  EXPECT_TRUE(row.blew_up);
  EXPECT_TRUE(std::isnan(row.orientation_error));
  EXPECT_TRUE(std::isnan(row.position_error));
  EXPECT_TRUE(std::isnan(row.angular_momentum_error));
  EXPECT_TRUE(std::isnan(row.energy_error));
  EXPECT_GT(row.ns_per_step, 0.0);
}

// Inside its limit (k dt = 1.25) explicit Euler's momenta form a geometric series whose sum,
// h Σ (1 - k h)^n v0 = v0 / k, is exactly the true distance coasted: only rounding is left.
// Semi-implicit Euler drifts with the new velocity and comes up short by v0 h, 0.0102 m.
TEST(Accuracy, ErrorsOfAStableStiffDecayAreTheOnesTheoryGives) {
  const HardCase& c = *find_hard_case("stiff_linear_damping");
  const double dt = 1.0 / 240;
  const AccuracyRow euler = measure_accuracy(c, Integrator::euler, dt, kUntimed);
  ASSERT_FALSE(euler.blew_up);
  EXPECT_LT(euler.position_error, 1e-14);
  const AccuracyRow symplectic = measure_accuracy(c, Integrator::symplectic_euler, dt, kUntimed);
  ASSERT_FALSE(symplectic.blew_up);
  const double coasting_speed = c.initial.velocity().norm();
  EXPECT_NEAR(symplectic.position_error, coasting_speed * dt, 1e-6);
  EXPECT_EQ(symplectic.orientation_error, 0.0);  // no spin, no turn
}

// Fiedler's cube with RK4 at dt = 1/60: the orientation error against the closed form after
// 183 rad (measured 2.43e-5 rad), L and the energy against it to rounding, and a cost per
// simulated second that is the cost per step times 60.
TEST(Accuracy, Rk4OnTheArticleCube) {
  const HardCase& c = *find_hard_case("article_cube");
  const AccuracyRow row =
      measure_accuracy(c, Integrator::rk4, 1.0 / 60, {.samples = 3, .min_sample_seconds = 0.001});
  ASSERT_FALSE(row.blew_up);
  EXPECT_EQ(row.steps, 1200);
  EXPECT_GT(row.orientation_error, 1e-5);
  EXPECT_LT(row.orientation_error, 5e-5);
  EXPECT_EQ(row.position_error, 0.0);  // no force: the cube never moves
  EXPECT_LT(row.angular_momentum_error, 1e-12);
  EXPECT_LT(row.energy_error, 1e-12);
  EXPECT_GT(row.ns_per_step, 0.0);
  EXPECT_DOUBLE_EQ(row.ns_per_simulated_second, row.ns_per_step * 60.0);
}

// The pendulum of 1 m from 90° (bench/joint_cases.cpp) under rk4 at 1/60 s keeps its period to
// 1e-4 of 4 √(L/g) K(sin 45°) and its rod to 1e-9 m; symplectic Euler, of order 1, misses the
// period by more than 1e-3 there.
TEST(Accuracy, TheJointPendulumKeepsItsPeriodUnderRk4) {
  const JointCase& c = *find_joint_case("pendulum");
  const AccuracyRow rk4 = measure_joint_accuracy(c, Integrator::rk4, 1.0 / 60,
                                                 {.samples = 1, .min_sample_seconds = 0.0});
  ASSERT_FALSE(rk4.blew_up);
  EXPECT_EQ(rk4.measure, "period_error");
  EXPECT_LT(rk4.error, 1e-4);
  EXPECT_LT(rk4.second_error, 1e-9);
  const AccuracyRow first = measure_joint_accuracy(c, Integrator::symplectic_euler, 1.0 / 60,
                                                   {.samples = 1, .min_sample_seconds = 0.0});
  EXPECT_GT(first.error, 1e-3);
}

TEST(Accuracy, TheQuickSweepCoversItsCasesIntegratorsAndStepsInOrder) {
  const AccuracySettings quick = quick_accuracy_settings();
  std::vector<std::string> started;
  const Result<std::vector<AccuracyRow>> measured =
      measure_accuracy(quick, [&](const std::string& run, Integrator) { started.push_back(run); });
  ASSERT_TRUE(measured) << measured.error();
  const std::vector<AccuracyRow>& rows = *measured;
  const std::size_t integrators = std::size(physics::kAllIntegrators);
  const std::size_t runs =
      (quick.cases.size() + 2 * quick.contact_cases.size() + quick.joint_cases.size()) *
      integrators;
  ASSERT_EQ(rows.size(), runs * quick.steps.size());
  ASSERT_EQ(started.size(), runs);
  std::size_t i = 0;
  const auto expect_rows = [&](const std::string& name, const std::string& contact) {
    for (const Integrator integrator : physics::kAllIntegrators) {
      EXPECT_EQ(started[i / quick.steps.size()], contact == "none" ? name
                                                 : contact == "joints"
                                                     ? name + " (joints)"
                                                     : name + " (" + contact + " contact)");
      for (const double dt : quick.steps) {
        EXPECT_EQ(rows[i].case_name, name);
        EXPECT_EQ(rows[i].contact, contact == "joints" ? "none" : contact);
        EXPECT_EQ(rows[i].integrator, physics::integrator_name(integrator));
        EXPECT_EQ(rows[i].dt, dt);
        EXPECT_FALSE(rows[i].measure.empty());
        ++i;
      }
    }
  };
  for (const std::string& name : quick.cases) expect_rows(name, "none");
  for (const std::string& name : quick.contact_cases) {
    expect_rows(name, "impulse");
    expect_rows(name, "penalty");
  }
  for (const std::string& name : quick.joint_cases) expect_rows(name, "joints");
  const Result<std::vector<AccuracyRow>> unknown = measure_accuracy({.cases = {"no_such_case"}});
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error(), "no hard case named no_such_case");
  const Result<std::vector<AccuracyRow>> unknown_contact =
      measure_accuracy({.contact_cases = {"no_such_case"}});
  ASSERT_FALSE(unknown_contact);
  EXPECT_EQ(unknown_contact.error(), "no contact case named no_such_case");
}

// A hard case's headline error is named and repeated in `error`.
TEST(Accuracy, AHardCaseNamesItsHeadlineError) {
  const AccuracyRow row = measure_accuracy(*find_hard_case("stiff_linear_damping"), Integrator::rk4,
                                           1.0 / 480, kUntimed);
  EXPECT_EQ(row.contact, "none");
  EXPECT_EQ(row.measure, "position_error_m");
  EXPECT_EQ(row.error, row.position_error);
  EXPECT_TRUE(row.second_measure.empty());
  EXPECT_TRUE(std::isnan(row.second_error));
}

}  // namespace
}  // namespace tumble::bench
