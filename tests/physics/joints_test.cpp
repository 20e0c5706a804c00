// Joints (physics/joints.hpp, physics/joint_solve.hpp): each kind's rows are the derivatives of
// its errors, and the closed-form cases of issue "Joints" hold: the pendulum's period, length and
// energy, a long chain's stretch, a door on a hinge, a slider, a weld.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <vector>

#include "bench/joint_cases.hpp"
#include "physics/contact_island.hpp"
#include "physics/joint_solve.hpp"
#include "physics/mass_properties.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;  // m/s²

BodyModel sphere(double mass, double radius) {
  return {.constants = sphere_constants(mass, radius),
          .forces = {Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
          .shape = sphere_shape(radius),
          .collides = false};
}

BodyModel box(double mass, const Vec3& size, bool gravity = true) {
  BodyModel model{.constants = box_constants(mass, size),
                  .forces = {},
                  .shape = box_shape(0.5 * size),
                  .collides = false};
  if (gravity) model.forces.push_back(Gravity{.acceleration = Vec3(0.0, -kG, 0.0)});
  return model;
}

// The body moved for τ (s) at its constant velocities: the kinematics the rows differentiate.
BodyState drifted(const BodyModel& model, const BodyState& state, double tau) {
  return make_state(model.constants, state.position() + tau * state.velocity(), state.velocity(),
                    rotated(state.orientation(), tau * state.angular_velocity()).normalized(),
                    state.angular_velocity());
}

std::vector<double> errors(const Joint& joint, std::span<const BodyState> states) {
  std::vector<JointRow> rows;
  const JointBody b = joint.b == kWorldBody ? JointBody{} : JointBody::of(states[joint.b]);
  equality_rows(joint, JointBody::of(states[joint.a]), b, rows);
  std::vector<double> out;
  for (const JointRow& row : rows) out.push_back(row.error);
  return out;
}

// For every kind, to a body and to the world: Ċ = J v and C̈ = J̇ v when neither body
// accelerates, against central differences of C along the bodies' drift (the joint placed where
// they stand, C = 0; a weld's and a slider's bodies turning together, as their rows hold them).
TEST(JointRows, RatesAndCurvaturesAreTheDerivativesOfTheErrors) {
  const BodyModel model_a = box(2.0, Vec3(0.3, 0.5, 0.7));
  const BodyModel model_b = box(3.0, Vec3(0.6, 0.2, 0.4));
  const std::vector<BodyModel> models = {model_a, model_b};
  for (const JointKind kind : {JointKind::ball, JointKind::hinge, JointKind::slider,
                               JointKind::fixed, JointKind::distance}) {
    for (const std::uint32_t b : {std::uint32_t{1}, kWorldBody}) {
      const bool locked = kind == JointKind::slider || kind == JointKind::fixed;
      const Vec3 spin_a(0.7, -1.3, 2.1);
      const Vec3 spin_b = b == kWorldBody ? Vec3::Zero() : locked ? spin_a : Vec3(-0.4, 0.9, 0.3);
      const Vec3 spin_a_here = locked && b == kWorldBody ? Vec3::Zero() : spin_a;
      const std::vector<BodyState> states = {
          make_state(model_a.constants, Vec3(0.1, 1.2, -0.3), Vec3(0.5, -0.2, 0.9),
                     Quat(0.9, 0.1, -0.3, 0.2).normalized(), spin_a_here),
          make_state(model_b.constants, Vec3(-0.4, 0.8, 0.2),
                     b == kWorldBody ? Vec3::Zero() : Vec3(-0.3, 0.4, 0.1),
                     Quat(0.7, -0.2, 0.4, 0.5).normalized(), spin_b)};
      const Joint joint =
          place_joint(kind, 0, b, states, Vec3(0.3, 1.0, 0.1),
                      kind == JointKind::distance ? Vec3(-0.2, 0.6, 0.4) : Vec3(0.3, 1.0, 0.1),
                      Vec3(1.0, 2.0, -0.5));
      std::vector<JointRow> rows;
      const JointBody body_b = b == kWorldBody ? JointBody{} : JointBody::of(states[1]);
      equality_rows(joint, JointBody::of(states[0]), body_b, rows);
      ASSERT_FALSE(rows.empty());
      constexpr double h = 1e-4;  // s
      std::vector<std::vector<double>> c;
      for (const double tau : {-h, 0.0, h}) {
        std::vector<BodyState> moved = states;
        for (std::size_t i = 0; i < 2; ++i) moved[i] = drifted(models[i], states[i], tau);
        c.push_back(errors(joint, moved));
      }
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const JointRow& row = rows[r];
        double rate = row.linear_a.dot(states[0].velocity()) +
                      row.angular_a.dot(states[0].angular_velocity());
        if (b != kWorldBody) {
          rate += row.linear_b.dot(states[1].velocity()) +
                  row.angular_b.dot(states[1].angular_velocity());
        }
        SCOPED_TRACE(std::string(joint_kind_name(kind)) + (b == kWorldBody ? " to the world" : "") +
                     ", row " + std::to_string(r));
        EXPECT_NEAR(row.error, 0.0, 1e-12);
        EXPECT_NEAR(rate, (c[2][r] - c[0][r]) / (2.0 * h), 1e-6);
        EXPECT_NEAR(row.curvature, (c[2][r] - 2.0 * c[1][r] + c[0][r]) / (h * h), 1e-4);
      }
    }
  }
}

// The mathematical pendulum: a 1 kg ball of radius 0.05 m on a rod of 1 m from a fixed point to
// its centre, released from θ0: the period 4 √(L/g) K(sin(θ0/2)) within 1e-4 relative, the rod's
// length within 1e-6 m and the energy within 1e-6 relative over 60 s (rk4, dt = 1/240 s).
struct PendulumRun {
  double period = 0.0;        // s: the mean time between upward crossings of the vertical
  double worst_length = 0.0;  // m: the largest |L - 1|
  double worst_energy = 0.0;  // of the start's |E|
};

PendulumRun swing(double theta0, Integrator integrator, double dt, double seconds) {
  const Vec3 pivot(0.0, 2.0, 0.0);
  const std::vector<BodyModel> models = {sphere(1.0, 0.05)};
  std::vector<BodyState> states = {
      make_state(models[0].constants, pivot + Vec3(std::sin(theta0), -std::cos(theta0), 0.0),
                 Vec3::Zero(), Quat::Identity(), Vec3::Zero())};
  JointWorld world = make_joint_world(
      {place_joint(JointKind::distance, 0, kWorldBody, states, states[0].position(), pivot)},
      models);
  const auto energy = [&](const BodyState& s) { return kinetic_energy(s) + kG * s.position().y(); };
  const double start = energy(states[0]);
  PendulumRun run;
  std::vector<double> crossings;
  std::vector<BodyState> next(1);
  const auto steps = static_cast<int>(std::llround(seconds / dt));
  for (int n = 0; n < steps; ++n) {
    step_joints(integrator, models, states, n * dt, dt, world, next);
    const BodyState& a = states[0];
    const BodyState& b = next[0];
    if (a.position().x() < 0.0 && b.position().x() >= 0.0) {
      // The crossing within the step, by the cubic through both ends' x and ẋ.
      const double s = bench::crossing_in_step(a.position().x(), a.velocity().x() * dt,
                                               b.position().x(), b.velocity().x() * dt);
      crossings.push_back((n + s) * dt);
    }
    states.swap(next);
    run.worst_length =
        std::max(run.worst_length, std::abs((states[0].position() - pivot).norm() - 1.0));
    run.worst_energy =
        std::max(run.worst_energy, std::abs(energy(states[0]) - start) / std::abs(start));
  }
  if (crossings.size() >= 2) {
    run.period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  }
  return run;
}

TEST(Pendulum, KeepsItsPeriodLengthAndEnergy) {
  for (const double degrees : {10.0, 90.0, 170.0}) {
    const double theta0 = degrees * std::numbers::pi / 180.0;
    const double exact = 4.0 * std::sqrt(1.0 / kG) * std::comp_ellint_1(std::sin(theta0 / 2.0));
    const PendulumRun run = swing(theta0, Integrator::rk4, 1.0 / 240.0, 60.0);
    SCOPED_TRACE(degrees);
    EXPECT_NEAR(run.period / exact - 1.0, 0.0, 1e-4) << run.period << " against " << exact;
    EXPECT_LT(run.worst_length, 1e-6);
    EXPECT_LT(run.worst_energy, 1e-6);
  }
}

// The double pendulum of two 1 kg balls of radius 0.05 m on rods of 1 m (pivot to the first
// centre, first centre to the second: point masses exactly), released from horizontal.
struct DoublePendulum {
  std::vector<BodyModel> models = {sphere(1.0, 0.05), sphere(1.0, 0.05)};
  std::vector<BodyState> states;
  JointWorld world;
  Vec3 pivot = Vec3(0.0, 2.0, 0.0);
  DoublePendulum() {
    for (int i = 0; i < 2; ++i) {
      states.push_back(make_state(models[i].constants, pivot + Vec3(i + 1.0, 0.0, 0.0),
                                  Vec3::Zero(), Quat::Identity(), Vec3::Zero()));
    }
    world.joints.push_back(
        place_joint(JointKind::distance, 0, kWorldBody, states, states[0].position(), pivot));
    world.joints.push_back(
        place_joint(JointKind::distance, 1, 0, states, states[1].position(), states[0].position()));
    world = make_joint_world(world.joints, models);
  }
  double energy() const {
    double e = 0.0;
    for (const BodyState& s : states) e += kinetic_energy(s) + kG * s.position().y();
    return e;
  }
  // The angles from the downward vertical (rad).
  std::array<double, 2> angles() const {
    const Vec3 d1 = states[0].position() - pivot;
    const Vec3 d2 = states[1].position() - states[0].position();
    return {std::atan2(d1.x(), -d1.y()), std::atan2(d2.x(), -d2.y())};
  }
};

// Until t = 5 s the angles follow the reduced equations integrated at 1e-12 (Boost.Odeint's
// Runge-Kutta-Fehlberg 7(8), bench/joint_cases.hpp) within 1e-6 rad at dt = 1/960 s.
TEST(DoublePendulum, FollowsTheReducedEquations) {
  DoublePendulum pendulum;
  constexpr double dt = 1.0 / 960.0;
  std::vector<double> reference = {std::numbers::pi / 2.0, std::numbers::pi / 2.0, 0.0, 0.0};
  std::vector<BodyState> next(2);
  double worst = 0.0;
  for (int n = 0; n < 5 * 960; ++n) {
    step_joints(Integrator::rk4, pendulum.models, pendulum.states, n * dt, dt, pendulum.world,
                next);
    pendulum.states.swap(next);
    reference = bench::double_pendulum_angles(reference, n * dt, (n + 1) * dt, 1e-12, kG);
    const std::array<double, 2> angles = pendulum.angles();
    for (std::size_t k = 0; k < 2; ++k) {
      worst = std::max(worst,
                       std::abs(std::remainder(angles[k] - reference[k], 2.0 * std::numbers::pi)));
    }
  }
  EXPECT_LT(worst, 1e-6);
}

// Over 60 s at dt = 1/240 s its energy stays within 1e-5 of its start, and both rods within
// 1e-6 m of their length.
TEST(DoublePendulum, KeepsItsEnergyAndRods) {
  DoublePendulum pendulum;
  constexpr double dt = 1.0 / 240.0;
  const double start = pendulum.energy();
  std::vector<BodyState> next(2);
  double worst_energy = 0.0, worst_rod = 0.0;
  for (int n = 0; n < 60 * 240; ++n) {
    step_joints(Integrator::rk4, pendulum.models, pendulum.states, n * dt, dt, pendulum.world,
                next);
    pendulum.states.swap(next);
    worst_energy = std::max(worst_energy, std::abs(pendulum.energy() - start) / std::abs(start));
    worst_rod = std::max(
        {worst_rod, std::abs((pendulum.states[0].position() - pendulum.pivot).norm() - 1.0),
         std::abs((pendulum.states[1].position() - pendulum.states[0].position()).norm() - 1.0)});
  }
  EXPECT_LT(worst_energy, 1e-5);
  EXPECT_LT(worst_rod, 1e-6);
}

// Runs the world for `seconds` at dt, calling watch(states) after each step.
template <class Watch>
void run(Integrator integrator, const std::vector<BodyModel>& models,
         std::vector<BodyState>& states, JointWorld& world, double dt, double seconds,
         Watch&& watch) {
  world = make_joint_world(world.joints, models);  // as the test set its joints
  std::vector<BodyState> next(states.size());
  const auto steps = static_cast<int>(std::llround(seconds / dt));
  for (int n = 0; n < steps; ++n) {
    step_joints(integrator, models, states, n * dt, dt, world, next);
    states.swap(next);
    watch(states);
  }
}

// A chain of `links` boxes of 0.1 m (0.02 × 0.1 × 0.02 m, `mass` each) on ball joints, hanging
// from the world at (0, 10, 0), or lying along +x from it when `horizontal`; with an end ball of
// `end_mass` (radius 0.1 m, hung on a ball joint at its top) when that is > 0.
struct Chain {
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  JointWorld world;
  Vec3 pivot = Vec3(0.0, 10.0, 0.0);
  double length = 0.0;  // m: pivot to the free end

  Chain(int links, double mass, bool horizontal, double end_mass = 0.0) {
    const Vec3 along = horizontal ? Vec3(Vec3::UnitX()) : Vec3(-Vec3::UnitY());
    const Quat turn = horizontal ? Quat(Eigen::AngleAxisd(-std::numbers::pi / 2.0, Vec3::UnitZ()))
                                 : Quat::Identity();
    for (int k = 0; k < links; ++k) {
      models.push_back(box(mass, Vec3(0.02, 0.1, 0.02)));
      states.push_back(make_state(models.back().constants, pivot + (0.1 * k + 0.05) * along,
                                  Vec3::Zero(), turn, Vec3::Zero()));
    }
    length = 0.1 * links;
    if (end_mass > 0.0) {
      models.push_back(sphere(end_mass, 0.1));
      states.push_back(make_state(models.back().constants, pivot + (length + 0.1) * along,
                                  Vec3::Zero(), Quat::Identity(), Vec3::Zero()));
      length += 0.2;
    }
    for (std::uint32_t k = 0; k < states.size(); ++k) {
      const Vec3 top = pivot + 0.1 * k * along;
      world.joints.push_back(
          place_joint(JointKind::ball, k, k == 0 ? kWorldBody : k - 1, states, top, top));
    }
  }
  // The largest gap between two anchors of a joint (m).
  double widest_gap() const {
    double out = 0.0;
    for (const Joint& joint : world.joints) out = std::max(out, joint_opening(joint, states));
    return out;
  }
  double energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < states.size(); ++i) {
      e += kinetic_energy(states[i]) + models[i].constants.mass * kG * states[i].position().y();
    }
    return e;
  }
};

// 100 links hanging under gravity for 2 s stretch by less than 1 mm.
TEST(Chain, OfAHundredLinksHangsWithoutStretching) {
  Chain chain(100, 0.1, false);
  run(Integrator::rk4, chain.models, chain.states, chain.world, 1.0 / 240.0, 2.0,
      [](const std::vector<BodyState>&) {});
  EXPECT_LT(chain.widest_gap(), 1e-9);
  EXPECT_NEAR((chain.states.back().position() - chain.pivot).norm(), chain.length - 0.05, 1e-3);
}

// Released from horizontal, no joint opens by 1 cm and the energy never rises above its start
// (by more than 1e-9 of its scale, m g L).
TEST(Chain, ReleasedFromHorizontalStaysTogetherAndGainsNoEnergy) {
  Chain chain(100, 0.1, true);
  const double start = chain.energy();
  const double scale = 100 * 0.1 * kG * 10.0;
  double widest = 0.0, highest = -1e300;
  run(Integrator::rk4, chain.models, chain.states, chain.world, 1.0 / 240.0, 3.0,
      [&](const std::vector<BodyState>&) {
        widest = std::max(widest, chain.widest_gap());
        highest = std::max(highest, chain.energy() - start);
      });
  EXPECT_LT(widest, 1e-2);
  EXPECT_LT(widest, 1e-9);
  EXPECT_LT(highest, 1e-9 * scale);
}

// A 10 kg ball at the end of 20 links of 0.1 kg (100:1): hanging, it stretches the chain by less
// than 1 cm; swung at 5 m/s, it does not blow up and the chain stays together.
TEST(Chain, HoldsAHundredTimesItsLinksMass) {
  Chain chain(20, 0.1, false, 10.0);
  run(Integrator::rk4, chain.models, chain.states, chain.world, 1.0 / 240.0, 3.0,
      [](const std::vector<BodyState>&) {});
  EXPECT_LT(chain.widest_gap(), 1e-2);
  EXPECT_NEAR((chain.states.back().position() - chain.pivot).norm(), chain.length - 0.1, 1e-2);
  PrimaryState kicked = chain.states.back().primary();
  kicked.momentum = Vec3(50.0, 0.0, 20.0);  // 10 kg at 5.4 m/s
  chain.states.back() = BodyState(kicked, chain.models.back().constants);
  const double start = chain.energy();
  double widest = 0.0, highest = -1e300;
  run(Integrator::rk4, chain.models, chain.states, chain.world, 1.0 / 240.0, 5.0,
      [&](const std::vector<BodyState>&) {
        widest = std::max(widest, chain.widest_gap());
        highest = std::max(highest, chain.energy() - start);
      });
  EXPECT_LT(widest, 1e-2);
  EXPECT_LT(highest, 1e-6 * start);
}

// A door, 1 × 2 × 0.05 m and 20 kg, on a hinge along its left edge, gravity along the hinge,
// swinging at `swing` rad/s about it; the whole of it turned by `frame` from the door standing on
// the world's y axis, so that no row lines up with a world axis.
struct Door {
  std::vector<BodyModel> models = {box(20.0, Vec3(1.0, 2.0, 0.05), false)};
  std::vector<BodyState> states;
  JointWorld world;
  Quat frame = Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()));
  Vec3 axis = frame * Vec3::UnitY();
  Door(double swing) {
    models[0].forces.push_back(Gravity{.acceleration = -kG * axis});
    const Vec3 hinge = frame * Vec3(0.0, 1.0, 0.0);
    states.push_back(make_state(models[0].constants, frame * Vec3(0.5, 1.0, 0.0),
                                frame * Vec3(0.0, 0.0, -0.5 * swing), frame, swing * axis));
    world.joints.push_back(
        place_joint(JointKind::hinge, 0, kWorldBody, states, hinge, hinge, axis));
  }
  double angle() const {
    return joint_coordinate(world.joints[0], JointBody::of(states[0]), JointBody{})->value;
  }
  double rate() const {
    return joint_coordinate(world.joints[0], JointBody::of(states[0]), JointBody{})->rate;
  }
  double sag() const {  // how far the door's own y axis is off the hinge (rad)
    return std::acos(std::min(1.0, (states[0].rotation() * Vec3::UnitY()).dot(axis)));
  }
  // Its moment about the hinge: m (w² + t²) / 12 + m (w / 2)² (kg m²).
  static double moment() { return 20.0 * (1.0 + 0.0025) / 12.0 + 20.0 * 0.25; }
};

// Swinging freely for 10 s, the door stays on its hinge: less than 1e-4 rad off its axis.
TEST(Hinge, HoldsADoorWithoutSag) {
  Door door(1.0);
  double worst = 0.0;
  run(Integrator::rk4, door.models, door.states, door.world, 1.0 / 240.0, 10.0,
      [&](const std::vector<BodyState>&) { worst = std::max(worst, door.sag()); });
  EXPECT_LT(worst, 1e-4);
  EXPECT_NEAR(door.rate(), 1.0, 1e-6);  // nothing acts about the hinge
}

// With limits of ±45°, struck at 3 rad/s, it stops at each limit and never passes one by
// more than 1e-3 rad.
TEST(Hinge, StopsAtItsLimits) {
  Door door(3.0);
  door.world.joints[0].limits =
      JointLimits{.lower = -std::numbers::pi / 4.0, .upper = std::numbers::pi / 4.0};
  double highest = -1.0, lowest = 1.0;
  run(Integrator::rk4, door.models, door.states, door.world, 1.0 / 240.0, 3.0,
      [&](const std::vector<BodyState>&) {
        highest = std::max(highest, door.angle());
        lowest = std::min(lowest, door.angle());
      });
  EXPECT_LT(highest, std::numbers::pi / 4.0 + 1e-3);
  EXPECT_GT(highest, std::numbers::pi / 4.0 - 1e-3);  // it reached the limit
  EXPECT_LT(door.sag(), 1e-4);
}

// A motor of 2 rad/s with torque to spare reaches it within 1 % and holds it; with 5 N m it
// accelerates at 5 N m / I within 1 %.
TEST(Hinge, MotorReachesItsSpeedOrAcceleratesAtItsTorque) {
  Door strong(0.0);
  strong.world.joints[0].motor = JointMotor{.speed = 2.0, .max_effort = 1000.0};
  double slowest_after = 1e300, fastest_after = 0.0;
  int n = 0;
  run(Integrator::rk4, strong.models, strong.states, strong.world, 1.0 / 240.0, 3.0,
      [&](const std::vector<BodyState>&) {
        if (++n > 240) {
          slowest_after = std::min(slowest_after, strong.rate());
          fastest_after = std::max(fastest_after, strong.rate());
        }
      });
  EXPECT_NEAR(slowest_after, 2.0, 0.02);
  EXPECT_NEAR(fastest_after, 2.0, 0.02);

  Door weak(0.0);
  weak.world.joints[0].motor = JointMotor{.speed = 100.0, .max_effort = 5.0};
  run(Integrator::rk4, weak.models, weak.states, weak.world, 1.0 / 240.0, 2.0,
      [](const std::vector<BodyState>&) {});
  EXPECT_NEAR(weak.rate() / 2.0, 5.0 / Door::moment(), 0.01 * 5.0 / Door::moment());
}

// A 2 kg box on a slider down a 30° incline (no friction in the joint) accelerates at g sin 30°
// within 0.1 %; its limit stops it; its motor drives it at its speed.
struct Incline {
  std::vector<BodyModel> models = {box(2.0, Vec3(0.4, 0.2, 0.3))};
  std::vector<BodyState> states;
  JointWorld world;
  Vec3 down = Vec3(std::cos(std::numbers::pi / 6.0), -std::sin(std::numbers::pi / 6.0), 0.0);
  Incline() {
    states.push_back(make_state(models[0].constants, Vec3(0.0, 3.0, 0.0), Vec3::Zero(),
                                Quat(Eigen::AngleAxisd(-std::numbers::pi / 6.0, Vec3::UnitZ())),
                                Vec3::Zero()));
    world.joints.push_back(place_joint(JointKind::slider, 0, kWorldBody, states,
                                       Vec3(0.0, 3.0, 0.0), Vec3(0.0, 3.0, 0.0), down));
  }
  double travel() const {
    return joint_coordinate(world.joints[0], JointBody::of(states[0]), JointBody{})->value;
  }
  double speed() const {
    return joint_coordinate(world.joints[0], JointBody::of(states[0]), JointBody{})->rate;
  }
};

TEST(Slider, SlidesDownAnInclineAtGSinTheta) {
  Incline incline;
  run(Integrator::rk4, incline.models, incline.states, incline.world, 1.0 / 240.0, 1.0,
      [](const std::vector<BodyState>&) {});
  const double expected = kG * 0.5;
  EXPECT_NEAR(2.0 * incline.travel() / 1.0, expected, 1e-3 * expected);
  EXPECT_NEAR(incline.speed() / 1.0, expected, 1e-3 * expected);
  // It kept to its line and did not turn.
  EXPECT_NEAR((incline.states[0].position() - Vec3(0.0, 3.0, 0.0)).normalized().dot(incline.down),
              1.0, 1e-12);
  EXPECT_LT(incline.states[0].angular_velocity().norm(), 1e-9);
}

TEST(Slider, StopsAtItsLimitAndFollowsItsMotor) {
  Incline limited;
  limited.world.joints[0].limits = JointLimits{.lower = -0.1, .upper = 0.5};
  double farthest = 0.0;
  run(Integrator::rk4, limited.models, limited.states, limited.world, 1.0 / 240.0, 2.0,
      [&](const std::vector<BodyState>&) { farthest = std::max(farthest, limited.travel()); });
  EXPECT_LT(farthest, 0.5 + 1e-3);
  EXPECT_NEAR(limited.travel(), 0.5, 1e-3);
  EXPECT_NEAR(limited.speed(), 0.0, 1e-3);

  Incline driven;
  driven.world.joints[0].motor = JointMotor{.speed = -0.5, .max_effort = 100.0};  // up the slope
  run(Integrator::rk4, driven.models, driven.states, driven.world, 1.0 / 240.0, 1.0,
      [](const std::vector<BodyState>&) {});
  EXPECT_NEAR(driven.speed(), -0.5, 0.005);
}

// Two boxes welded, spun and thrown under gravity, move as one body: their relative pose drifts
// by less than 1e-6 m and 1e-6 rad over 10 s, and each follows the single body of their combined
// mass properties within 1e-6 m and 1e-6 rad.
TEST(Fixed, WeldsTwoBoxesIntoOneBody) {
  const std::vector<BodyModel> models = {box(3.0, Vec3(0.4, 0.3, 0.2)),
                                         box(1.0, Vec3(0.2, 0.6, 0.2))};
  const Quat qa(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  const Quat qb(Eigen::AngleAxisd(-0.7, Vec3(-1, 0, 2).normalized()));
  const Vec3 xa(0.0, 5.0, 0.0), xb(0.25, 5.35, 0.1);
  const Vec3 v(1.0, 4.0, -0.5), w(0.8, -2.5, 1.7);  // the pair's velocity and spin
  const double mass = 4.0;
  const Vec3 centre = (3.0 * xa + 1.0 * xb) / mass;
  const Vec3 vc = v;  // the centre's velocity: v at the centre of mass, w about it
  std::vector<BodyState> states = {
      make_state(models[0].constants, xa, vc + w.cross(xa - centre), qa, w),
      make_state(models[1].constants, xb, vc + w.cross(xb - centre), qb, w)};
  // The combined body: its inertia about the centre, world frame, and its principal axes.
  Mat3 inertia = Mat3::Zero();
  for (std::size_t i = 0; i < 2; ++i) {
    const Mat3 r = states[i].rotation();
    const Vec3 d = states[i].position() - centre;
    const double m = models[i].constants.mass;
    inertia += r * models[i].constants.inertia.asDiagonal() * r.transpose() +
               m * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> principal(inertia);
  Mat3 axes = principal.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(0) = -axes.col(0);
  const BodyModel whole{.constants = constants_from_moments(mass, principal.eigenvalues()),
                        .forces = {Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
                        .collides = false};
  BodyState one = make_state(whole.constants, centre, vc, Quat(axes), w);
  // Each box's pose in the combined body's frame.
  std::array<Vec3, 2> offset;
  std::array<Quat, 2> turn;
  for (std::size_t i = 0; i < 2; ++i) {
    offset[i] = axes.transpose() * (states[i].position() - centre);
    turn[i] = Quat(axes).conjugate() * states[i].orientation();
  }
  JointWorld world;
  world.joints.push_back(
      place_joint(JointKind::fixed, 1, 0, states, Vec3(0.15, 5.2, 0.05), Vec3(0.15, 5.2, 0.05)));
  const Joint weld = world.joints[0];  // a copy: run() makes the world again
  double worst_offset = 0.0, worst_turn = 0.0, worst_place = 0.0, worst_angle = 0.0;
  constexpr double dt = 1.0 / 240.0;
  int n = 0;
  run(Integrator::rk4, models, states, world, dt, 10.0, [&](const std::vector<BodyState>& now) {
    one = step(Integrator::rk4, whole, one, n * dt, dt);
    ++n;
    worst_offset = std::max(worst_offset, joint_opening(weld, now));
    worst_turn =
        std::max(worst_turn, angle_between(now[1].orientation(), now[0].orientation() * weld.rest));
    for (std::size_t i = 0; i < 2; ++i) {
      worst_place = std::max(
          worst_place, (now[i].position() - (one.position() + one.rotation() * offset[i])).norm());
      worst_angle =
          std::max(worst_angle, angle_between(now[i].orientation(), one.orientation() * turn[i]));
    }
  });
  EXPECT_LT(worst_offset, 1e-6);
  EXPECT_LT(worst_turn, 1e-6);
  EXPECT_LT(worst_place, 1e-6);
  EXPECT_LT(worst_angle, 1e-6);
}

// The heavy symmetric (Lagrange) top: a 1 kg disc of radius 0.1 m and thickness 0.02 m on a ball
// joint 0.1 m below its centre along its axis, tilted 20° and spinning at ω3 = 50 rad/s, started
// on its slow steady precession Ω (the root of I1 Ω² cos θ - I3 ω3 Ω + M g l = 0, I1 about the
// pivot). Over 10 s it precesses at Ω within 1 % without nutating (θ within 0.1° of 20°), and
// keeps its energy, its angular momentum about the vertical through the pivot and its spin
// I3 ω3 within 1e-6 of their start (rk4, dt = 1/480 s: at 1/240 s they drift by 1.9e-6, 2.9e-6
// and 2.6e-6, RK4's own error at ω dt = 0.21, which moves the same disc spinning freely, with no
// joint and no gravity, by 8.5e-6 in energy over the 10 s).
TEST(SpinningTop, PrecessesSteadilyAndKeepsItsEnergyAndMomenta) {
  constexpr double radius = 0.1, thickness = 0.02, mass = 1.0, l = 0.1, spin = 50.0;
  const double tilt = 20.0 * std::numbers::pi / 180.0;
  const Vec3 moments = cylinder_inertia(mass, radius, thickness).diagonal();  // y: the axis
  const double i3 = moments.y(), i1 = moments.x() + mass * l * l;
  const double mgl = mass * kG * l;
  const double omega =
      (i3 * spin - std::sqrt(i3 * i3 * spin * spin - 4.0 * i1 * mgl * std::cos(tilt))) /
      (2.0 * i1 * std::cos(tilt));
  const std::vector<BodyModel> models = {{.constants = constants_from_moments(mass, moments),
                                          .forces = {Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
                                          .shape = cylinder_shape(radius, 0.5 * thickness),
                                          .collides = false}};
  const Vec3 pivot(0.0, 1.0, 0.0);
  const Quat q(Eigen::AngleAxisd(tilt, Vec3::UnitZ()));  // its axis (body y) tilted towards -x
  const Vec3 axis = q * Vec3::UnitY();
  const Vec3 w = omega * Vec3::UnitY() + (spin - omega * std::cos(tilt)) * axis;
  std::vector<BodyState> states = {
      make_state(models[0].constants, pivot + l * axis, w.cross(l * axis), q, w)};
  JointWorld world;
  world.joints.push_back(place_joint(JointKind::ball, 0, kWorldBody, states, pivot, pivot));
  const auto energy = [&](const BodyState& s) {
    return kinetic_energy(s) + mgl / l * s.position().y();
  };
  const auto vertical_momentum = [&](const BodyState& s) {
    return (s.angular_momentum() + mass * (s.position() - pivot).cross(s.velocity())).y();
  };
  const auto axial_momentum = [&](const BodyState& s) {
    return s.angular_momentum().dot(s.rotation() * Vec3::UnitY());
  };
  const double e0 = energy(states[0]), lz0 = vertical_momentum(states[0]);
  const double l30 = axial_momentum(states[0]);
  double worst_e = 0.0, worst_lz = 0.0, worst_l3 = 0.0, worst_tilt = 0.0, turned = 0.0;
  Vec3 last = axis;
  run(Integrator::rk4, models, states, world, 1.0 / 480.0, 10.0,
      [&](const std::vector<BodyState>& now) {
        const Vec3 a = now[0].rotation() * Vec3::UnitY();
        worst_tilt = std::max(worst_tilt, std::abs(std::acos(a.y()) - tilt));
        // The azimuth of the axis, unwrapped.
        turned +=
            std::atan2(last.z() * a.x() - last.x() * a.z(), last.x() * a.x() + last.z() * a.z());
        last = a;
        worst_e = std::max(worst_e, std::abs(energy(now[0]) - e0) / e0);
        worst_lz = std::max(worst_lz, std::abs(vertical_momentum(now[0]) - lz0) / std::abs(lz0));
        worst_l3 = std::max(worst_l3, std::abs(axial_momentum(now[0]) - l30) / std::abs(l30));
      });
  EXPECT_NEAR(turned / 10.0, omega, 0.01 * omega);  // turned about +y (z towards x)
  EXPECT_LT(worst_tilt, 0.1 * std::numbers::pi / 180.0);
  EXPECT_LT(worst_e, 1e-6);
  EXPECT_LT(worst_lz, 1e-6);
  EXPECT_LT(worst_l3, 1e-6);
}

}  // namespace
}  // namespace tumble::physics
