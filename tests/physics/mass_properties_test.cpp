// Mass properties of the shapes: the closed forms against an independent integration of each
// solid of revolution, and the polyhedral integrals against solids whose tensors are known.
#include "physics/mass_properties.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "physics/convex_hull.hpp"

namespace tumble::physics {
namespace {

using std::numbers::pi;

// The largest entry of |a - b| over the largest of |b|.
double relative_difference(const Mat3& a, const Mat3& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// A solid of revolution about y of unit density, its radius squared R²(y) a polynomial of degree
// at most 2 on each of `pieces` (from, to): mass ∫ π R² dy, I_y = ∫ π R⁴/2 dy, I_x = ∫ (π R⁴/4 +
// π R² y²) dy, by 5-point Gauss-Legendre on each piece (exact to degree 9, these integrands are
// of degree 4 at most).
struct Revolved {
  double volume = 0.0, along = 0.0, across = 0.0;
};
Revolved revolve(const std::vector<std::pair<double, double>>& pieces,
                 const std::function<double(double)>& radius_squared) {
  const std::array<double, 5> x = {0.0, -0.5384693101056831, 0.5384693101056831,
                                   -0.9061798459386640, 0.9061798459386640};
  const std::array<double, 5> w = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                   0.2369268850561891, 0.2369268850561891};
  Revolved out;
  for (const auto& [from, to] : pieces) {
    const double half = 0.5 * (to - from), mid = 0.5 * (to + from);
    for (std::size_t k = 0; k < x.size(); ++k) {
      const double y = mid + half * x[k], r2 = radius_squared(y), weight = half * w[k];
      out.volume += weight * pi * r2;
      out.along += weight * pi * r2 * r2 / 2.0;
      out.across += weight * (pi * r2 * r2 / 4.0 + pi * r2 * y * y);
    }
  }
  return out;
}

// The tensor of a revolved solid of `mass` (kg).
Mat3 revolved_tensor(const Revolved& solid, double mass) {
  const double density = mass / solid.volume;
  return Vec3(density * solid.across, density * solid.along, density * solid.across).asDiagonal();
}

TEST(MassProperties, SphereMatchesItsIntegral) {
  const double r = 0.37, m = 2.5;
  const Revolved ball = revolve({{-r, r}}, [&](double y) { return r * r - y * y; });
  EXPECT_NEAR(ball.volume, 4.0 / 3.0 * pi * r * r * r, 1e-15);
  EXPECT_LT(relative_difference(sphere_inertia(m, r), revolved_tensor(ball, m)), 1e-12);
}

TEST(MassProperties, CylinderMatchesItsIntegral) {
  const double r = 0.5, h = 0.05, m = 0.8;  // a coin's proportions
  const Revolved coin = revolve({{-h / 2, h / 2}}, [&](double) { return r * r; });
  EXPECT_LT(relative_difference(cylinder_inertia(m, r, h), revolved_tensor(coin, m)), 1e-12);
  const double long_h = 3.0;  // and a rod's
  const Revolved rod = revolve({{-long_h / 2, long_h / 2}}, [&](double) { return r * r; });
  EXPECT_LT(relative_difference(cylinder_inertia(m, r, long_h), revolved_tensor(rod, m)), 1e-12);
}

TEST(MassProperties, CapsuleMatchesItsIntegral) {
  for (const auto& [r, h] :
       std::vector<std::pair<double, double>>{{0.1, 0.6}, {0.5, 1.0}, {0.3, 0.0}}) {
    const double m = 3.0;
    const auto cap = [&](double y) {
      const double past = std::abs(y) - h / 2;
      return past > 0.0 ? r * r - past * past : r * r;
    };
    const Revolved capsule =
        revolve({{-h / 2 - r, -h / 2}, {-h / 2, h / 2}, {h / 2, h / 2 + r}}, cap);
    EXPECT_LT(relative_difference(capsule_inertia(m, r, h), revolved_tensor(capsule, m)), 1e-12)
        << "r = " << r << ", length = " << h;
  }
  // With no cylinder between its caps a capsule is a ball.
  EXPECT_LT(relative_difference(capsule_inertia(2.0, 0.3, 0.0), sphere_inertia(2.0, 0.3)), 1e-15);
}

// The eight corners of a box of edges `size` centred at `centre`.
std::vector<Vec3> box_corners(const Vec3& size, const Vec3& centre) {
  std::vector<Vec3> out;
  for (int k = 0; k < 8; ++k) {
    out.push_back(centre + 0.5 * Vec3((k & 1) ? size.x() : -size.x(),
                                      (k & 2) ? size.y() : -size.y(),
                                      (k & 4) ? size.z() : -size.z()));
  }
  return out;
}

MassProperties hull_properties(const std::vector<Vec3>& points, double density) {
  const Result<ConvexHull> hull = convex_hull(points);
  EXPECT_TRUE(hull.ok()) << (hull.ok() ? "" : hull.error());
  const auto triangles = hull->triangles();
  return polyhedron_mass_properties(hull->vertices, triangles, density);
}

TEST(MassProperties, TheHullOfABoxIsTheBox) {
  const Vec3 size(0.4, 1.3, 2.2), centre(1.5, -2.0, 0.25);
  const double density = 700.0, mass = density * size.prod();
  const MassProperties hull = hull_properties(box_corners(size, centre), density);
  EXPECT_NEAR(hull.mass, mass, 1e-12 * mass);
  EXPECT_LT((hull.centre - centre).norm(), 1e-14);
  const Mat3 box = box_constants(mass, size).inertia.asDiagonal();
  EXPECT_LT(relative_difference(hull.inertia, box), 1e-12);
  const PrincipalAxes axes = principal_axes(hull.inertia);
  EXPECT_EQ(axes.rotation, Mat3::Identity());  // already principal: its own axes, in order
  EXPECT_LT((axes.moments - box_constants(mass, size).inertia).cwiseAbs().maxCoeff(),
            1e-12 * box.maxCoeff());
}

// A regular tetrahedron of edge a: I = m a²/20 about every axis through its centre.
TEST(MassProperties, ARegularTetrahedronHasItsClosedForm) {
  const double a = 0.8, density = 1000.0;
  const double s = a / std::sqrt(8.0);  // corners (±s, ±s, ±s) with an even number of minuses
  const std::vector<Vec3> corners = {Vec3(s, s, s), Vec3(s, -s, -s), Vec3(-s, s, -s),
                                     Vec3(-s, -s, s)};
  const MassProperties tetra = hull_properties(corners, density);
  const double mass = density * a * a * a / (6.0 * std::sqrt(2.0));
  EXPECT_NEAR(tetra.mass, mass, 1e-12 * mass);
  EXPECT_LT(tetra.centre.norm(), 1e-15);
  EXPECT_LT(relative_difference(tetra.inertia, Mat3::Identity() * (mass * a * a / 20.0)), 1e-12);
}

// The corner of a cube cut off by the plane x + y + z = 1, moved off the origin: its centre of
// mass is a quarter of the way along each edge from the right-angled corner, and its tensor has
// products of inertia (unit density: I_xx = 1/80, I_xy = 1/480 about the centre), whose
// principal axes are (1, 1, 1)/√3 (moment 1/60) and any two across it (1/96).
TEST(MassProperties, AnOffCentreCornerHasItsCentreAndProducts) {
  const Vec3 offset(2.0, -1.0, 0.5);
  std::vector<Vec3> points = {offset, offset + Vec3::UnitX(), offset + Vec3::UnitY(),
                              offset + Vec3::UnitZ(), offset + Vec3(0.1, 0.1, 0.1)};  // one inside
  const MassProperties corner = hull_properties(points, 1.0);
  EXPECT_NEAR(corner.mass, 1.0 / 6.0, 1e-15);
  EXPECT_LT((corner.centre - (offset + Vec3::Constant(0.25))).norm(), 1e-14);
  Mat3 expected;
  expected << 6, 1, 1, 1, 6, 1, 1, 1, 6;
  expected /= 480.0;
  EXPECT_LT(relative_difference(corner.inertia, expected), 1e-12);

  const PrincipalAxes axes = principal_axes(corner.inertia);
  EXPECT_LT(
      relative_difference(axes.rotation * axes.moments.asDiagonal() * axes.rotation.transpose(),
                          corner.inertia),
      1e-14);
  EXPECT_NEAR(axes.rotation.determinant(), 1.0, 1e-14);
  EXPECT_NEAR(axes.moments.x(), 1.0 / 96.0, 1e-15);
  EXPECT_NEAR(axes.moments.y(), 1.0 / 96.0, 1e-15);
  EXPECT_NEAR(axes.moments.z(), 1.0 / 60.0, 1e-15);
  EXPECT_LT((axes.rotation.col(2) - Vec3::Constant(1.0 / std::sqrt(3.0))).norm(), 1e-12);
}

}  // namespace
}  // namespace tumble::physics
