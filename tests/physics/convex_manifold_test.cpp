// The contact of any two convex shapes (issue "Shapes"): GJK's distance and EPA's depth against
// distances worked by hand; the manifold of the hull of a box against a box as the boxes' own
// separating-axis test gives it; cylinders standing and lying on boxes, coins on coins, logs side
// by side, a capsule on a hull's face; and through the world step: a cylinder rolls down a static
// box at 2/3 g sin θ, a stack of coins stands, hull boxes stand in a tower, and two hull cubes
// exchange their speeds in an elastic impact.
#include "physics/convex_manifold.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "physics/gjk.hpp"
#include "physics/hull_shape.hpp"
#include "physics/mass_properties.hpp"
#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;
constexpr double kStep = 1.0 / 60.0;

Mat3 about(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

std::shared_ptr<const ConvexHull> hull_of_box(const Vec3& half) {
  std::vector<Vec3> corners;
  for (int k = 0; k < 8; ++k) corners.push_back(corner(half, k));
  return hull_body(corners, 1.0).value().hull;
}

// The manifold's points, world frame, with their separations, ordered.
std::vector<std::array<double, 4>> points_of(const PairManifold& m, const ShapePose& a) {
  std::vector<std::array<double, 4>> out;
  for (int k = 0; k < m.count; ++k) {
    const PairPoint& p = m.points[static_cast<std::size_t>(k)];
    const Vec3 w = a.position + a.rotation * p.point_a;
    out.push_back({p.separation, w.x(), w.y(), w.z()});
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ConvexGeometry, DistanceAndDepthOfACylinderOverABox) {
  const Shape table = box_shape(Vec3(2.0, 0.5, 2.0));
  const Shape can = cylinder_shape(0.3, 0.4);
  const ShapePose a{Vec3::Zero(), Mat3::Identity(), &table};
  for (const double tilt : {0.0, 0.2, 0.7, std::numbers::pi / 2.0}) {
    const Mat3 turn = about(tilt, Vec3(1, 0, 1));
    // The lowest point of the cylinder is h cos θ + r sin θ below its centre.
    const double below = 0.4 * std::cos(tilt) + 0.3 * std::sin(tilt);
    for (const double gap : {0.05, 1e-4, -1e-4, -0.02}) {
      const ShapePose b{Vec3(0.1, 0.5 + below + gap, -0.2), turn, &can};
      const CoreDistance d = core_distance(a, b);
      EXPECT_NEAR(d.distance, gap, 1e-8) << "tilt " << tilt << " gap " << gap;
      EXPECT_NEAR((d.normal - Vec3::UnitY()).norm(), 0.0, 1e-6) << tilt << " " << gap;
      const PairManifold m = convex_manifold(a, b, 0.1);
      ASSERT_GE(m.count, 1);
      double deepest = 1.0;
      int touching = 0;
      for (int k = 0; k < m.count; ++k) {
        const double s = m.points[static_cast<std::size_t>(k)].separation;
        deepest = std::min(deepest, s);
        if (s < gap + 1e-9) ++touching;
      }
      EXPECT_NEAR(deepest, gap, 1e-9);
      // Standing: the four rim points of its lower end; lying: its lowest line; else one point
      // (and, within the margin, speculative ones higher on the rim).
      const int expected = tilt == 0.0 ? 4 : tilt == std::numbers::pi / 2.0 ? 2 : 1;
      EXPECT_EQ(touching, expected) << "tilt " << tilt << " gap " << gap;
      EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-12);
    }
  }
}

// A smaller box over a larger one, turned about the vertical, tilted a little, apart or sunk in:
// the hull of its corners gives the same normal, separations and points as the box itself
// (box_box_manifold), in either role.
TEST(ConvexGeometry, TheHullOfABoxTouchesABoxAsTheBoxDoes) {
  const Vec3 big(1.0, 0.3, 0.8), small(0.3, 0.2, 0.25);
  const Shape base = box_shape(big), top = box_shape(small);
  const Shape base_hull = hull_shape(hull_of_box(big));
  const Shape top_hull = hull_shape(hull_of_box(small));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int cases = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Mat3 turn = about(3.0 * unit(random), Vec3::UnitY()) *
                      about(0.05 * unit(random), Vec3(unit(random), 0.0, unit(random)));
    const Vec3 at(0.4 * unit(random), 0.3 + 0.2 + 0.01 * unit(random), 0.3 * unit(random));
    const BoxPose box_a{Vec3::Zero(), Mat3::Identity(), big}, box_b{at, turn, small};
    const PairManifold expected = box_box_manifold(box_a, box_b, 0.05);
    if (expected.count == 0) continue;
    ++cases;
    const ShapePose a{Vec3::Zero(), Mat3::Identity(), &base}, b{at, turn, &top};
    const ShapePose ha{Vec3::Zero(), Mat3::Identity(), &base_hull}, hb{at, turn, &top_hull};
    for (const auto& [first, second] : {std::pair{ha, b}, std::pair{a, hb}, std::pair{ha, hb}}) {
      const PairManifold m = convex_manifold(first, second, 0.05);
      ASSERT_EQ(m.count, expected.count) << "trial " << trial;
      EXPECT_NEAR((m.normal - expected.normal).norm(), 0.0, 1e-12) << "trial " << trial;
      const auto got = points_of(m, first), want = points_of(expected, first);
      for (std::size_t k = 0; k < got.size(); ++k) {
        for (int c = 0; c < 4; ++c) {
          EXPECT_NEAR(got[k][static_cast<std::size_t>(c)], want[k][static_cast<std::size_t>(c)],
                      1e-12)
              << "trial " << trial << " point " << k;
        }
      }
    }
    // Swapped, as the boxes swapped.
    const PairManifold back = convex_manifold(b, ha, 0.05);
    const PairManifold boxes_back = box_box_manifold(box_b, box_a, 0.05);
    ASSERT_EQ(back.count, boxes_back.count);
    EXPECT_NEAR((back.normal - boxes_back.normal).norm(), 0.0, 1e-12);
  }
  EXPECT_GT(cases, 150);
}

// Any two of a box, a capsule, a cylinder and a hull (an irregular one of 12 corners), placed at
// random near each other: where the cores are apart, GJK's nearest points are that far apart along
// the normal; where they overlap, moving B by EPA's depth and 1 µm along its normal leaves them
// 1 µm apart within 10 µm (for polytopes and mostly to 1e-9: the slack is for a curved cylinder
// whose difference needs more corners than EPA's 132; one in 20000 pairs), and by 1 µm less leaves
// them overlapping. Nothing is NaN.
TEST(ConvexGeometry, GjkAndEpaAgreeForEveryPairAtRandom) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> corners;
  for (int k = 0; k < 12; ++k) {
    corners.push_back(Vec3(0.4 * unit(random), 0.3 * unit(random), 0.5 * unit(random)));
  }
  const Shape shapes[] = {box_shape(Vec3(0.3, 0.2, 0.4)), capsule_shape(0.15, 0.3),
                          cylinder_shape(0.25, 0.2),
                          hull_shape(hull_body(corners, 1.0).value().hull)};
  const auto turn = [&] {
    return Mat3(Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random))
                    .normalized()
                    .toRotationMatrix());
  };
  int apart = 0, overlapping = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    const Shape& sa = shapes[trial % 4];
    const Shape& sb = shapes[(trial / 4) % 4];
    if (sa.kind == ShapeKind::capsule && sb.kind == ShapeKind::capsule) continue;
    const ShapePose a{Vec3::Zero(), turn(), &sa};
    ShapePose b{0.6 * Vec3(unit(random), unit(random), unit(random)), turn(), &sb};
    const CoreDistance d = core_distance(a, b);
    ASSERT_TRUE(std::isfinite(d.distance) && d.normal.allFinite()) << "trial " << trial;
    EXPECT_NEAR(d.normal.norm(), 1.0, 1e-12);
    if (d.distance > 0.0) {
      ++apart;
      EXPECT_NEAR((d.on_b - d.on_a).norm(), d.distance, 1e-9) << "trial " << trial;
      EXPECT_NEAR((d.on_b - d.on_a).dot(d.normal), d.distance, 1e-9) << "trial " << trial;
      continue;
    }
    ++overlapping;
    b.position += (-d.distance + 1e-6) * d.normal;
    const CoreDistance after = core_distance(a, b);
    EXPECT_NEAR(after.distance, 1e-6, 1e-5) << "trial " << trial << " depth " << -d.distance;
    b.position -= 2e-6 * d.normal;
    EXPECT_LT(core_distance(a, b).distance, 1e-6) << "trial " << trial;
    const PairManifold m =
        convex_manifold({Vec3::Zero(), a.rotation, &sa}, {b.position, b.rotation, &sb}, 0.05);
    ASSERT_GE(m.count, 1);
    for (int k = 0; k < m.count; ++k) {
      EXPECT_TRUE(m.points[static_cast<std::size_t>(k)].point_a.allFinite());
    }
  }
  std::printf("[ measured ] %d pairs apart, %d overlapping\n", apart, overlapping);
  EXPECT_GT(apart, 2000);
  EXPECT_GT(overlapping, 2000);
}

// Two boxes' edges crossed (a box turned 45° about x over one turned 45° about z): one point,
// the edges' distance apart.
TEST(ConvexGeometry, CrossedEdgesTouchAtOnePoint) {
  const Shape hull = hull_shape(hull_of_box(Vec3::Constant(0.5)));
  const Shape box = box_shape(Vec3::Constant(0.5));
  const double reach = 0.5 * std::sqrt(2.0);
  for (const double gap : {0.01, -0.01}) {
    const ShapePose a{Vec3::Zero(), about(std::numbers::pi / 4, Vec3::UnitZ()), &hull};
    const ShapePose b{Vec3(0.0, 2.0 * reach + gap, 0.0), about(std::numbers::pi / 4, Vec3::UnitX()),
                      &box};
    const PairManifold m = convex_manifold(a, b, 0.05);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, gap, 1e-9);
    EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-6);
    const PairManifold boxes =
        box_box_manifold({a.position, a.rotation, Vec3::Constant(0.5)},
                         {b.position, b.rotation, Vec3::Constant(0.5)}, 0.05);
    ASSERT_EQ(boxes.count, 1);
    EXPECT_NEAR(m.points[0].separation, boxes.points[0].separation, 1e-9);
  }
}

TEST(ConvexGeometry, CoinsStackAndLogsLieSideBySide) {
  const Shape coin = cylinder_shape(0.04, 0.0025);
  // A coin on a coin, off centre by 1 cm and turned: four points (clipped to the lower coin's
  // octagon), 0.2 mm apart.
  const ShapePose lower{Vec3::Zero(), Mat3::Identity(), &coin};
  const ShapePose upper{Vec3(0.01, 0.005 + 2e-4, 0.0), about(0.3, Vec3::UnitY()), &coin};
  PairManifold m = convex_manifold(lower, upper, 0.01);
  ASSERT_EQ(m.count, 4);
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(m.points[static_cast<std::size_t>(k)].separation, 2e-4, 1e-12);
  EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-12);
  // Two logs lying side by side, their axes along z, half overlapping in length: two points, the
  // ends of the stretch where they lie together.
  const Shape log = cylinder_shape(0.1, 0.5);
  const Mat3 along_z = about(std::numbers::pi / 2, Vec3::UnitX());
  const ShapePose left{Vec3::Zero(), along_z, &log};
  const ShapePose right{Vec3(0.2 + 0.003, 0.0, 0.5), along_z, &log};
  m = convex_manifold(left, right, 0.01);
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR((m.normal - Vec3::UnitX()).norm(), 0.0, 1e-9);
  std::vector<double> z;
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(m.points[static_cast<std::size_t>(k)].separation, 0.003, 1e-9);
    z.push_back(m.points[static_cast<std::size_t>(k)].point_a.y());  // body y is world z
  }
  std::sort(z.begin(), z.end());
  EXPECT_NEAR(z[0], 0.0, 1e-9);
  EXPECT_NEAR(z[1], 0.5, 1e-9);
  // Crossed at right angles, one on the other: one point, 3 mm apart.
  const ShapePose across{Vec3(0.0, 0.2 + 0.003, 0.0), about(std::numbers::pi / 2, Vec3::UnitZ()),
                         &log};
  m = convex_manifold(left, across, 0.01);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].separation, 0.003, 1e-9);
}

// A capsule lying on a hull's top face, one end over its edge: two points, the end over the face
// and where the segment leaves it, each a radius and the gap above.
TEST(ConvexGeometry, ACapsuleLiesOnAHullFace) {
  const Shape hull = hull_shape(hull_of_box(Vec3(0.5, 0.2, 0.5)));
  const Shape capsule = capsule_shape(0.1, 0.4);
  const ShapePose a{Vec3::Zero(), Mat3::Identity(), &hull};
  const ShapePose b{Vec3(0.3, 0.2 + 0.1 + 0.002, 0.0), about(std::numbers::pi / 2, Vec3::UnitZ()),
                    &capsule};
  const PairManifold m = convex_manifold(a, b, 0.01);
  ASSERT_EQ(m.count, 2);
  std::vector<double> x;
  for (int k = 0; k < 2; ++k) {
    const PairPoint& p = m.points[static_cast<std::size_t>(k)];
    EXPECT_NEAR(p.separation, 0.002, 1e-12);
    x.push_back(p.point_a.x());
  }
  std::sort(x.begin(), x.end());
  EXPECT_NEAR(x[0], -0.1, 1e-12);  // the segment's end
  EXPECT_NEAR(x[1], 0.5, 1e-12);   // the face's edge
}

BodyModel model_of(const Shape& shape, const BodyConstants& constants, Material material) {
  return {.constants = constants,
          .forces = {Gravity{.acceleration = Vec3(0, -kG, 0)}},
          .shape = shape,
          .material = material};
}

BodyModel static_box(const Vec3& half, Material material) {
  return {.constants = static_constants(),
          .forces = {},
          .shape = box_shape(half),
          .material = material,
          .is_static = true};
}

// Lying across a static box tilted 30° (μ = 0.5), a solid cylinder rolls without slipping at
// 2/3 g sin θ within 0.5 %, its contact point still within 1e-6 m/s.
TEST(ConvexWorld, ACylinderRollsDownAStaticBoxAtTwoThirds) {
  const double r = 0.3, angle = std::numbers::pi / 6.0;
  const Material grip{.restitution = 0.0, .friction = 0.5};
  const BodyModel can =
      model_of(cylinder_shape(r, 0.2),
               constants_from_moments(2.0, cylinder_inertia(2.0, r, 0.4).diagonal()), grip);
  const Mat3 tilt = about(angle, Vec3::UnitZ());
  const Vec3 n = tilt.col(1);
  const BodyModel ramp = static_box(Vec3(5.0, 0.5, 1.0), grip);
  const Mat3 across = about(std::numbers::pi / 2.0, Vec3::UnitX());
  const Vec3 start = 2.0 * tilt.col(0) + r * n;
  sim::Simulation world(
      {ramp, can},
      {make_state(ramp.constants, -0.5 * n, Vec3::Zero(), Quat(tilt), Vec3::Zero()),
       make_state(can.constants, start, Vec3::Zero(), Quat(across), Vec3::Zero())},
      Integrator::rk4, kStep, {}, {.sleep = false});
  const double t_end = 1.5;
  double worst_slip = 0.0;
  while (world.time() < t_end - 1e-12) {
    world.step();
    const BodyState& s = world.current()[1];
    const double slip = (s.velocity() + s.angular_velocity().cross(-r * n)).norm();
    worst_slip = std::max(worst_slip, slip);
  }
  const BodyState& s = world.current()[1];
  const double a = 2.0 * (s.position() - start).dot(-tilt.col(0)) / (t_end * t_end);
  const double expected = 2.0 / 3.0 * kG * std::sin(angle);
  std::printf(
      "[ measured ] cylinder down a static box: a %.6f for %.6f (%+.4f%%), slip %.1e m/s, off "
      "the face %.1e m\n",
      a, expected, 100.0 * (a / expected - 1.0), worst_slip, std::abs(s.position().dot(n) - r));
  EXPECT_NEAR(a, expected, 5e-3 * expected);
  EXPECT_LT(worst_slip, 1e-6);
  EXPECT_LT(std::abs(s.position().dot(n) - r), 1e-4);
}

// Three coins stacked on a static box, and three hull boxes in a tower on a floor, stand 10 s:
// each moves less than 1 mm and tilts less than 1e-3 rad.
TEST(ConvexWorld, CoinsAndHullBoxesStandInStacks) {
  const Material grip{.restitution = 0.0, .friction = 0.5};
  const double r = 0.04, length = 0.005, mass = 0.03;
  const BodyModel coin =
      model_of(cylinder_shape(r, 0.5 * length),
               constants_from_moments(mass, cylinder_inertia(mass, r, length).diagonal()), grip);
  const BodyModel table = static_box(Vec3(0.3, 0.05, 0.3), grip);
  const Vec3 half(0.2, 0.1, 0.15);
  const HullBody block = hull_body(
                             [&] {
                               std::vector<Vec3> c;
                               for (int k = 0; k < 8; ++k) c.push_back(corner(half, k));
                               return c;
                             }(),
                             1.0)
                             .value();
  const BodyModel brick = model_of(hull_shape(block.hull), block.constants, grip);
  std::vector<BodyModel> models{table};
  std::vector<BodyState> start{
      make_state(table.constants, Vec3(0, -0.05, 0), Vec3::Zero(), Quat::Identity(), Vec3::Zero())};
  for (int k = 0; k < 3; ++k) {
    models.push_back(coin);
    start.push_back(make_state(coin.constants, Vec3(0.002 * k, (k + 0.5) * length, 0.0),
                               Vec3::Zero(), Quat(about(0.4 * k, Vec3::UnitY())), Vec3::Zero()));
  }
  for (int k = 0; k < 3; ++k) {
    models.push_back(brick);
    start.push_back(make_state(brick.constants, Vec3(1.0 + 0.01 * k, (2 * k + 1) * half.y(), 0.0),
                               Vec3::Zero(), Quat(about(0.2 * k, Vec3::UnitY())), Vec3::Zero()));
  }
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  sim::Simulation world(models, start, Integrator::rk4, kStep, {floor}, {.sleep = false});
  double moved = 0.0, tilt = 0.0;
  while (world.time() < 10.0 - 1e-12) {
    world.step();
    for (std::size_t k = 1; k < models.size(); ++k) {
      const BodyState& s = world.current()[k];
      moved = std::max(moved, (s.position() - start[k].position()).norm());
      tilt = std::max(tilt, std::acos(std::min(1.0, s.rotation().col(1).y())));
    }
  }
  std::printf("[ measured ] coins and hull bricks in stacks: moved up to %.1e m, tilted %.1e rad\n",
              moved, tilt);
  EXPECT_LT(moved, 1e-3);
  EXPECT_LT(tilt, 1e-3);
}

// Two hull cubes meeting face on, e = 1, μ = 0, no gravity: they exchange velocities within 1e-9
// m/s and keep their energy within 1e-9 of itself, and nothing turns (two boxes give the same).
TEST(ConvexWorld, HullCubesExchangeVelocitiesInAnElasticImpact) {
  const HullBody cube = hull_body(
                            [] {
                              std::vector<Vec3> c;
                              for (int k = 0; k < 8; ++k)
                                c.push_back(corner(Vec3::Constant(0.5), k));
                              return c;
                            }(),
                            1.0)
                            .value();
  const BodyModel model{.constants = cube.constants,
                        .forces = {},
                        .shape = hull_shape(cube.hull),
                        .material = {.restitution = 1.0, .friction = 0.0}};
  sim::Simulation world({model, model},
                        {make_state(model.constants, Vec3(-1.0, 0, 0), Vec3(2.0, 0, 0),
                                    Quat::Identity(), Vec3::Zero()),
                         make_state(model.constants, Vec3(0.5, 0, 0), Vec3(-1.25, 0, 0),
                                    Quat::Identity(), Vec3::Zero())},
                        Integrator::rk4, kStep, {}, {.sleep = false});
  while (world.time() < 1.0 - 1e-12) world.step();
  const BodyState &a = world.current()[0], &b = world.current()[1];
  std::printf("[ measured ] hull cubes after an elastic impact: %.12f and %.12f m/s\n",
              a.velocity().x(), b.velocity().x());
  EXPECT_NEAR(a.velocity().x(), -1.25, 1e-9);
  EXPECT_NEAR(b.velocity().x(), 2.0, 1e-9);
  const double energy = 0.5 * (4.0 + 1.5625);
  EXPECT_NEAR(kinetic_energy(a) + kinetic_energy(b), energy, 1e-9 * energy);
  EXPECT_LT(a.angular_velocity().norm() + b.angular_velocity().norm(), 1e-9);
}

}  // namespace
}  // namespace tumble::physics
