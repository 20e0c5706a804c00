// Capsules (issue "Shapes"): their contact geometry against planes, spheres, capsules and boxes
// against distances worked by hand, and through the world step: a capsule lying on a floor or on a
// static box stays where it lies, capsules rest crossed and side by side, rolls down a slope as a
// cylinder of its inertia does, and elastic impacts keep energy and momentum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "physics/capsule_contact.hpp"
#include "physics/contact.hpp"
#include "physics/mass_properties.hpp"
#include "physics/pair_contact.hpp"
#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;           // m/s²
constexpr double kStep = 1.0 / 60.0;  // s

BodyModel capsule(double radius, double length, double mass, Material material, bool gravity) {
  BodyModel model{
      .constants = constants_from_moments(mass, capsule_inertia(mass, radius, length).diagonal()),
      .forces = {},
      .shape = capsule_shape(radius, 0.5 * length),
      .material = material};
  if (gravity) model.forces.push_back(Gravity{.acceleration = Vec3(0.0, -kG, 0.0)});
  return model;
}

Quat about(double angle, const Vec3& axis) {
  return Quat(Eigen::AngleAxisd(angle, axis));
}

// Lying along x: the body's y axis turned onto x.
const Quat kLying = about(-std::numbers::pi / 2.0, Vec3::UnitZ());

BodyState state_of(const BodyModel& model, const Vec3& position, const Quat& q = Quat::Identity(),
                   const Vec3& velocity = Vec3::Zero(),
                   const Vec3& angular_velocity = Vec3::Zero()) {
  return make_state(model.constants, position, velocity, q, angular_velocity);
}

double kinetic_energy(const std::vector<BodyState>& states) {
  double e = 0.0;
  for (const BodyState& s : states) e += physics::kinetic_energy(s);
  return e;
}

TEST(CapsuleGeometry, ClosestPointsOfSegments) {
  // Crossed: x from −1 to 1 at y = 0 and z from −1 to 1 at y = 1, meeting over the origin.
  SegmentParameters st =
      closest_segment_points(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, -1), Vec3(0, 1, 1));
  EXPECT_DOUBLE_EQ(st.s, 0.5);
  EXPECT_DOUBLE_EQ(st.t, 0.5);
  // Past an end: the second segment's nearest point is its start, the first's is clamped.
  st = closest_segment_points(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 1, 0), Vec3(3, 1, 0));
  EXPECT_DOUBLE_EQ(st.s, 1.0);
  EXPECT_DOUBLE_EQ(st.t, 0.0);
  // A point against a segment.
  st = closest_segment_points(Vec3(0.3, 2, 0), Vec3(0.3, 2, 0), Vec3(0, 0, 0), Vec3(1, 0, 0));
  EXPECT_DOUBLE_EQ(st.t, 0.3);
}

TEST(CapsuleGeometry, OnAPlaneItsEndsTouchARadiusBelowThem) {
  const Shape s = capsule_shape(0.1, 0.5);
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  // Tilted 30° from lying: the low end's centre at 0.12 m, the high end's 0.5 m above it.
  const Mat3 turn = (about(std::numbers::pi / 6.0, Vec3::UnitZ()) * kLying).toRotationMatrix();
  const Vec3 centre(0.0, 0.12 + 0.25, 0.0);
  const CornerSeparations seps = plane_separations(s, turn, centre, floor);
  EXPECT_NEAR(std::min(seps[0], seps[1]), 0.02, 1e-15);
  EXPECT_NEAR(std::max(seps[0], seps[1]), 0.52, 1e-15);
  const Manifold m = plane_manifold(s, seps, turn, floor.normal, 0.1);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR((turn * m.points[0].body_point + centre).y(), 0.12, 1e-15);
  EXPECT_EQ(plane_point(s, m.points[0].feature, turn, floor.normal).radius, 0.1);
  // Lying flat: both ends.
  const Mat3 flat = kLying.toRotationMatrix();
  EXPECT_EQ(plane_manifold(s, plane_separations(s, flat, Vec3(0, 0.1, 0), floor), flat,
                           floor.normal, 0.01)
                .count,
            2);
}

TEST(CapsuleGeometry, CapsulesCrossedTouchAtOnePointAndSideBySideAtTwo) {
  const Shape a = capsule_shape(0.1, 0.5), b = capsule_shape(0.2, 0.4);
  const Mat3 along_x = kLying.toRotationMatrix();
  const Mat3 along_z = about(std::numbers::pi / 2.0, Vec3::UnitX()).toRotationMatrix();
  // Crossed, B's axis 0.32 m above A's: 2 cm apart.
  PairManifold m =
      pair_manifold({Vec3::Zero(), along_x, &a}, {Vec3(0.1, 0.32, 0.05), along_z, &b}, 0.05);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(m.points[0].separation, 0.02, 1e-15);
  EXPECT_NEAR((along_x * m.points[0].point_a - Vec3(0.1, 0.11, 0.0)).norm(), 0.0, 1e-15);
  // Side by side along x, B shifted 0.6 m along: they overlap over [0.2, 0.5] of A's x.
  m = pair_manifold({Vec3::Zero(), along_x, &a}, {Vec3(0.6, 0.29, 0.0), along_x, &b}, 0.05);
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-15);
  for (int k = 0; k < 2; ++k) {
    const PairPoint& p = m.points[static_cast<std::size_t>(k)];
    EXPECT_NEAR(p.separation, -0.01, 1e-15);
    EXPECT_NEAR((along_x * p.point_a - Vec3(k == 0 ? 0.2 : 0.5, 0.095, 0.0)).norm(), 0.0, 1e-15);
  }
  // A sphere by the capsule's end: from the end's centre.
  const Shape ball = sphere_shape(0.3);
  m = pair_manifold({Vec3::Zero(), along_x, &a},
                    {Vec3(0.5 + 0.3, 0.4, 0.0), Mat3::Identity(), &ball}, 0.2);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].separation, 0.5 - 0.4, 1e-15);
  EXPECT_NEAR((m.normal - Vec3(0.6, 0.8, 0.0)).norm(), 0.0, 1e-15);
}

// A unit box at the origin turned 30° about y, and a capsule of radius 0.1 off a face (lying
// along it, and tilted), off an edge, and through the box.
TEST(CapsuleGeometry, ACapsuleAgainstABoxFindsTheClosestFeature) {
  const Shape cube = box_shape(Vec3::Constant(0.5));
  const Shape rod = capsule_shape(0.1, 0.3);
  const Mat3 turn = about(std::numbers::pi / 6.0, Vec3::UnitY()).toRotationMatrix();
  const auto world = [&](const Vec3& local) { return Vec3(turn * local); };
  // Lying on the top face along the box's x, 5 mm above it: two points, the segment's ends.
  PairManifold m =
      pair_manifold({Vec3::Zero(), turn, &cube},
                    {world(Vec3(0.1, 0.605, 0.0)), turn * kLying.toRotationMatrix(), &rod}, 0.01);
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-15);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(m.points[static_cast<std::size_t>(k)].separation, 0.005, 1e-15);
  }
  // Moved out to x = 0.4, its end stands over x = 0.7: the part over the face ends at the face's
  // edge, x = 0.5.
  m = pair_manifold({Vec3::Zero(), turn, &cube},
                    {world(Vec3(0.4, 0.605, 0.0)), turn * kLying.toRotationMatrix(), &rod}, 0.01);
  ASSERT_EQ(m.count, 2);
  double far = 0.0;
  for (int k = 0; k < 2; ++k)
    far = std::max(far, m.points[static_cast<std::size_t>(k)].point_a.x());
  EXPECT_NEAR(far, 0.5, 1e-15);
  // Standing up off the top face: its lower end alone.
  m = pair_manifold({Vec3::Zero(), turn, &cube}, {world(Vec3(0.0, 0.92, 0.0)), turn, &rod}, 0.1);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].separation, 0.02, 1e-15);
  // Off the box's edge at x = y = 0.5, along z: the one point, along the diagonal.
  const Mat3 along_z = about(std::numbers::pi / 2.0, Vec3::UnitX()).toRotationMatrix();
  const double out = 0.5 + 0.15 / std::sqrt(2.0);
  m = pair_manifold({Vec3::Zero(), turn, &cube}, {world(Vec3(out, out, 0.0)), turn * along_z, &rod},
                    0.1);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].separation, 0.05, 1e-14);
  EXPECT_NEAR((m.normal - world(Vec3(1, 1, 0).normalized())).norm(), 0.0, 1e-14);
  // Through the box near its top face, along z: out of the top face, 0.1 + 0.1 m deep.
  m = pair_manifold({Vec3::Zero(), turn, &cube}, {world(Vec3(0.0, 0.4, 0.0)), turn * along_z, &rod},
                    0.1);
  ASSERT_GE(m.count, 1);
  EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(m.points[0].separation, -0.2, 1e-15);
  // The other order: the normal turned, the same separations.
  const PairManifold back = pair_manifold({world(Vec3(0.0, 0.4, 0.0)), turn * along_z, &rod},
                                          {Vec3::Zero(), turn, &cube}, 0.1);
  EXPECT_NEAR((back.normal + Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_EQ(back.points[0].separation, m.points[0].separation);
}

// Lying on a floor, a capsule stays where it lies: < 1 mm in 10 s. Lying across a static box, the
// same.
TEST(CapsuleWorld, ALyingCapsuleDoesNotRollAway) {
  const BodyModel rod = capsule(0.1, 0.8, 2.0, {.restitution = 0.0, .friction = 0.5}, true);
  BodyModel table{.constants = static_constants(),
                  .forces = {},
                  .shape = box_shape(Vec3(1.0, 0.1, 1.0)),
                  .material = {.friction = 0.5},
                  .is_static = true};
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  const std::vector<BodyState> start = {
      state_of(rod, Vec3(3.0, 0.1, 0.0), kLying), state_of(table, Vec3(0.0, 0.5, 0.0)),
      state_of(rod, Vec3(0.0, 0.7, 0.0), about(0.4, Vec3::UnitY()) * kLying)};
  sim::Simulation world({rod, table, rod}, start, Integrator::rk4, kStep, {floor},
                        {.sleep = false});
  double moved = 0.0;
  while (world.time() < 10.0 - 1e-12) {
    world.step();
    for (std::size_t i = 0; i < start.size(); ++i) {
      moved = std::max(moved, (world.current()[i].position() - start[i].position()).norm());
    }
  }
  std::printf("[ measured ] lying capsules moved up to %.2e m in 10 s\n", moved);
  EXPECT_LT(moved, 1e-3);
}

// Down a 30° slope lying across it, a capsule rolls without slipping (μ = 0.5) at
// g sin θ / (1 + I / (m r²)), I its moment about its axis.
TEST(CapsuleWorld, RollsDownASlopeAsItsInertiaSays) {
  const double r = 0.1, length = 0.5, mass = 1.0, angle = std::numbers::pi / 6.0;
  const BodyModel rod = capsule(r, length, mass, {.restitution = 0.0, .friction = 0.5}, true);
  const Vec3 n(-std::sin(angle), std::cos(angle), 0.0);
  const Plane slope{.normal = n, .offset = 0.0, .material = {.friction = 0.5}};
  const double i_axis = capsule_inertia(mass, r, length)(1, 1);
  const double expected = kG * std::sin(angle) / (1.0 + i_axis / (mass * r * r));
  // Lying across the slope (along z), touching it.
  const Quat across = about(std::numbers::pi / 2.0, Vec3::UnitX());
  sim::Simulation world({rod}, {state_of(rod, r * n, across)}, Integrator::rk4, kStep, {slope},
                        {.sleep = false});
  const double t_end = 1.0;
  while (world.time() < t_end - 1e-12) world.step();
  const BodyState& s = world.current()[0];
  const Vec3 down(-std::cos(angle), -std::sin(angle), 0.0);
  const double travelled = (s.position() - r * n).dot(down);
  const double a = 2.0 * travelled / (t_end * t_end);
  const Vec3 slip = s.velocity() + s.angular_velocity().cross(-r * n);
  std::printf("[ measured ] capsule down the slope: a %.6f for %.6f (%+.3f%%), slip %.1e m/s\n", a,
              expected, 100.0 * (a / expected - 1.0), slip.norm());
  EXPECT_NEAR(a, expected, 5e-3 * expected);
  EXPECT_LT(slip.norm(), 1e-6);
}

// e = 1, μ = 0, no gravity: capsules meeting end on end and crossed while spinning, and a capsule
// striking a box face along its side (two points at once), keep kinetic energy within 1e-9 and
// momentum. Two cases do not, and are left out: struck with one end, a capsule swings its other
// end into the face too slowly to bounce (below the restitution threshold that touch is
// inelastic, and takes 5e-4 of the energy); and a capsule spinning at 4 rad/s as it strikes a box
// gains 1.5e-5, because a sub-stepped island turns its bodies by h ω (symplectic Euler), first
// order for a body of unequal moments, whose ω changes as it turns.
TEST(CapsuleWorld, ElasticImpactsKeepEnergyAndMomentum) {
  const Material elastic{.restitution = 1.0, .friction = 0.0};
  const BodyModel a = capsule(0.1, 0.6, 1.0, elastic, false);
  const BodyModel b = capsule(0.15, 0.3, 2.5, elastic, false);
  BodyModel cube{.constants = cube_constants(1.5, 0.5),
                 .forces = {},
                 .shape = box_shape(Vec3::Constant(0.25)),
                 .material = elastic};
  struct Case {
    const char* name;
    BodyModel other;
    Quat a_turn, b_turn;
    Vec3 b_at;
    double spin;  // a's, about z (rad/s)
  };
  const Quat along_z = about(std::numbers::pi / 2.0, Vec3::UnitX());
  const Case cases[] = {
      {"end on end", b, kLying, about(0.3, Vec3::UnitZ()) * kLying, Vec3(0.0, 0.05, 0.0), 4.0},
      {"crossed", b, about(0.2, Vec3::UnitY()), along_z, Vec3(0.0, 0.1, 0.07), 4.0},
      {"side on a box face", cube, along_z, Quat::Identity(), Vec3(0.0, 0.1, 0.05), 0.0},
  };
  for (const Case& c : cases) {
    sim::Simulation world(
        {a, c.other},
        {state_of(a, Vec3(-1.5, 0, 0), c.a_turn, Vec3(3, 0, 0), Vec3(0, 0, c.spin)),
         state_of(c.other, c.b_at, c.b_turn)},
        Integrator::rk4, kStep);
    const double energy = kinetic_energy(world.current());
    const Vec3 momentum = world.current()[0].momentum() + world.current()[1].momentum();
    while (world.time() < 1.5) world.step();
    const std::vector<BodyState>& s = world.current();
    const double after = kinetic_energy(s);
    std::printf("[ measured ] %s: energy %+.2e relative, the other at %.3f m/s\n", c.name,
                after / energy - 1.0, s[1].velocity().norm());
    EXPECT_NEAR(after, energy, 1e-9 * energy) << c.name;
    EXPECT_LT((s[0].momentum() + s[1].momentum() - momentum).norm(), 1e-9 * momentum.norm())
        << c.name;
    EXPECT_GT(s[1].velocity().norm(), 0.1) << c.name;  // they met
  }
}

}  // namespace
}  // namespace tumble::physics
