#include "sim/simulation.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "physics/interpolation.hpp"
#include "support/closed_forms.hpp"

namespace tumble::sim {
namespace {

using physics::BodyModel;
using physics::BodyState;
using physics::Quat;
using physics::Vec3;

Simulation projectile_simulation(double dt) {
  const testing::SpinningProjectile exact;
  BodyModel model{.constants = physics::cube_constants(1.0, 1.0),
                  .forces = {physics::Gravity{.acceleration = exact.gravity}}};
  BodyState start = physics::make_state(model.constants, exact.position, exact.velocity,
                                        exact.orientation, exact.angular_velocity);
  return Simulation({model}, {start}, physics::Integrator::rk4, dt);
}

TEST(Simulation, StepsAreExactlyDtWithNoAccumulatedRounding) {
  Simulation simulation = projectile_simulation(0.1);
  for (int n = 0; n < 1000; ++n) simulation.step();
  EXPECT_EQ(simulation.step_count(), 1000);
  EXPECT_EQ(simulation.time(), 100.0);  // 1000 additions of 0.1 would give 99.9999999999986
  EXPECT_EQ(simulation.time_of_step(999), 999 * 0.1);
}

TEST(Simulation, StatesAtAStepTimeAreThatStepExactly) {
  Simulation stepped = projectile_simulation(0.01);
  for (int n = 0; n < 50; ++n) stepped.step();
  Simulation queried = projectile_simulation(0.01);
  const BodyState at = queried.states_at(stepped.time()).front();
  EXPECT_EQ(at.position(), stepped.current().front().position());
  EXPECT_EQ(at.orientation().coeffs(), stepped.current().front().orientation().coeffs());
}

TEST(Simulation, StatesBetweenStepsInterpolateTheBracketingSteps) {
  Simulation simulation = projectile_simulation(0.1);
  const double t = 0.37;  // between steps 3 and 4
  const BodyState at = simulation.states_at(t).front();
  EXPECT_EQ(simulation.step_count(), 4);
  const BodyState expected =
      physics::interpolate(simulation.previous().front(), simulation.current().front(),
                           (t - 0.30000000000000004) / 0.1, simulation.models().front().constants);
  EXPECT_LT((at.position() - expected.position()).norm(), 1e-15);
  EXPECT_LT(physics::angle_between(at.orientation(), expected.orientation()), 1e-15);
}

TEST(Simulation, FrameTimesSeeTheSameMotionWhateverTheFrameRate) {
  const testing::SpinningProjectile exact;
  for (const double fps : {24.0, 30.0, 60.0, 144.0}) {
    Simulation simulation = projectile_simulation(1.0 / 100.0);
    for (int k = 0; k < static_cast<int>(2.0 * fps); ++k) {
      const double t = k / fps;
      const BodyState at = simulation.states_at(t).front();
      // Lerp between exact-to-round-off steps: error ≤ g dt² / 8 = 1.3e-4 m.
      ASSERT_LT((at.position() - exact.position_at(t)).norm(), 1.3e-4)
          << "fps " << fps << " t " << t;
      // Slerp at constant angular velocity is exact; what remains is RK4's rotation error.
      ASSERT_LT(physics::angle_between(at.orientation(), exact.orientation_at(t)), 1e-6);
    }
  }
}

TEST(Simulation, BodiesAdvanceIndependently) {
  Simulation pair = projectile_simulation(0.01);
  Simulation one = projectile_simulation(0.01);
  std::vector<BodyModel> models = {
      pair.models().front(),
      BodyModel{.constants = physics::cube_constants(2.0, 0.5), .forces = {}}};
  std::vector<BodyState> starts = {
      pair.current().front(), physics::make_state(models[1].constants, Vec3(5, 0, 0), Vec3::Zero(),
                                                  Quat::Identity(), Vec3(0, 1, 0))};
  Simulation two(models, starts, physics::Integrator::rk4, 0.01);
  for (int n = 0; n < 100; ++n) {
    two.step();
    one.step();
  }
  EXPECT_EQ(two.current()[0].position(), one.current()[0].position());
  EXPECT_EQ(two.current()[1].position(), Vec3(5, 0, 0));
}

}  // namespace
// Explicit Euler on damping k: v_{n+1} = (1 - k dt) v_n. With k dt = 5, |v| = 4^n v_0.
TEST(Simulation, AStepBeyondTheStabilityLimitIsCaughtAtTheStepThatPassesTheBound) {
  BodyModel model{.constants = physics::cube_constants(1.0, 1.0),
                  .forces = {physics::LinearDamping{.coefficient = 100.0}}};
  const BodyState start = physics::make_state(model.constants, Vec3::Zero(), Vec3(1.0, 0.0, 0.0),
                                              Quat::Identity(), Vec3::Zero());
  const BodyModel calm{.constants = physics::cube_constants(1.0, 1.0), .forces = {}};
  // 10 m above the other: bodies collide, and this one is not to be hit.
  const BodyState above = physics::make_state(calm.constants, Vec3(0.0, 10.0, 0.0), Vec3::Zero(),
                                              Quat::Identity(), Vec3::Zero());
  Simulation simulation({calm, model}, {above, start}, physics::Integrator::euler, 0.05);
  simulation.states_at(10.0);
  ASSERT_TRUE(simulation.blow_up().has_value());
  const BlowUp& blow_up = *simulation.blow_up();
  EXPECT_EQ(blow_up.body, 1u);
  // 4^13 = 6.7e7 <= 1e8 < 4^14 = 2.7e8.
  EXPECT_EQ(blow_up.step, 14);
  EXPECT_DOUBLE_EQ(blow_up.time, 14 * 0.05);
  EXPECT_EQ(blow_up.what.rfind("its speed reached 2.68e+08 m/s", 0), 0u) << blow_up.what;
  // Nothing moves after it: the states stay where the blow-up was found.
  EXPECT_EQ(simulation.step_count(), 14);
  simulation.step();
  EXPECT_EQ(simulation.step_count(), 14);
}

TEST(Simulation, BlowUpProblemsNameNonFiniteAndOutOfBoundValues) {
  const physics::BodyConstants cube = physics::cube_constants(1.0, 1.0);
  const auto state = [&](Vec3 x, Vec3 v, Vec3 w) {
    return physics::make_state(cube, x, v, Quat::Identity(), w);
  };
  // "" when the state passes, else its error.
  const auto blow_up_problem = [](const physics::BodyState& checked) -> std::string {
    const Result<void> result = check_in_bounds(checked);
    return result ? "" : result.error();
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(blow_up_problem(state(Vec3::Zero(), Vec3::Zero(), Vec3::Zero())), "");
  EXPECT_EQ(blow_up_problem(state(Vec3(kMaxPosition, 0, 0), Vec3(0, kMaxSpeed, 0),
                                  Vec3(0, 0, kMaxAngularSpeed))),
            "");  // the bounds themselves are allowed
  EXPECT_EQ(blow_up_problem(state(Vec3(nan, 0, 0), Vec3::Zero(), Vec3::Zero())),
            "its distance from the origin is not finite");
  EXPECT_EQ(blow_up_problem(state(Vec3::Zero(), Vec3::Zero(), Vec3(0, 2e7, 0))),
            "its angular speed reached 2e+07 rad/s, past the bound of 1e+07 rad/s");
  EXPECT_EQ(blow_up_problem(state(Vec3(0, 0, -3e9), Vec3::Zero(), Vec3::Zero())),
            "its distance from the origin reached 3e+09 m, past the bound of 1e+09 m");
  // Squared, 1e200 overflows to infinity: the message still gives the finite size.
  EXPECT_EQ(blow_up_problem(state(Vec3::Zero(), Vec3(1e200, 0, 0), Vec3::Zero())),
            "its speed reached 1e+200 m/s, past the bound of 1e+08 m/s");
  const double infinity = std::numeric_limits<double>::infinity();
  EXPECT_EQ(blow_up_problem(state(Vec3::Zero(), Vec3(0, -infinity, 0), Vec3::Zero())),
            "its speed is not finite");
  physics::PrimaryState primary = state(Vec3::Zero(), Vec3::Zero(), Vec3::Zero()).primary();
  primary.orientation = Quat(nan, 0, 0, 0);
  EXPECT_EQ(blow_up_problem(physics::BodyState(primary, cube)), "its orientation is not finite");
}

}  // namespace tumble::sim
