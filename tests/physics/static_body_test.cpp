// Static bodies (issue "Shapes"): fixed in the world, met as planes are met. A ball rolls down a
// static ramp as down a plane, boxes and balls rest on a static table, a fast ball stops at a thin
// static plate, and the static body never moves by a bit, whether it comes first or last.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "physics/mass_properties.hpp"
#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;           // m/s²
constexpr double kStep = 1.0 / 60.0;  // s

BodyModel ball(double radius, double mass, double friction) {
  return {.constants = sphere_constants(mass, radius),
          .forces = {Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
          .shape = sphere_shape(radius),
          .material = {.restitution = 0.0, .friction = friction}};
}

BodyModel fixed_box(const Vec3& size, double friction) {
  return {.constants = static_constants(),
          .forces = {},
          .shape = box_shape(0.5 * size),
          .material = {.restitution = 0.0, .friction = friction},
          .is_static = true};
}

BodyState placed(const BodyModel& model, const Vec3& position, const Quat& q = Quat::Identity(),
                 const Vec3& velocity = Vec3::Zero()) {
  return make_state(model.constants, position, velocity, q, Vec3::Zero());
}

// A ball on a static ramp (a 4 × 0.2 × 2 m slab turned 25° about z) rolls as on a plane:
// a = 5/7 g sin θ within 0.5%, whether the ramp is the first body or the last; the ramp's state
// stays the same bits. (0.24% fast, where on a plane it is exact: once the ball moves 2 cm a step
// its island is sub-stepped, and sub-steps move poses with the solved velocity, symplectic Euler,
// first order in position.)
TEST(StaticBody, ABallRollsDownAStaticRampAtFiveSevenths) {
  const double theta = 25.0 * std::numbers::pi / 180.0, r = 0.2;
  const Quat turn(Eigen::AngleAxisd(-theta, Vec3::UnitZ()));  // falling towards +x
  const Vec3 n = turn * Vec3::UnitY(), down = turn * Vec3::UnitX();
  const BodyModel ramp = fixed_box(Vec3(4.0, 0.2, 2.0), 0.6);
  const BodyModel rolling = ball(r, 1.0, 0.6);
  const BodyState ramp_at = placed(ramp, Vec3::Zero(), turn);
  const BodyState ball_at = placed(rolling, (0.1 + r) * n - 1.5 * down);
  for (const bool ramp_first : {true, false}) {
    std::vector<BodyModel> models =
        ramp_first ? std::vector{ramp, rolling} : std::vector{rolling, ramp};
    std::vector<BodyState> start =
        ramp_first ? std::vector{ramp_at, ball_at} : std::vector{ball_at, ramp_at};
    sim::Simulation world(models, start, Integrator::rk4, kStep);
    const std::size_t b = ramp_first ? 1 : 0, s = 1 - b;
    while (world.time() < 1.0 - 1e-12) world.step();
    const BodyState& end = world.current()[b];
    const double travelled = (end.position() - ball_at.position()).dot(down);
    const double a = 2.0 * travelled / (world.time() * world.time());
    const double expected = 5.0 / 7.0 * kG * std::sin(theta);
    std::printf("[ measured ] ramp %s: a = %.6f m/s² (5/7 g sin θ = %.6f)\n",
                ramp_first ? "first" : "last", a, expected);
    EXPECT_NEAR(a, expected, 0.005 * expected);
    EXPECT_NEAR((end.position() - (0.1 + r) * n).dot(n), 0.0, 1e-6);  // on the surface
    EXPECT_EQ(world.current()[s].position(), ramp_at.position());
    EXPECT_EQ(world.current()[s].orientation().coeffs(), ramp_at.orientation().coeffs());
  }
}

// A cube and a ball dropped onto a static table come to rest on it: after 5 s they stand still
// (1e-6 m over the last second) on its top; the table has not moved.
TEST(StaticBody, BodiesComeToRestOnAStaticTable) {
  const BodyModel table = fixed_box(Vec3(3.0, 0.1, 3.0), 0.5);
  BodyModel cube{.constants = cube_constants(1.0, 0.4),
                 .forces = {Gravity{.acceleration = Vec3(0.0, -kG, 0.0)}},
                 .shape = box_shape(Vec3::Constant(0.2)),
                 .material = {.restitution = 0.2, .friction = 0.5}};
  const BodyModel rolling = ball(0.15, 0.5, 0.5);
  sim::Simulation world(
      {cube, table, rolling},
      {placed(cube, Vec3(-0.5, 1.0, 0.0), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 0, 1).normalized()))),
       placed(table, Vec3(0.0, 0.5, 0.0)), placed(rolling, Vec3(0.6, 1.2, 0.3))},
      Integrator::rk4, kStep, {}, {.sleep = false});
  while (world.time() < 4.0 - 1e-12) world.step();
  const std::vector<BodyState> at_four = world.current();
  while (world.time() < 5.0 - 1e-12) world.step();
  const std::vector<BodyState>& s = world.current();
  std::printf(
      "[ measured ] cube y %.6f (top 0.55 + 0.2), ball y %.6f (0.55 + 0.15); moved %.1e, %.1e m\n",
      s[0].position().y(), s[2].position().y(), (s[0].position() - at_four[0].position()).norm(),
      (s[2].position() - at_four[2].position()).norm());
  EXPECT_NEAR(s[0].position().y(), 0.75, 1e-3);
  EXPECT_NEAR(s[2].position().y(), 0.70, 1e-3);
  EXPECT_LT((s[0].position() - at_four[0].position()).norm(), 1e-6);
  EXPECT_LT((s[2].position() - at_four[2].position()).norm(), 1e-6);
  EXPECT_EQ(s[1].position(), Vec3(0.0, 0.5, 0.0));
}

// Rolling resistance holds in a sub-stepped island: a ball rolling at 2 m/s on a static slab
// (3.3 cm a step: its island is sub-stepped) stops at 7 r v² / (10 c g) within 2%, as on a plane.
TEST(StaticBody, RollingResistanceStopsABallOnAStaticSlab) {
  const double r = 0.2, v = 2.0, c = 0.01;
  BodyModel rolling = ball(r, 1.0, 0.5);
  rolling.material.rolling_resistance = c;
  const BodyModel slab = fixed_box(Vec3(40.0, 0.2, 4.0), 0.5);
  sim::Simulation world({slab, rolling},
                        {placed(slab, Vec3(15.0, -0.1, 0.0)),
                         make_state(rolling.constants, Vec3(0.0, r, 0.0), Vec3(v, 0.0, 0.0),
                                    Quat::Identity(), Vec3(0.0, 0.0, -v / r))},
                        Integrator::rk4, kStep, {}, {.sleep = false});
  const double distance = 7.0 * r * v * v / (10.0 * c * kG);
  while (world.time() < 9.0) world.step();
  const BodyState& s = world.current()[1];
  std::printf("[ measured ] rolled %.4f m on the slab (closed form %.4f), then %.1e m/s\n",
              s.position().x(), distance, s.velocity().norm());
  EXPECT_NEAR(s.position().x(), distance, 0.02 * distance);
  EXPECT_LT(s.velocity().norm(), 1e-6);
}

// A 5 cm ball at 100 m/s (1.7 m a step) against a 2 cm static plate: it stops there.
TEST(StaticBody, AFastBallDoesNotTunnelThroughAThinStaticPlate) {
  BodyModel bullet = ball(0.025, 0.1, 0.5);
  bullet.forces.clear();
  const BodyModel plate = fixed_box(Vec3(0.02, 2.0, 2.0), 0.5);
  sim::Simulation world({bullet, plate},
                        {placed(bullet, Vec3(-3.0, 0.3, 0.1), Quat::Identity(), Vec3(100.0, 0, 0)),
                         placed(plate, Vec3::Zero())},
                        Integrator::rk4, kStep);
  double furthest = -10.0;
  while (world.time() < 0.5) {
    world.step();
    furthest = std::max(furthest, world.current()[0].position().x());
  }
  std::printf("[ measured ] the ball got to x = %.6f m (the plate's face at -0.01)\n", furthest);
  EXPECT_LT(furthest, -0.01 - 0.025 + 1e-3);
}

}  // namespace
}  // namespace tumble::physics
