#include "sim/stability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace tumble::sim {
namespace {

using physics::BodyModel;
using physics::BodyState;
using physics::Integrator;
using physics::Quat;
using physics::Vec3;

TEST(StabilityLimit, MatchesTheLinearTestEquation) {
  const LinearMode decay{.damping_rate = 300.0};
  EXPECT_NEAR(*stability_limit(Integrator::euler, decay) * 300.0, 2.0, 1e-12);
  EXPECT_NEAR(*stability_limit(Integrator::symplectic_euler, decay) * 300.0, 2.0, 1e-12);
  // The real root of 1 + z + z²/2 + z³/6 + z⁴/24 = -1.
  EXPECT_NEAR(*stability_limit(Integrator::rk4, decay) * 300.0, 2.785293563405, 1e-9);

  const LinearMode oscillator{.frequency = 10.0};
  EXPECT_EQ(*stability_limit(Integrator::euler, oscillator), 0.0);  // |1 + iωh| > 1 always
  EXPECT_NEAR(*stability_limit(Integrator::symplectic_euler, oscillator) * 10.0, 2.0, 1e-12);
  EXPECT_NEAR(*stability_limit(Integrator::rk4, oscillator) * 10.0, 2.0 * std::sqrt(2.0), 1e-9);

  // Damping lets explicit Euler through: |1 + hλ| <= 1 for h <= 2ζ/ω_n = k/ω_n².
  const LinearMode damped{.damping_rate = 2.0, .frequency = 10.0};
  EXPECT_NEAR(*stability_limit(Integrator::euler, damped), 2.0 / 100.0, 1e-12);

  EXPECT_EQ(*stability_limit(Integrator::rk4, LinearMode{}), HUGE_VAL);  // nothing stiff
  if (const auto splitting = physics::integrator_from_name("splitting")) {
    EXPECT_EQ(*stability_limit(*splitting, decay), HUGE_VAL);  // damping applied exactly
  }
}

// The model's limits are the integrators' own: a step 2% inside keeps every mode bounded and
// 2% outside makes it grow, for the physics code in src/physics/integrators.cpp and every
// integrator the model knows (the splitting methods too, when they are built).
struct LimitCase {
  std::string name;
  BodyModel model;
  BodyState start;
  LinearMode mode;
};

std::vector<LimitCase> limit_cases() {
  const physics::BodyConstants cube = physics::cube_constants(2.0, 1.0);
  const physics::BodyConstants box = physics::box_constants(1.0, Vec3(0.3, 1.0, 2.0));
  const double box_smallest = box.inertia.minCoeff();  // about body z
  return {
      {"linear damping",
       {.constants = cube, .forces = {physics::LinearDamping{.coefficient = 600.0}}},
       physics::make_state(cube, Vec3::Zero(), Vec3(2, 1, -1), Quat::Identity(), Vec3::Zero()),
       {.damping_rate = 300.0}},
      {"angular damping about the box's smallest moment",
       {.constants = box, .forces = {physics::AngularDamping{.coefficient = 30.0 * box_smallest}}},
       physics::make_state(box, Vec3::Zero(), Vec3::Zero(), Quat::Identity(), Vec3(0, 0, 5)),
       {.damping_rate = 30.0}},
      {"spring at the centre",
       {.constants = cube, .forces = {physics::Spring{.anchor = Vec3::Zero(), .stiffness = 200.0}}},
       physics::make_state(cube, Vec3(0.5, 0, 0), Vec3(0, 1, 0), Quat::Identity(), Vec3::Zero()),
       {.frequency = 10.0}},
      // Moving along the spring only, so that its damping, which resists stretching alone, acts
      // on the whole velocity: y'' = -100 y - 30 y'.
      {"damped spring at the centre",
       {.constants = cube,
        .forces = {physics::Spring{.anchor = Vec3::Zero(), .stiffness = 200.0, .damping = 60.0}}},
       physics::make_state(cube, Vec3(0.5, 0, 0), Vec3(1, 0, 0), Quat::Identity(), Vec3::Zero()),
       {.damping_rate = 30.0, .frequency = 10.0}},
  };
}

double size_of(const BodyState& s) {
  return s.position().norm() + s.momentum().norm() + s.angular_momentum().norm();
}

TEST(StabilityLimit, IsWhereTheIntegratorsThemselvesTurnUnstable) {
  for (const LimitCase& c : limit_cases()) {
    for (const Integrator integrator : physics::kAllIntegrators) {
      const std::optional<double> limit = stability_limit(integrator, c.mode);
      if (!limit || !std::isfinite(*limit) || *limit == 0.0) continue;
      const auto growth = [&](double dt) {
        BodyState state = c.start;
        for (int n = 0; n < 500; ++n) state = physics::step(integrator, c.model, state, n * dt, dt);
        return size_of(state) / size_of(c.start);
      };
      SCOPED_TRACE(c.name + ", " + std::string(physics::integrator_name(integrator)));
      EXPECT_LT(growth(0.98 * *limit), 20.0);
      EXPECT_GT(growth(1.02 * *limit), 1e3);
    }
  }
}

BodyModel stiff_decay() {
  return {.constants = physics::cube_constants(2.0, 1.0),
          .forces = {physics::LinearDamping{.coefficient = 600.0}}};  // k = 300 /s
}

BodyState at_rest(const BodyModel& model) {
  return physics::make_state(model.constants, Vec3::Zero(), Vec3::Zero(), Quat::Identity(),
                             Vec3::Zero());
}

// No warning at 1.99 / k, one at 2.01 / k with a step inside the limit that then passes.
void expect_warns_exactly_beyond(const BodyModel& model, const BodyState& start,
                                 Integrator integrator, double limit_times_rate, double rate,
                                 const std::string& cause) {
  SCOPED_TRACE(std::string(physics::integrator_name(integrator)) + ": " + cause);
  EXPECT_TRUE(check_step(model, start, integrator, (limit_times_rate - 0.01) / rate, 1.0).empty());
  const std::vector<StepWarning> warnings =
      check_step(model, start, integrator, (limit_times_rate + 0.01) / rate, 1.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find(cause), std::string::npos) << warnings[0].message;
  EXPECT_NE(warnings[0].message.find("blow up"), std::string::npos) << warnings[0].message;
  ASSERT_TRUE(warnings[0].suggested_dt.has_value());
  EXPECT_NEAR(*warnings[0].suggested_dt * rate, 0.8 * limit_times_rate, 1e-3);
  EXPECT_NE(warnings[0].message.find("use dt <= "), std::string::npos);
  EXPECT_TRUE(check_step(model, start, integrator, *warnings[0].suggested_dt, 1.0).empty());
}

TEST(CheckStep, WarnsExactlyBeyondTheDampingLimits) {
  const BodyModel model = stiff_decay();
  const BodyState start = at_rest(model);
  expect_warns_exactly_beyond(model, start, Integrator::euler, 2.0, 300.0, "c/m = 300 /s");
  expect_warns_exactly_beyond(model, start, Integrator::symplectic_euler, 2.0, 300.0,
                              "c/m = 300 /s");
  expect_warns_exactly_beyond(model, start, Integrator::rk4, 2.785, 300.0, "c/m = 300 /s");

  // Angular damping against the smallest principal moment, I_z = 1.09 / 12 kg m² here.
  const physics::BodyConstants box = physics::box_constants(1.0, Vec3(0.3, 1.0, 2.0));
  const BodyModel spun{.constants = box, .forces = {physics::AngularDamping{.coefficient = 9.0}}};
  const double rate = 9.0 / box.inertia.z();
  expect_warns_exactly_beyond(spun, at_rest(spun), Integrator::euler, 2.0, rate, "c/I_min");
  expect_warns_exactly_beyond(spun, at_rest(spun), Integrator::rk4, 2.785, rate, "c/I_min");
}

// A damping rate past double range (c = 1.7e308 N m s over I_min < 1) says nothing rather than
// something false: splitting damps exactly at any rate, and no step is 0 s.
TEST(CheckStep, ARateBeyondDoubleRangeGivesNoFalseWarning) {
  EXPECT_FALSE(stability_limit(Integrator::splitting, LinearMode{.damping_rate = INFINITY}));
  const physics::BodyConstants box = physics::box_constants(1.0, Vec3(0.3, 1.0, 2.0));
  const BodyModel spun{.constants = box,
                       .forces = {physics::AngularDamping{.coefficient = 1.7e308}}};
  EXPECT_TRUE(check_step(spun, at_rest(spun), Integrator::splitting, 0.01, 1.0).empty());
}

TEST(CheckStep, WarnsExactlyBeyondTheSpringLimit) {
  const physics::BodyConstants cube = physics::cube_constants(2.0, 1.0);
  const BodyModel model{.constants = cube,
                        .forces = {physics::Spring{.anchor = Vec3(0, 1, 0), .stiffness = 200.0}}};
  expect_warns_exactly_beyond(model, at_rest(model), Integrator::symplectic_euler, 2.0, 10.0,
                              "ω_n = 10 rad/s");
  expect_warns_exactly_beyond(model, at_rest(model), Integrator::rk4, 2.828, 10.0, "ω_n = 10");

  // An attachment at a corner: ω_n² = k (1/m + |r|²/I_min) = 200 (0.5 + 0.75 / (1/3)) = 550.
  const BodyModel cornered{
      .constants = cube,
      .forces = {physics::Spring{.attachment = Vec3(0.5, 0.5, 0.5), .stiffness = 200.0}}};
  expect_warns_exactly_beyond(cornered, at_rest(cornered), Integrator::symplectic_euler, 2.0,
                              std::sqrt(550.0), "ω_n = 23.45 rad/s");
}

// A drag is a spring like any other to the advisor: its modes come from stiffness, damping and
// attachment, not from where the anchor is or when it acts.
TEST(CheckStep, WarnsExactlyBeyondTheLimitOfAMovingTimedSpring) {
  const physics::BodyConstants cube = physics::cube_constants(2.0, 1.0);
  const BodyModel model{
      .constants = cube,
      .forces = {physics::Spring{.anchor_keys = {{.time = 0.0, .anchor = Vec3(0, 1, 0)},
                                                 {.time = 1.5, .anchor = Vec3(3, 2, 0)}},
                                 .stiffness = 200.0,
                                 .start = 0.5,
                                 .end = 1.0}}};
  expect_warns_exactly_beyond(model, at_rest(model), Integrator::symplectic_euler, 2.0, 10.0,
                              "ω_n = 10 rad/s");
  expect_warns_exactly_beyond(model, at_rest(model), Integrator::rk4, 2.828, 10.0, "ω_n = 10");
  // Critically damped (c = 2 sqrt(k m) = 40 N s/m: k = c/m = 20 /s): damped like the fixed one.
  BodyModel damped = model;
  std::get<physics::Spring>(damped.forces.front()).damping = 40.0;
  BodyModel fixed = damped;
  std::get<physics::Spring>(fixed.forces.front()).anchor_keys = {};
  for (const Integrator integrator : physics::kAllIntegrators) {
    for (const double dt : {0.01, 0.1, 0.3}) {
      const std::vector<StepWarning> moving =
          check_step(damped, at_rest(damped), integrator, dt, 2.0);
      const std::vector<StepWarning> still = check_step(fixed, at_rest(fixed), integrator, dt, 2.0);
      ASSERT_EQ(moving.size(), still.size()) << physics::integrator_name(integrator) << " " << dt;
      for (std::size_t i = 0; i < moving.size(); ++i)
        EXPECT_EQ(moving[i].message, still[i].message);
    }
  }
  EXPECT_FALSE(check_step(damped, at_rest(damped), Integrator::rk4, 0.3, 2.0).empty());
}

TEST(CheckStep, ExplicitEulerOnAnUndampedSpringIsUnstableAtAnyStep) {
  const BodyModel model{.constants = physics::cube_constants(1.0, 1.0),
                        .forces = {physics::Spring{.stiffness = 1.0}}};
  const std::vector<StepWarning> warnings =
      check_step(model, at_rest(model), Integrator::euler, 1e-4, 1.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("at any dt"), std::string::npos) << warnings[0].message;
  EXPECT_FALSE(warnings[0].suggested_dt.has_value());
  ASSERT_TRUE(warnings[0].suggested_integrator.has_value());
  EXPECT_NE(*warnings[0].suggested_integrator, Integrator::euler);
  EXPECT_TRUE(
      check_step(model, at_rest(model), *warnings[0].suggested_integrator, 1e-4, 1.0).empty());
}

// 10 rad/s at dt = 0.049 s turns 0.49 rad per step: fine; at 0.051 s, 0.51 rad: a warning.
TEST(CheckStep, WarnsWhenTheBodyTurnsMoreThanHalfARadianPerStep) {
  const physics::BodyConstants cube = physics::cube_constants(1.0, 1.0);
  const BodyModel model{.constants = cube, .forces = {}};
  const BodyState spinning =
      physics::make_state(cube, Vec3::Zero(), Vec3::Zero(), Quat::Identity(), Vec3(0, 0, 10));
  for (const Integrator integrator :
       {Integrator::euler, Integrator::symplectic_euler, Integrator::rk4}) {
    EXPECT_TRUE(check_step(model, spinning, integrator, 0.049, 1.0).empty());
    const std::vector<StepWarning> warnings = check_step(model, spinning, integrator, 0.051, 1.0);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].message.find("0.51 rad per step"), std::string::npos)
        << warnings[0].message;
    EXPECT_NE(warnings[0].message.find("inaccurately"), std::string::npos);
    ASSERT_TRUE(warnings[0].suggested_dt.has_value());
    EXPECT_NEAR(*warnings[0].suggested_dt, 0.8 * 0.05, 1e-12);
    EXPECT_EQ(warnings[0].suggested_integrator, physics::integrator_from_name("splitting"));
  }
}

// A constant torque spins the body up: 1 N m on I = 1/6 kg m² for 2 s reaches 12 rad/s, and
// against angular damping 0.1 N m s it tends to τ/c = 10 rad/s.
TEST(CheckStep, ExpectsTheSpinATorqueBuildsUp) {
  const physics::BodyConstants cube = physics::cube_constants(1.0, 1.0);
  const BodyModel driven{.constants = cube,
                         .forces = {physics::ConstantTorque{.torque = Vec3(1, 0, 0)}}};
  EXPECT_TRUE(check_step(driven, at_rest(driven), Integrator::rk4, 0.5 / 12.5, 2.0).empty());
  EXPECT_EQ(check_step(driven, at_rest(driven), Integrator::rk4, 0.5 / 11.5, 2.0).size(), 1u);

  BodyModel damped = driven;
  damped.forces.push_back(physics::AngularDamping{.coefficient = 0.1});
  EXPECT_TRUE(check_step(damped, at_rest(damped), Integrator::rk4, 0.5 / 10.5, 100.0).empty());
  EXPECT_EQ(check_step(damped, at_rest(damped), Integrator::rk4, 0.5 / 9.5, 100.0).size(), 1u);
}

}  // namespace
}  // namespace tumble::sim
