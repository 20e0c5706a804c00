// Penalty contact between bodies (physics/penalty_pairs.hpp): two cubes meeting head-on bounce
// apart in every integrator, momentum kept to round-off and energy never gained; bodies that do
// not collide pass through each other; and a world where no two bodies come close steps each
// body exactly as alone.
#include "physics/penalty_pairs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tumble::physics {
namespace {

constexpr double kStep = 1.0 / 4000.0;  // s: within every integrator's limit at k = 1e5 N/m

BodyModel unit_cube() {
  return {.constants = cube_constants(1.0, 1.0),
          .forces = {},
          .shape = box_shape(Vec3::Constant(0.5)),
          .material = {.restitution = 0.0, .friction = 0.5}};
}

const ContactSettings kPenalty = {.method = ContactMethod::penalty};

struct HeadOn {
  std::vector<BodyState> end;
  double largest_energy = 0.0;  // J, over every step
  double momentum_error = 0.0;  // N s, the largest change of the total over every step
};

// Two unit cubes 0.5 m apart along x, A at +2 m/s and B at −1.25 m/s, for 1 s.
HeadOn head_on(Integrator integrator, std::vector<BodyModel> models) {
  std::vector<BodyState> states = {
      make_state(models[0].constants, Vec3(-0.75, 0.0, 0.0), Vec3(2.0, 0.0, 0.0), Quat::Identity(),
                 Vec3::Zero()),
      make_state(models[1].constants, Vec3(0.75, 0.0, 0.0), Vec3(-1.25, 0.0, 0.0), Quat::Identity(),
                 Vec3::Zero())};
  const Vec3 momentum = states[0].momentum() + states[1].momentum();
  HeadOn run;
  std::vector<BodyState> next(2);
  PenaltyWorld scratch;
  for (int n = 0; n < 4000; ++n) {
    step_penalty_world(integrator, models, states, n * kStep, kStep, kPenalty, scratch, next);
    states = next;
    double energy = 0.0;
    for (const BodyState& s : states) {
      energy += 0.5 * s.velocity().dot(s.momentum()) +
                0.5 * s.angular_velocity().dot(s.angular_momentum());
    }
    run.largest_energy = std::max(run.largest_energy, energy);
    run.momentum_error = std::max(run.momentum_error,
                                  (states[0].momentum() + states[1].momentum() - momentum).norm());
  }
  run.end = states;
  return run;
}

TEST(PenaltyPairs, CubesMeetingHeadOnBounceApartInEveryIntegrator) {
  const double start_energy = 0.5 * (2.0 * 2.0 + 1.25 * 1.25);  // J
  for (const Integrator integrator : kAllIntegrators) {
    SCOPED_TRACE(std::string(integrator_name(integrator)));
    const HeadOn run = head_on(integrator, {unit_cube(), unit_cube()});
    const BodyState& a = run.end[0];
    const BodyState& b = run.end[1];
    // They did not pass: A is still on the left and they move apart.
    EXPECT_LT(a.position().x(), b.position().x() - 1.0);
    EXPECT_GT(b.velocity().x() - a.velocity().x(), 0.0);
    // The damped springs take energy and never give it: the bounce's relative speed is a
    // fraction of the approach's 3.25 m/s.
    EXPECT_LT(b.velocity().x() - a.velocity().x(), 3.25);
    EXPECT_LE(run.largest_energy, start_energy * (1.0 + 1e-12));
    // Equal and opposite forces: the total momentum keeps (2 − 1.25) kg m/s.
    EXPECT_LT(run.momentum_error, 1e-12);
    // Face on face, centred: no spin and nothing sideways.
    EXPECT_LT(a.angular_velocity().norm() + b.angular_velocity().norm(), 1e-12);
    EXPECT_LT(std::abs(a.velocity().y()) + std::abs(a.velocity().z()), 1e-12);
  }
}

TEST(PenaltyPairs, BodiesThatDoNotCollidePassThroughEachOther) {
  BodyModel ghost = unit_cube();
  ghost.collides = false;
  const HeadOn run = head_on(Integrator::rk4, {unit_cube(), ghost});
  EXPECT_DOUBLE_EQ(run.end[0].velocity().x(), 2.0);
  EXPECT_GT(run.end[0].position().x(), run.end[1].position().x());
}

TEST(PenaltyPairs, BodiesFarApartStepExactlyAsAlone) {
  BodyModel falling = unit_cube();
  falling.forces = {Gravity{}, LinearDamping{.coefficient = 0.3}};
  const std::vector<BodyModel> models = {falling, falling};
  for (const Integrator integrator : kAllIntegrators) {
    std::vector<BodyState> states = {
        make_state(falling.constants, Vec3(0.0, 0.0, 0.0), Vec3(0.1, 0.0, 0.0), Quat::Identity(),
                   Vec3(0.3, 1.0, -0.2)),
        make_state(falling.constants, Vec3(10.0, 0.0, 0.0), Vec3(-0.1, 0.0, 0.0), Quat::Identity(),
                   Vec3(1.0, 0.0, 2.0))};
    std::vector<BodyState> alone = states, next(2);
    PenaltyWorld scratch;
    for (int n = 0; n < 100; ++n) {
      step_penalty_world(integrator, models, states, n * 0.01, 0.01, kPenalty, scratch, next);
      states = next;
      for (int i = 0; i < 2; ++i) alone[i] = step(integrator, falling, alone[i], n * 0.01, 0.01);
    }
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ(states[i].position(), alone[i].position());
      EXPECT_EQ(states[i].orientation().coeffs(), alone[i].orientation().coeffs());
      EXPECT_EQ(states[i].angular_momentum(), alone[i].angular_momentum());
    }
  }
}

// The coupled step is the integrator's own step of the whole system: rk4 on two cubes pressed
// 1 mm into each other, at rest, undamped, is fourth order against the closed form. Their
// overlap q obeys q'' = −(4k/μ) q (four points, reduced mass μ = m/2) while it lasts (a quarter
// period, 1.76 ms), so A is at −0.4995 − (q₀ − q₀ cos ωt)/2 after t = 1 ms.
TEST(PenaltyPairs, Rk4OnTheSpringsBetweenTwoBodiesIsFourthOrder) {
  constexpr double kStiffness = 1e5, kOverlap = 1e-3, kTime = 1e-3;
  const double omega = std::sqrt(4.0 * kStiffness / 0.5);
  const double exact = -0.4995 - 0.5 * kOverlap * (1.0 - std::cos(omega * kTime));
  const auto error_at = [&](double dt) {
    const ContactSettings springs = {
        .method = ContactMethod::penalty, .stiffness = kStiffness, .damping = 0.0};
    const std::vector<BodyModel> models = {unit_cube(), unit_cube()};
    std::vector<BodyState> states = {make_state(models[0].constants, Vec3(-0.4995, 0.0, 0.0),
                                                Vec3::Zero(), Quat::Identity(), Vec3::Zero()),
                                     make_state(models[1].constants, Vec3(0.4995, 0.0, 0.0),
                                                Vec3::Zero(), Quat::Identity(), Vec3::Zero())};
    std::vector<BodyState> next(2);
    PenaltyWorld scratch;
    const int steps = static_cast<int>(std::lround(kTime / dt));
    for (int n = 0; n < steps; ++n) {
      step_penalty_world(Integrator::rk4, models, states, n * dt, dt, springs, scratch, next);
      states = next;
    }
    return std::abs(states[0].position().x() - exact);
  };
  const double coarse = error_at(1e-4), fine = error_at(5e-5);  // measured 1.7e-10, 1.1e-11
  EXPECT_LT(coarse, 1e-9);
  EXPECT_NEAR(std::log2(coarse / fine), 4.0, 0.3);
}

}  // namespace
}  // namespace tumble::physics
