// Spheres (issue "Shapes"): their contact geometry with planes, spheres and boxes, and through the
// world step against closed forms — bounce apexes, rolling down a slope with and without slipping,
// rolling on a floor for ever, and elastic impacts that keep energy and momentum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "physics/contact.hpp"
#include "physics/mass_properties.hpp"
#include "physics/pair_contact.hpp"
#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;           // m/s²
constexpr double kStep = 1.0 / 60.0;  // s

BodyModel ball(double radius, double mass, Material material, bool gravity) {
  BodyModel model{.constants = sphere_constants(mass, radius),
                  .forces = {},
                  .shape = sphere_shape(radius),
                  .material = material};
  if (gravity) model.forces.push_back(Gravity{.acceleration = Vec3(0.0, -kG, 0.0)});
  return model;
}

BodyState state_of(const BodyModel& model, const Vec3& position,
                   const Vec3& velocity = Vec3::Zero(),
                   const Vec3& angular_velocity = Vec3::Zero()) {
  return make_state(model.constants, position, velocity, Quat::Identity(), angular_velocity);
}

double kinetic_energy(const std::vector<BodyState>& states) {
  double e = 0.0;
  for (const BodyState& s : states) {
    e += 0.5 * (s.momentum().dot(s.velocity()) + s.angular_momentum().dot(s.angular_velocity()));
  }
  return e;
}

TEST(SphereGeometry, TwoSpheresTouchAtTheMiddleOfTheirGap) {
  const Shape a = sphere_shape(0.5), b = sphere_shape(0.25);
  const Mat3 turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const PairManifold m =
      pair_manifold({Vec3(1, 0, 0), Mat3::Identity(), &a}, {Vec3(1, 0.8, 0), turn, &b}, 0.1);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(m.points[0].separation, 0.05, 1e-15);
  EXPECT_NEAR((m.points[0].point_a - Vec3(0, 0.525, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((turn * m.points[0].point_b - Vec3(0, -0.275, 0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(
      pair_manifold({Vec3(1, 0, 0), Mat3::Identity(), &a}, {Vec3(1, 0.8, 0), turn, &b}, 0.05).count,
      0);  // 5 cm apart: beyond a 5 cm margin
}

// A unit cube at the origin, turned 30° about y, and a ball of radius 0.2 off a face, an edge, a
// corner, and with its centre inside near the top face.
TEST(SphereGeometry, ABallAgainstABoxFindsTheClosestFeature) {
  const Shape cube = box_shape(Vec3::Constant(0.5)), small = sphere_shape(0.2);
  const Mat3 turn = Eigen::AngleAxisd(std::numbers::pi / 6, Vec3::UnitY()).toRotationMatrix();
  const auto contact = [&](const Vec3& local_centre, double margin) {
    return pair_manifold({Vec3::Zero(), turn, &cube},
                         {turn * local_centre, Mat3::Identity(), &small}, margin);
  };
  const PairManifold face = contact(Vec3(0.1, 0.8, -0.2), 1.0);
  ASSERT_EQ(face.count, 1);
  EXPECT_NEAR((face.normal - turn * Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(face.points[0].separation, 0.1, 1e-15);
  EXPECT_NEAR((face.points[0].point_a - Vec3(0.1, 0.55, -0.2)).norm(), 0.0, 1e-15);
  const PairManifold edge = contact(Vec3(0.8, 0.9, 0.0), 1.0);
  ASSERT_EQ(edge.count, 1);
  EXPECT_NEAR(edge.points[0].separation, 0.5 - 0.2, 1e-15);
  EXPECT_NEAR((edge.normal - turn * Vec3(0.6, 0.8, 0.0)).norm(), 0.0, 1e-15);
  const PairManifold corner = contact(Vec3(0.6, 0.6, 0.6), 1.0);
  EXPECT_NEAR(corner.points[0].separation, std::sqrt(0.03) - 0.2, 1e-15);
  EXPECT_NE(corner.points[0].feature, edge.points[0].feature);
  const PairManifold inside = contact(Vec3(0.1, 0.45, 0.0), 0.0);
  ASSERT_EQ(inside.count, 1);
  EXPECT_NEAR((inside.normal - turn * Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(inside.points[0].separation, -0.05 - 0.2, 1e-15);
  // The other way round: the normal turned, the anchors swapped.
  const PairManifold back = pair_manifold({turn * Vec3(0.1, 0.8, -0.2), Mat3::Identity(), &small},
                                          {Vec3::Zero(), turn, &cube}, 1.0);
  EXPECT_NEAR((back.normal + face.normal).norm(), 0.0, 1e-15);
  EXPECT_EQ(back.points[0].point_b, face.points[0].point_a);
}

TEST(SphereGeometry, ABallOnAPlaneTouchesBelowItsCentre) {
  const Shape s = sphere_shape(0.3);
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  const Mat3 turn = Eigen::AngleAxisd(1.1, Vec3(1, 1, 0).normalized()).toRotationMatrix();
  const CornerSeparations seps = plane_separations(s, turn, Vec3(2, 0.35, 1), floor);
  EXPECT_NEAR(seps[0], 0.05, 1e-15);
  const Manifold m = plane_manifold(s, seps, turn, floor.normal, 0.1);
  ASSERT_EQ(m.count, 1);
  // The point is the core's (the centre): it touches the radius below it, whichever way it turned.
  EXPECT_EQ(m.points[0].body_point, Vec3::Zero());
  EXPECT_EQ(plane_point(s, m.points[0].feature, turn, floor.normal).radius, 0.3);
  EXPECT_EQ(plane_manifold(s, seps, turn, floor.normal, 0.04).count, 0);
}

// Dropped from 1 m (its lowest point) with e = 0.5 onto a floor of e = 0.5: the n-th bounce rises
// to e^(2n) m. Each apex is read from the flight after the bounce, exactly: y + v²/(2g).
TEST(SphereWorld, BounceApexesFollowTheRestitution) {
  const double r = 0.1;
  const BodyModel model = ball(r, 1.0, {.restitution = 0.5, .friction = 0.5}, true);
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0, .material = {.restitution = 0.5}};
  sim::Simulation world({model}, {state_of(model, Vec3(0, 1.0 + r, 0))}, Integrator::rk4, kStep,
                        {floor});
  std::vector<double> apexes;
  bool rising = false;
  while (world.time() < 4.0 && apexes.size() < 3) {
    world.step();
    const BodyState& s = world.current()[0];
    const double apex = s.position().y() - r + s.velocity().y() * s.velocity().y() / (2 * kG);
    if (!rising && s.velocity().y() > 0.0 && s.position().y() - r > 1e-3) {
      apexes.push_back(apex);
      rising = true;
    }
    if (s.velocity().y() < 0.0) rising = false;
  }
  ASSERT_EQ(apexes.size(), 3u);
  for (std::size_t n = 0; n < 3; ++n) {
    const double expected = std::pow(0.5, 2.0 * (n + 1));
    std::printf("[ measured ] apex %zu: %.6f m (e^2n: %.6f)\n", n + 1, apexes[n], expected);
    EXPECT_NEAR(apexes[n], expected, 0.01 * expected);
  }
}

// A ball let go on a 30° slope. With μ = 0.5 (more than 2/7 tan 30° = 0.165) it rolls without
// slipping: a = 5/7 g sin θ, its contact point still; with μ = 0.05 it slips: a = g (sin θ − μ cos
// θ).
TEST(SphereWorld, RollsDownASlopeAtFiveSeventhsOrSlips) {
  const double theta = std::numbers::pi / 6, r = 0.25;
  const Vec3 n(std::sin(theta), std::cos(theta), 0.0), down(std::cos(theta), -std::sin(theta), 0.0);
  for (const double mu : {0.5, 0.05}) {
    const BodyModel model = ball(r, 2.0, {.restitution = 0.0, .friction = mu}, true);
    const Plane slope{.normal = n, .offset = 0.0, .material = {.friction = mu}};
    sim::Simulation world({model}, {state_of(model, r * n)}, Integrator::rk4, kStep, {slope});
    double slip = 0.0;
    while (world.time() < 2.0 - 1e-12) {
      world.step();
      const BodyState& s = world.current()[0];
      slip = std::max(slip, (s.velocity() + s.angular_velocity().cross(-r * n)).norm());
    }
    const BodyState& s = world.current()[0];
    const double travelled = (s.position() - r * n).dot(down), t = world.time();
    const double a = 2.0 * travelled / (t * t);
    const double expected =
        mu > 0.2 ? 5.0 / 7.0 * kG * std::sin(theta) : kG * (std::sin(theta) - mu * std::cos(theta));
    std::printf("[ measured ] mu %.2f: a = %.6f m/s² (closed form %.6f), slip up to %.2e m/s\n", mu,
                a, expected, slip);
    EXPECT_NEAR(a, expected, 0.005 * expected);
    EXPECT_LT(std::abs(s.position().dot(n) - r), 1e-6);  // on the surface
    if (mu > 0.2) {
      EXPECT_LT(slip, 1e-6);
    }
  }
}

// Rolling on a flat floor at 2 m/s (ω = v/r, no rolling resistance): no force along the floor,
// so the speed stays, within 1e-6 relative over 10 s.
TEST(SphereWorld, RollsOnAFloorWithoutLosingSpeed) {
  const double r = 0.2, v = 2.0;
  const BodyModel model = ball(r, 1.0, {.restitution = 0.0, .friction = 0.5}, true);
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  sim::Simulation world({model},
                        {state_of(model, Vec3(0, r, 0), Vec3(v, 0, 0), Vec3(0, 0, -v / r))},
                        Integrator::rk4, kStep, {floor});
  while (world.time() < 10.0 - 1e-12) world.step();
  const BodyState& s = world.current()[0];
  std::printf("[ measured ] after 10 s: %.12f m/s, height %.3e m off\n", s.velocity().x(),
              s.position().y() - r);
  EXPECT_NEAR(s.velocity().x(), v, 1e-6 * v);
  EXPECT_NEAR(s.position().x(), 10.0 * v, 1e-5);
  EXPECT_NEAR(s.position().y(), r, 1e-6);
}

// With rolling resistance c (m), a ball rolling without slipping on a floor slows at
// 5 c g / (7 r) (the torque c N against its turning, shared with its mass through the rolling
// constraint), so from v it rolls 7 r v² / (10 c g) and stops: within 2%, and at rest after.
TEST(SphereWorld, RollingResistanceStopsABallAtTheClosedFormDistance) {
  const double r = 0.2, v = 2.0;
  for (const double c : {0.002, 0.01}) {
    BodyModel model = ball(r, 1.0, {.restitution = 0.0, .friction = 0.5}, true);
    model.material.rolling_resistance = c;
    const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
    sim::Simulation world({model},
                          {state_of(model, Vec3(0, r, 0), Vec3(v, 0, 0), Vec3(0, 0, -v / r))},
                          Integrator::rk4, kStep, {floor}, {.sleep = false});
    const double distance = 7.0 * r * v * v / (10.0 * c * kG),
                 stop = v / (5.0 * c * kG / (7.0 * r));
    while (world.time() < stop + 2.0) world.step();
    const BodyState& s = world.current()[0];
    std::printf("[ measured ] c = %.3f m: rolled %.4f m (closed form %.4f), then %.1e m/s\n", c,
                s.position().x(), distance, s.velocity().norm());
    EXPECT_NEAR(s.position().x(), distance, 0.02 * distance);
    EXPECT_LT(s.velocity().norm(), 1e-6);
    EXPECT_LT(s.angular_velocity().norm(), 1e-6);
  }
}

// The same for two balls rolling side by side, touching: their island is sub-stepped (each moves
// 3.3 cm a step) and their rows against the floor are kept through the sub-steps, so the rolling
// rows must start afresh in each (carried over, they held the balls back in the first sub-step
// alone, and the pair rolled 15.6 m, 2.7 times as far).
TEST(SphereWorld, RollingResistanceHoldsInASubSteppedIsland) {
  const double r = 0.2, v = 2.0, c = 0.01;
  BodyModel model = ball(r, 1.0, {.restitution = 0.0, .friction = 0.5}, true);
  model.material.rolling_resistance = c;
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  sim::Simulation world({model, model},
                        {state_of(model, Vec3(0, r, 0), Vec3(v, 0, 0), Vec3(0, 0, -v / r)),
                         state_of(model, Vec3(0, r, 2.0 * r), Vec3(v, 0, 0), Vec3(0, 0, -v / r))},
                        Integrator::rk4, kStep, {floor}, {.sleep = false});
  const double distance = 7.0 * r * v * v / (10.0 * c * kG);
  while (world.time() < 10.0) world.step();
  for (const BodyState& s : world.current()) {
    std::printf("[ measured ] rolled %.4f m side by side (closed form %.4f)\n", s.position().x(),
                distance);
    EXPECT_NEAR(s.position().x(), distance, 0.02 * distance);
  }
}

// Elastic (e = 1, μ = 0), no gravity: a ball meets one at rest head-on (they exchange velocities)
// and off-centre; energy and momentum are kept within 1e-9.
TEST(SphereWorld, ElasticImpactsKeepEnergyAndMomentum) {
  for (const double offset : {0.0, 0.3, 0.7}) {
    const BodyModel a = ball(0.5, 1.0, {.restitution = 1.0, .friction = 0.0}, false);
    const BodyModel b = ball(0.4, 2.5, {.restitution = 1.0, .friction = 0.0}, false);
    sim::Simulation world(
        {a, b}, {state_of(a, Vec3(-2, 0, 0), Vec3(3, 0, 0)), state_of(b, Vec3(0, offset, 0))},
        Integrator::rk4, kStep);
    const double energy = kinetic_energy(world.current());
    const Vec3 momentum = world.current()[0].momentum() + world.current()[1].momentum();
    while (world.time() < 2.0) world.step();
    const std::vector<BodyState>& s = world.current();
    const double after = kinetic_energy(s);
    std::printf("[ measured ] offset %.1f: energy %+.2e relative, b at %.3f m/s\n", offset,
                after / energy - 1.0, s[1].velocity().norm());
    EXPECT_NEAR(after, energy, 1e-9 * energy);
    EXPECT_LT((s[0].momentum() + s[1].momentum() - momentum).norm(), 1e-9 * momentum.norm());
    EXPECT_GT(s[1].velocity().norm(), 0.5);  // they met
    if (offset == 0.0) {                     // head-on: v_b = 2 m_a v / (m_a + m_b)
      EXPECT_NEAR(s[1].velocity().x(), 2.0 * 3.0 / 3.5, 1e-9);
    }
  }
}

// Three balls touching in a triangle on a floor, a fourth resting in the hollow on top (μ = 0.5):
// the pyramid stands 10 s, no ball moving more than 1 mm.
TEST(SphereWorld, APyramidOfFourBallsStands) {
  const double r = 0.25;
  const BodyModel model = ball(r, 1.0, {.restitution = 0.0, .friction = 0.5}, true);
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  std::vector<BodyState> start;
  for (int k = 0; k < 3; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / 3.0, out = 2.0 * r / std::sqrt(3.0);
    start.push_back(state_of(model, Vec3(out * std::cos(angle), r, out * std::sin(angle))));
  }
  start.push_back(state_of(model, Vec3(0.0, r + 2.0 * r * std::sqrt(2.0 / 3.0), 0.0)));
  sim::Simulation world(std::vector<BodyModel>(4, model), start, Integrator::rk4, kStep, {floor},
                        {.sleep = false});
  double moved = 0.0;
  while (world.time() < 10.0 - 1e-12) {
    world.step();
    for (std::size_t i = 0; i < 4; ++i) {
      moved = std::max(moved, (world.current()[i].position() - start[i].position()).norm());
    }
  }
  std::printf("[ measured ] the pyramid's balls moved up to %.2e m in 10 s\n", moved);
  EXPECT_LT(moved, 1e-3);
}

// Newton's cradle of five touching balls (e = 1, μ = 0, no gravity), struck end-on by a sixth:
// the far ball leaves with the striker's speed, the others stay.
TEST(SphereWorld, ACradleOfBallsPassesTheImpactOn) {
  const double r = 0.1, speed = 2.0;
  const BodyModel model = ball(r, 1.0, {.restitution = 1.0, .friction = 0.0}, false);
  std::vector<BodyState> start;
  start.push_back(state_of(model, Vec3(-0.5, 0, 0), Vec3(speed, 0, 0)));
  for (int k = 0; k < 5; ++k) start.push_back(state_of(model, Vec3(2.0 * r * k, 0, 0)));
  sim::Simulation world(std::vector<BodyModel>(6, model), start, Integrator::rk4, kStep);
  while (world.time() < 0.5) world.step();
  const std::vector<BodyState>& s = world.current();
  std::printf("[ measured ] cradle: striker %.4f, middle %.4f %.4f %.4f %.4f, far %.4f m/s\n",
              s[0].velocity().x(), s[1].velocity().x(), s[2].velocity().x(), s[3].velocity().x(),
              s[4].velocity().x(), s[5].velocity().x());
  EXPECT_GE(s[5].velocity().x(), 0.95 * speed);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_LE(std::abs(s[i].velocity().x()), 0.05 * speed);
}

// A 5 cm ball at 100 m/s (1.7 m a step) at a heavy box: it does not pass through.
TEST(SphereWorld, AFastBallDoesNotTunnelThroughABox) {
  const BodyModel bullet = ball(0.025, 0.1, {.restitution = 0.0, .friction = 0.5}, false);
  BodyModel wall{.constants = box_constants(1000.0, Vec3(0.02, 2.0, 2.0)),
                 .forces = {},
                 .shape = box_shape(Vec3(0.01, 1.0, 1.0)),
                 .material = {.restitution = 0.0, .friction = 0.5}};
  sim::Simulation world(
      {bullet, wall},
      {state_of(bullet, Vec3(-3.0, 0.1, 0.0), Vec3(100.0, 0, 0)),
       make_state(wall.constants, Vec3::Zero(), Vec3::Zero(), Quat::Identity(), Vec3::Zero())},
      Integrator::rk4, kStep);
  while (world.time() < 0.5) world.step();
  const BodyState& b = world.current()[0];
  const BodyState& w = world.current()[1];
  std::printf("[ measured ] ball at x = %.4f m, wall at %.4f m\n", b.position().x(),
              w.position().x());
  EXPECT_LT(b.position().x(), w.position().x() - 0.01 - 0.025 + 1e-3);
}

}  // namespace
}  // namespace tumble::physics
