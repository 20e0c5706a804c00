#include "sim/stability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "physics/contact.hpp"

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

// ---- Penalty contact: the advisor's limits against the integrators' own ------------------------

constexpr double kG = 9.81;  // m/s²

// A 1 kg box of edge lengths `size` (m) on a floor at y = 0 under gravity, with penalty contact
// of stiffness k and damping c per corner (N/m, N s/m) and friction μ for both box and floor.
BodyModel penalty_box(const Vec3& size, double stiffness, double damping, double friction) {
  const physics::Material material{.restitution = 0.0, .friction = friction};
  BodyModel model{.constants = physics::box_constants(1.0, size),
                  .forces = {physics::Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
                  .shape = physics::box_shape(0.5 * size),
                  .material = material};
  return physics::with_penalty_contact(model, {physics::Plane{.material = material}}, stiffness,
                                       damping);
}

// Each corner's share of the weight sinks it by m g / (4k) at rest (m).
double rest_depth(const BodyModel& model) {
  const auto& law = std::get<physics::PenaltyContact>(model.forces.back());
  return model.constants.mass * kG / (4.0 * law.stiffness);
}

// The height of the centre (m) at which the box, turned by `orientation`, rests on its lowest
// face: that face's corners sunk by rest_depth.
double rest_height(const BodyModel& model, const Quat& orientation) {
  double lowest = 0.0;  // of a corner relative to the centre (m)
  for (int feature = 0; feature < 8; ++feature) {
    lowest = std::min(lowest, (orientation * physics::corner(model.shape.half_size, feature)).y());
  }
  return -lowest - rest_depth(model);
}

// Lowered from 1 µm above its rest height and left to settle by RK4 at a step far inside every
// limit (ω_n dt <= 0.01), for 30 times the bounce's decay time 2m/(4c), the slowest of its modes.
BodyState settled(const BodyModel& model, const Quat& orientation = Quat::Identity()) {
  const auto& law = std::get<physics::PenaltyContact>(model.forces.back());
  const double step = 0.01 / std::sqrt(4.0 * law.stiffness / model.constants.mass);  // s
  const double duration = 60.0 * model.constants.mass / (4.0 * law.damping);         // s
  BodyState state =
      physics::make_state(model.constants, Vec3(0, rest_height(model, orientation) + 1e-6, 0),
                          Vec3::Zero(), orientation, Vec3::Zero());
  for (int n = 0; n * step < duration; ++n) {
    state = physics::step(Integrator::rk4, model, state, n * step, step);
  }
  EXPECT_NEAR(state.position().y(), rest_height(model, orientation), 1e-12);
  EXPECT_LT(state.velocity().norm(), 1e-9);
  return state;
}

// The energy of the departure from rest (J): kinetic, plus ½ k (d - d_rest)² for each corner in
// contact — the linearised system's energy, gravity's first-order part cancelling the springs'.
double departure_energy(const BodyModel& model, const BodyState& state) {
  const auto& law = std::get<physics::PenaltyContact>(model.forces.back());
  double energy = physics::kinetic_energy(state);
  for (int feature = 0; feature < 8; ++feature) {
    const double depth =
        -physics::body_point_to_world(state, physics::corner(law.half_size, feature)).y();
    if (depth > 0.0) energy += 0.5 * law.stiffness * std::pow(depth - rest_depth(model), 2);
  }
  return energy;
}

// Whether a departure from rest grows under `integrator` at `dt`: the largest energy of the last
// 50 of 4000 steps against that of the first 5 (a step's transient), or a millionfold growth at
// any step (an amplitude 1e3 × the start, still far inside the sink, where the run stops: the
// system stays linear throughout).
bool grows(Integrator integrator, const BodyModel& model, const BodyState& start, double dt) {
  constexpr int kSteps = 4000, kFirst = 5, kLast = 50;
  const double start_energy = departure_energy(model, start);
  BodyState state = start;
  double first = start_energy, last = 0.0;
  for (int n = 0; n < kSteps; ++n) {
    state = physics::step(integrator, model, state, n * dt, dt);
    const double energy = departure_energy(model, state);
    if (!(energy <= 1e6 * start_energy)) return true;
    if (n < kFirst) first = std::max(first, energy);
    if (n >= kSteps - kLast) last = std::max(last, energy);
  }
  return !(last <= 10.0 * first);
}

// The step (s) where growth sets in, by bisection in log dt between a step that does not grow
// and one that does, to 0.2%.
double measured_limit(Integrator integrator, const BodyModel& model, const BodyState& start,
                      double stable, double unstable) {
  EXPECT_FALSE(grows(integrator, model, start, stable)) << "dt = " << stable;
  EXPECT_TRUE(grows(integrator, model, start, unstable)) << "dt = " << unstable;
  while (unstable / stable > 1.002) {
    const double middle = std::sqrt(stable * unstable);
    (grows(integrator, model, start, middle) ? unstable : stable) = middle;
  }
  return std::sqrt(stable * unstable);
}

// The smallest dt (s) at which the advisor warns, found the same way from check_step.
double predicted_limit(Integrator integrator, const BodyModel& model, const BodyState& start) {
  double quiet = 1e-7, warned = 1.0;
  EXPECT_TRUE(check_step(model, start, integrator, quiet, 1.0).empty());
  EXPECT_FALSE(check_step(model, start, integrator, warned, 1.0).empty());
  while (warned / quiet > 1.0 + 1e-9) {
    const double middle = std::sqrt(quiet * warned);
    (check_step(model, start, integrator, middle, 1.0).empty() ? quiet : warned) = middle;
  }
  return warned;
}

// The starting departure: 1 nm up and a turn of 10 nrad about (1, 0, 2), which rocks the cube
// about x and z; the corners move by under 10 nm against a sink of 25 µm.
BodyState nudged(const BodyModel& model, const BodyState& rest) {
  physics::PrimaryState primary = rest.primary();
  primary.position.y() += 1e-9;
  primary.orientation =
      Quat(Eigen::AngleAxisd(1e-8, Vec3(1, 0, 2).normalized())) * primary.orientation;
  return BodyState(primary, model.constants);
}

// Compares the advisor's limit with the measured one for every integrator.
void expect_predicted_limits(const BodyModel& model, const BodyState& start) {
  for (const Integrator integrator : physics::kAllIntegrators) {
    SCOPED_TRACE(std::string(physics::integrator_name(integrator)));
    const double predicted = predicted_limit(integrator, model, start);
    const double measured =
        measured_limit(integrator, model, start, predicted / 3.0, 3.0 * predicted);
    std::printf("[ measured ] %-16s unstable from dt = %.5g s, predicted %.5g s (%+.2f%%)\n",
                std::string(physics::integrator_name(integrator)).c_str(), measured, predicted,
                100.0 * (predicted / measured - 1.0));
    EXPECT_NEAR(predicted, measured, 0.05 * measured);
    // One warning, or two where bouncing and rocking share a limit (explicit Euler's c/k).
    const std::vector<StepWarning> warnings =
        check_step(model, start, integrator, 1.01 * predicted, 1.0);
    ASSERT_FALSE(warnings.empty());
    for (const StepWarning& warning : warnings) {
      EXPECT_NE(warning.message.find("contact = \"impulse\""), std::string::npos)
          << warning.message;
      EXPECT_TRUE(warning.suggests_impulse_contact);
    }
  }
}

// A 1 kg unit cube, ω_n = 632 rad/s bouncing (4c/m = 200 /s) and 775 rad/s rocking
// (4c a²/I = 300 /s), no friction. Explicit Euler, unstable on any undamped spring, is stable
// here up to 2ζ/ω_n = c/k = 0.5 ms for both.
TEST(CheckStep, PredictsWherePenaltyContactTurnsEachIntegratorUnstable) {
  const BodyModel model = penalty_box(Vec3::Ones(), 1e5, 50.0, 0.0);
  expect_predicted_limits(model, nudged(model, settled(model)));
}

// A 0.3 × 1 × 2 m box lying on its largest face (body x up): its rocking about body y, with
// the 1 m lever, is the stiffest of any face (ω_n² = 4k a²/I_y = 1.17e6 /s²), so that the mode
// the advisor picks is the one this box has.
TEST(CheckStep, PredictsThePenaltyLimitsOfABoxOnItsStiffestFace) {
  const BodyModel model = penalty_box(Vec3(0.3, 1.0, 2.0), 1e5, 50.0, 0.0);
  const Quat on_largest_face(Eigen::AngleAxisd(std::numbers::pi / 2.0, Vec3::UnitZ()));
  expect_predicted_limits(model, nudged(model, settled(model, on_largest_face)));
}

// Soft contact (ω_n = 63 and 77 rad/s) with friction μ = 0.5: the regularised friction's slip,
// decaying at up to 3 μ g / v_s = 294 /s (twisting), is then the stiffest mode for every
// integrator. The departure adds a slide of 0.1 µm/s along x and a twist of 0.1 µrad/s, far below
// the slip speed of 5 cm/s where the friction is linear.
TEST(CheckStep, PredictsWherePenaltyFrictionTurnsEachIntegratorUnstable) {
  const BodyModel model = penalty_box(Vec3::Ones(), 1e3, 10.0, 0.5);
  physics::PrimaryState primary = nudged(model, settled(model)).primary();
  primary.momentum.x() += 1e-7;
  primary.angular_momentum.y() += 1e-7 * model.constants.inertia.y();
  const BodyState start(primary, model.constants);
  expect_predicted_limits(model, start);
  const std::vector<StepWarning> warnings = check_step(model, start, Integrator::rk4, 0.01, 1.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("twist decay at k = 294.3 /s"), std::string::npos)
      << warnings[0].message;
  EXPECT_NE(warnings[0].message.find("jitter"), std::string::npos) << warnings[0].message;
}

// Beyond the friction's limit the slip overshoots every step, but the friction force is at most
// μ F_n: the box sliding at 0.3 m/s and twisting at 0.2 rad/s under symplectic Euler does not come
// to rest, yet stays slower than it started. Inside the limit it stops.
TEST(CheckStep, BeyondTheFrictionLimitTheBoxJittersWithoutBlowingUp) {
  const BodyModel model = penalty_box(Vec3::Ones(), 1e3, 10.0, 0.5);
  const double limit = predicted_limit(Integrator::symplectic_euler, model, settled(model));
  const auto fastest_late_spin = [&](double dt) {
    BodyState state =
        physics::make_state(model.constants, Vec3(0, rest_height(model, Quat::Identity()), 0),
                            Vec3(0.3, 0, 0), Quat::Identity(), Vec3(0, 0.2, 0));
    double fastest = 0.0;  // rad/s, over the second half of 20000 steps
    for (int n = 0; n < 20000; ++n) {
      state = physics::step(Integrator::symplectic_euler, model, state, n * dt, dt);
      if (n >= 10000) fastest = std::max(fastest, state.angular_velocity().norm());
    }
    return fastest;
  };
  EXPECT_LT(fastest_late_spin(0.95 * limit), 1e-12);
  const double jitter = fastest_late_spin(1.5 * limit);
  std::printf(
      "[ measured ] symplectic_euler at 1.5 × the friction limit: spins at up to %.3g rad/s\n",
      jitter);
  EXPECT_GT(jitter, 1e-3);
  EXPECT_LT(jitter, 0.2);
}

}  // namespace
}  // namespace tumble::sim
