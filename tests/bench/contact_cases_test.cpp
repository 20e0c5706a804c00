// The contact cases' measures against motions whose answer is known, and the cases run through
// the world step against their closed forms.
#include "bench/contact_cases.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <utility>

#include <cmath>
#include <string>
#include <vector>

#include "bench/accuracy.hpp"
#include "sim/stability.hpp"

namespace tumble::bench {
namespace {

using physics::BodyState;
using physics::ContactMethod;
using physics::Integrator;
using physics::Quat;
using physics::Vec3;

constexpr double kG = 9.81;  // m/s²
const TimingSettings kUntimed{.samples = 1, .min_sample_seconds = 0.0};

BodyState cube_at(const ContactCase& c, const Vec3& position, const Vec3& velocity) {
  return physics::make_state(c.model.constants, position, velocity, Quat::Identity(), Vec3::Zero());
}

// A rebound at 2.2 m/s sampled every 0.1 s: the highest sample is 1.2 cm below the true apex
// v²/(2g) = 0.2467 m, the parabola through the three highest has it to rounding.
TEST(ContactCases, TheBounceApexIsTheVertexOfTheSampledFlight) {
  const ContactCase& c = *find_contact_case("bounce");
  const double dt = 0.1, rise = 2.2;
  std::vector<BodyState> states = {c.initial, cube_at(c, Vec3(0, 1.0, 0), Vec3(0, -4.4, 0))};
  for (int n = 0; n < 8; ++n) {
    const double t = 0.03 + n * dt;  // s since leaving the floor
    states.push_back(
        cube_at(c, Vec3(0, 0.5 + rise * t - 0.5 * kG * t * t, 0), Vec3(0, rise - kG * t, 0)));
  }
  const double apex = rise * rise / (2.0 * kG);
  EXPECT_NEAR(c.judge(states, dt).at(0), std::abs(apex - 0.25), 1e-12);
}

// Over the last second only: the cube sunk 1 mm and one step of 2 mm; before it, 5 cm deep.
TEST(ContactCases, RestMeasuresTheLastSecondsPenetrationAndCornerMotion) {
  const ContactCase& c = *find_contact_case("rest");
  const double dt = 0.25;
  std::vector<BodyState> states = {c.initial, cube_at(c, Vec3(0, 0.45, 0), Vec3::Zero())};
  for (int n = 0; n < 5; ++n) {  // the last four steps are the last second
    states.push_back(cube_at(c, Vec3(n == 4 ? 2e-3 : 0.0, 0.499, 0), Vec3::Zero()));
  }
  const std::vector<double> errors = c.judge(states, dt);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NEAR(errors[0], 1e-3, 1e-12);
  EXPECT_NEAR(errors[1], 2e-3, 1e-12);
}

// Impulse contact with RK4 at dt = 1/60: the bounce is resolved at its time of impact, so the
// apex is e² h₀ to rounding (measured 2e-11 m); the slide stops within 1e-4 m of v₀²/(2μg)
// (measured 9e-5 m: the stop falls inside a step); the tumbling cube lies still on the floor.
TEST(ContactCases, ImpulseContactWithRk4MeetsTheClosedForms) {
  const auto run = [](const std::string& name) {
    return measure_contact_accuracy(*find_contact_case(name), ContactMethod::impulse,
                                    Integrator::rk4, 1.0 / 60, kUntimed);
  };
  const AccuracyRow bounce = run("bounce");
  EXPECT_EQ(bounce.contact, "impulse");
  EXPECT_EQ(bounce.measure, "apex_error_m");
  ASSERT_FALSE(bounce.blew_up);
  EXPECT_LT(bounce.error, 1e-9);
  EXPECT_TRUE(std::isnan(bounce.position_error));  // contact cases do not measure it

  const AccuracyRow slide = run("slide");
  ASSERT_FALSE(slide.blew_up);
  EXPECT_LT(slide.error, 1e-4);

  const AccuracyRow rest = run("rest");
  ASSERT_FALSE(rest.blew_up);
  EXPECT_EQ(rest.second_measure, "corner_motion_m");
  EXPECT_LT(rest.error, 1e-9);
  EXPECT_LT(rest.second_error, 1e-9);
}

// A ball rolls down 30° at 5/7 g sin θ, and a cylinder lying across it at 2/3 g sin θ, with their
// contact points still. With rk4 the ball's distance is the closed form to rounding (measured
// 1.5e-14 m) at any step; the cylinder's is within 1e-6 m, first order in dt (2.0e-7 m at 1/30,
// 1.0e-7 at 1/60, its slip 4.7e-8 and 2.3e-8 m/s): its points are on its rim, fixed in the body
// through a step while it turns, where the ball's is its centre's. Euler's is first order in dt
// (0.117 m at 1/30, 0.0584 at 1/60 for the ball). They run with impulse contact only.
TEST(ContactCases, RoundBodiesRollDownTheSlopeWithRk4AndFirstOrderWithEuler) {
  for (const auto& [name, tolerance] :
       {std::pair<const char*, double>{"roll", 1e-9}, {"roll_cylinder", 1e-6}}) {
    SCOPED_TRACE(name);
    const ContactCase& roll = *find_contact_case(name);
    EXPECT_EQ(roll.methods, std::vector<ContactMethod>{ContactMethod::impulse});
    for (const double dt : {1.0 / 30, 1.0 / 60}) {
      const AccuracyRow rk4 =
          measure_contact_accuracy(roll, ContactMethod::impulse, Integrator::rk4, dt, kUntimed);
      ASSERT_FALSE(rk4.blew_up);
      EXPECT_EQ(rk4.measure, "roll_distance_error_m");
      std::printf("[ measured ] %s, rk4, dt %.4f: %.1e m, slip %.1e m/s\n", name, dt, rk4.error,
                  rk4.second_error);
      EXPECT_LT(rk4.error, tolerance);
      EXPECT_LT(rk4.second_error, tolerance);  // m/s of slip
    }
    const AccuracyRow coarse = measure_contact_accuracy(roll, ContactMethod::impulse,
                                                        Integrator::euler, 1.0 / 30, kUntimed);
    const AccuracyRow fine = measure_contact_accuracy(roll, ContactMethod::impulse,
                                                      Integrator::euler, 1.0 / 60, kUntimed);
    EXPECT_NEAR(coarse.error / fine.error, 2.0, 0.05);
  }
}

// Wherever the stability advice says a penalty run is stable, the bench does not find it blown
// up; at 1/30, far beyond every limit (ω_n dt = 26 rocking), every integrator blows up, and its
// errors are NaN.
TEST(ContactCases, PenaltyRunsTheAdviceCallsStableDoNotBlowUp) {
  const ContactCase& c = *find_contact_case("bounce");
  const physics::BodyModel model =
      physics::with_penalty_contact(c.model, c.planes, c.penalty.stiffness, c.penalty.damping);
  int stable = 0;
  for (const Integrator integrator : physics::kAllIntegrators) {
    for (const double dt : kAccuracySteps) {
      SCOPED_TRACE(std::string(physics::integrator_name(integrator)) + " at " + std::to_string(dt));
      const AccuracyRow row =
          measure_contact_accuracy(c, ContactMethod::penalty, integrator, dt, kUntimed);
      if (sim::check_step(model, c.initial, integrator, dt, c.duration).empty()) {
        ++stable;
        EXPECT_FALSE(row.blew_up);
      }
      if (dt == kAccuracySteps[0]) {
        EXPECT_TRUE(row.blew_up);
        EXPECT_TRUE(std::isnan(row.error));
      }
    }
  }
  EXPECT_GT(stable, 0);
}

}  // namespace
}  // namespace tumble::bench
