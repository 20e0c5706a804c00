// Convex hulls as bodies (issue "Shapes"): their constants against closed forms, their centre of
// mass becoming the body's origin, the hull of a box moving as the box does (free, and dropped on a
// floor), a hull resting still on a face of more than four corners, and a hull of many corners
// reduced to kMostHullCorners.
#include "physics/hull_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "physics/free_rigid_body.hpp"
#include "physics/mass_properties.hpp"
#include "physics/pair_contact.hpp"
#include "sim/simulation.hpp"

namespace tumble::physics {
namespace {

constexpr double kG = 9.81;

std::vector<Vec3> box_corners(const Vec3& size) {
  std::vector<Vec3> out;
  for (int k = 0; k < 8; ++k) out.push_back(corner(0.5 * size, k));
  return out;
}

double largest_relative(const Vec3& a, const Vec3& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(HullBody, TheHullOfABoxHasTheBoxsConstants) {
  const Vec3 size(1.0, 2.0, 3.0);
  const Result<HullBody> made = hull_body(box_corners(size), 2.5);
  ASSERT_TRUE(made) << made.error();
  const HullBody& hull = made.value();
  const BodyConstants box = box_constants(2.5, size);
  EXPECT_LT(largest_relative(hull.constants.inertia, box.inertia), 1e-12);
  EXPECT_EQ(hull.axes, Mat3::Identity());
  EXPECT_LT(hull.centre.norm(), 1e-15);
  EXPECT_EQ(hull.hull->vertices.size(), 8u);
}

// A regular tetrahedron of edge a: I = m a² / 20 about every axis through its centre.
TEST(HullBody, ARegularTetrahedronHasItsClosedFormMoments) {
  const double a = 0.7, mass = 3.0;
  const double s = a / (2.0 * std::sqrt(2.0));  // the corners of a cube's alternate vertices
  const std::vector<Vec3> corners = {Vec3(s, s, s), Vec3(s, -s, -s), Vec3(-s, s, -s),
                                     Vec3(-s, -s, s)};
  const Result<HullBody> made = hull_body(corners, mass);
  ASSERT_TRUE(made) << made.error();
  const Vec3 expected = Vec3::Constant(mass * a * a / 20.0);
  EXPECT_LT(largest_relative(made.value().constants.inertia, expected), 1e-12);
}

// The corner tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1): its centre of mass at (1/4, 1/4,
// 1/4) becomes the body's origin, and its corners are given about it.
TEST(HullBody, TheCentreOfMassOfAnOffCentreSetIsTheOrigin) {
  const std::vector<Vec3> corners = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const Result<HullBody> made = hull_body(corners, 1.0);
  ASSERT_TRUE(made) << made.error();
  const HullBody& hull = made.value();
  EXPECT_LT((hull.centre - Vec3::Constant(0.25)).norm(), 1e-15);
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : hull.hull->vertices) mean += v;
  EXPECT_LT((mean / 4.0).norm(), 1e-15);  // a tetrahedron's centroid is its corners' mean
  // The corners back in the points' frame.
  for (const Vec3& v : hull.hull->vertices) {
    const Vec3 back = hull.axes * v + hull.centre;
    double nearest = 1.0;
    for (const Vec3& c : corners) nearest = std::min(nearest, (back - c).norm());
    EXPECT_LT(nearest, 1e-15);
  }
}

TEST(HullBody, FewerThanFourPointsThatSpanAVolumeAreAnError) {
  const std::vector<Vec3> flat = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  const Result<HullBody> made = hull_body(flat, 1.0);
  ASSERT_FALSE(made);
  EXPECT_NE(made.error().find("plane"), std::string::npos) << made.error();
}

// 2000 points on a sphere of radius 0.5: their hull has as many corners, reduced to
// kMostHullCorners spread over the sphere. The polyhedron they span lies inside the ball, its mass
// nearer the centre: its moments are below the ball's 2/5 m r² = 0.1 kg m², by 6.5% (measured),
// and within 10% of it.
TEST(HullBody, AHullOfManyCornersIsReduced) {
  std::vector<Vec3> points;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < 2000; ++i) {
    const double y = 1.0 - 2.0 * (i + 0.5) / 2000.0, r = std::sqrt(1.0 - y * y);
    points.push_back(0.5 * Vec3(r * std::cos(golden * i), y, r * std::sin(golden * i)));
  }
  const Result<HullBody> made = hull_body(points, 1.0);
  ASSERT_TRUE(made) << made.error();
  const HullBody& hull = made.value();
  std::printf("[ measured ] %zu corners reduced to %zu; moments %.4f %.4f %.4f (ball 0.1000)\n",
              hull.given_corners, hull.hull->vertices.size(), hull.constants.inertia.x(),
              hull.constants.inertia.y(), hull.constants.inertia.z());
  EXPECT_GT(hull.given_corners, kMostHullCorners);
  EXPECT_LE(hull.hull->vertices.size(), kMostHullCorners);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(hull.constants.inertia[k], 0.1);
    EXPECT_GT(hull.constants.inertia[k], 0.09);
  }
}

// A ball against the hull of a box's corners touches as against the box (box_sphere_manifold,
// closed form): off a face, an edge, a corner, and with its centre inside; the same normal and
// separation to 1e-15, from either side.
TEST(HullGeometry, ABallTouchesTheHullOfABoxAsTheBox) {
  const Vec3 size(1.0, 0.6, 0.8);
  const HullBody hull = hull_body(box_corners(size), 1.0).value();
  const Shape as_hull = hull_shape(hull.hull);
  const Shape ball = sphere_shape(0.2);
  const Mat3 turn = Eigen::AngleAxisd(0.5, Vec3(1, 1, 0).normalized()).toRotationMatrix();
  const Vec3 at(0.3, -0.1, 0.2);
  for (const Vec3& local :
       {Vec3(0.1, 0.45, 0.05), Vec3(0.6, 0.4, 0.0), Vec3(0.62, 0.4, -0.5), Vec3(0.3, 0.1, 0.05)}) {
    SCOPED_TRACE(local.transpose());
    const ShapePose ball_pose{at + turn * local, Mat3::Identity(), &ball};
    const PairManifold box =
        box_sphere_manifold({at, turn, 0.5 * size}, ball_pose, ball.radius, 1.0);
    const PairManifold m = pair_manifold({at, turn, &as_hull}, ball_pose, 1.0);
    ASSERT_EQ(box.count, 1);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].separation, box.points[0].separation, 1e-15);
    EXPECT_NEAR((m.normal - box.normal).norm(), 0.0, 1e-15);
    const PairManifold back = pair_manifold(ball_pose, {at, turn, &as_hull}, 1.0);
    ASSERT_EQ(back.count, 1);
    EXPECT_NEAR((back.normal + box.normal).norm(), 0.0, 1e-15);
  }
}

// A ball dropped onto the flat top of a static frustum (a square of 2 m below, of 1 m on top,
// 0.5 m up) comes to rest on it, its centre its radius above the top, within 1e-6 m.
TEST(HullWorld, ABallRestsOnAStaticHull) {
  std::vector<Vec3> corners;
  for (const double x : {-1.0, 1.0}) {
    for (const double z : {-1.0, 1.0}) {
      corners.push_back(Vec3(x, 0.0, z));
      corners.push_back(Vec3(0.5 * x, 0.5, 0.5 * z));
    }
  }
  const HullBody hull = hull_body(corners, 1.0).value();
  const BodyModel fixed{.constants = static_constants(),
                        .forces = {},
                        .shape = hull_shape(hull.hull),
                        .material = {.friction = 0.8},
                        .is_static = true};
  const BodyModel ball{.constants = sphere_constants(0.2, 0.1),
                       .forces = {Gravity{.acceleration = Vec3(0, -kG, 0)}},
                       .shape = sphere_shape(0.1),
                       .material = {.restitution = 0.0, .friction = 0.8}};
  // The hull's body frame is its principal one, about its centre of mass: placed so that its
  // points are where they were written.
  sim::Simulation world(
      {fixed, ball},
      {make_state(fixed.constants, hull.centre, Vec3::Zero(), Quat(hull.axes), Vec3::Zero()),
       make_state(ball.constants, Vec3(0.1, 0.9, -0.2), Vec3::Zero(), Quat::Identity(),
                  Vec3::Zero())},
      Integrator::rk4, 1.0 / 60, {}, {.sleep = false});
  while (world.time() < 3.0 - 1e-12) world.step();
  const BodyState& s = world.current()[1];
  std::printf(
      "[ measured ] a ball on a static hull's top: centre at %.9f m (0.5 + 0.1), |v| %.1e\n",
      s.position().y(), s.velocity().norm());
  EXPECT_NEAR(s.position().y(), 0.6, 1e-6);
  EXPECT_LT(s.velocity().norm(), 1e-6);
}

// Tumbling free for 10 s (rk4, 1/60 s), the hull of a box follows the box within 1e-12 m; dropped
// flat on a floor, it comes to rest at the box's height (its half height) within 1e-6 m.
TEST(HullWorld, TheHullOfABoxMovesAsTheBox) {
  const Vec3 size(0.4, 0.6, 1.0);
  const HullBody hull = hull_body(box_corners(size), 1.5).value();
  const BodyModel as_box{.constants = box_constants(1.5, size),
                         .forces = {},
                         .shape = box_shape(0.5 * size),
                         .material = {}};
  const BodyModel as_hull{
      .constants = hull.constants, .forces = {}, .shape = hull_shape(hull.hull), .material = {}};
  const Quat q(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  const auto start = [&](const BodyModel& m) {
    return make_state(m.constants, Vec3(0, 5, 0), Vec3(1, 2, 0), q, Vec3(0.4, 3.0, 0.2));
  };
  sim::Simulation box({as_box}, {start(as_box)}, Integrator::rk4, 1.0 / 60);
  sim::Simulation free({as_hull}, {start(as_hull)}, Integrator::rk4, 1.0 / 60);
  double apart = 0.0;
  while (box.time() < 10.0 - 1e-12) {
    box.step();
    free.step();
    for (int k = 0; k < 8; ++k) {
      const Vec3 c = corner(0.5 * size, k);
      apart = std::max(apart, (body_point_to_world(box.current()[0], c) -
                               body_point_to_world(free.current()[0], c))
                                  .norm());
    }
  }
  std::printf("[ measured ] free: the hull's corners off the box's by %.1e m over 10 s\n", apart);
  EXPECT_LT(apart, 1e-12);

  BodyModel dropped = as_hull;
  dropped.forces.push_back(Gravity{.acceleration = Vec3(0, -kG, 0)});
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  sim::Simulation world({dropped},
                        {make_state(dropped.constants, Vec3(0, 0.8, 0), Vec3::Zero(),
                                    Quat::Identity(), Vec3::Zero())},
                        Integrator::rk4, 1.0 / 60, {floor});
  while (world.time() < 3.0 - 1e-12) world.step();
  std::printf("[ measured ] dropped: rests at %.9f m (half height 0.3)\n",
              world.current()[0].position().y());
  EXPECT_NEAR(world.current()[0].position().y(), 0.3, 1e-6);
}

// A hexagonal prism (12 corners) resting on a hexagonal face, six corners on the floor: four of
// them hold it, and from 1 s to 5 s no corner moves more than 1e-5 m between steps.
TEST(HullWorld, AHullRestsOnAFaceOfSixCornersWithoutJitter) {
  std::vector<Vec3> corners;
  for (int k = 0; k < 6; ++k) {
    const double angle = std::numbers::pi / 3.0 * k;
    for (const double y : {-0.1, 0.1}) {
      corners.push_back(Vec3(0.3 * std::cos(angle), y, 0.3 * std::sin(angle)));
    }
  }
  const HullBody hull = hull_body(corners, 1.0).value();
  const BodyModel model{.constants = hull.constants,
                        .forces = {Gravity{.acceleration = Vec3(0, -kG, 0)}},
                        .shape = hull_shape(hull.hull),
                        .material = {.restitution = 0.0, .friction = 0.5}};
  const Plane floor{.normal = Vec3::UnitY(), .offset = 0.0};
  // Its body axes are its principal ones: the prism's axis may have become body x or z. Stand it
  // so that the axis is up.
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(hull.axes(1, k)) > std::abs(hull.axes(1, axis))) axis = k;
  }
  const Quat up = Quat::FromTwoVectors(Vec3::Unit(axis), Vec3::UnitY());
  sim::Simulation world(
      {model},
      {make_state(model.constants, Vec3(0, 0.1 + 1e-3, 0), Vec3::Zero(), up, Vec3::Zero())},
      Integrator::rk4, 1.0 / 60, {floor}, {.sleep = false});
  double jitter = 0.0;
  std::vector<BodyState> previous;
  while (world.time() < 5.0 - 1e-12) {
    world.step();
    if (world.time() > 1.0) {
      for (const Vec3& v : model.shape.hull->vertices) {
        jitter = std::max(jitter, (body_point_to_world(world.current()[0], v) -
                                   body_point_to_world(previous[0], v))
                                      .norm());
      }
    }
    previous = world.current();
  }
  std::printf(
      "[ measured ] a hexagonal prism on its face: corners moved up to %.1e m a step, "
      "rests at %.9f m\n",
      jitter, world.current()[0].position().y());
  EXPECT_LT(jitter, 1e-5);
  EXPECT_NEAR(world.current()[0].position().y(), 0.1, 1e-6);
}

}  // namespace
}  // namespace tumble::physics
