// Convex hulls: corners, merged faces wound outward, and the inputs that have no volume.
#include "physics/convex_hull.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace tumble::physics {
namespace {

std::vector<Vec3> unit_cube_with_inside_points() {
  std::vector<Vec3> points;
  for (int k = 0; k < 8; ++k)
    points.emplace_back(k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, k & 4 ? 0.5 : -0.5);
  points.emplace_back(0.0, 0.0, 0.0);
  points.emplace_back(0.1, -0.2, 0.3);
  points.emplace_back(0.5, 0.0, 0.0);  // on a face: not a corner
  return points;
}

TEST(ConvexHull, ACubesHullIsEightCornersAndSixSquares) {
  const Result<ConvexHull> hull = convex_hull(unit_cube_with_inside_points());
  ASSERT_TRUE(hull.ok()) << hull.error();
  EXPECT_EQ(hull->vertices.size(), 8u);
  ASSERT_EQ(hull->faces.size(), 6u);
  std::set<std::tuple<double, double, double>> normals;
  for (std::size_t f = 0; f < hull->faces.size(); ++f) {
    const std::vector<std::uint32_t>& face = hull->faces[f];
    EXPECT_EQ(face.size(), 4u);
    const Vec3& n = hull->normals[f];
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1.0, 1e-12);  // along an axis
    normals.insert({std::round(n.x()), std::round(n.y()), std::round(n.z())});
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Vec3& a = hull->vertices[face[k]];
      const Vec3& b = hull->vertices[face[(k + 1) % face.size()]];
      const Vec3& c = hull->vertices[face[(k + 2) % face.size()]];
      EXPECT_GT((b - a).cross(c - b).dot(n), 0.0) << "face " << f << " turns clockwise";
      EXPECT_NEAR(a.dot(n), 0.5, 1e-15);  // on its plane, half a side out
    }
  }
  EXPECT_EQ(normals.size(), 6u);  // one face per side
  EXPECT_EQ(hull->triangles().size(), 12u);
}

TEST(ConvexHull, TheSamePointsGiveTheSameHull) {
  const Result<ConvexHull> a = convex_hull(unit_cube_with_inside_points());
  const Result<ConvexHull> b = convex_hull(unit_cube_with_inside_points());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->vertices, b->vertices);
  EXPECT_EQ(a->faces, b->faces);
}

// Euler's formula V − E + F = 2 on a hull of many points on a sphere, every face convex and every
// point inside or on every face's plane.
TEST(ConvexHull, ManyPointsMakeAClosedConvexSurface) {
  std::vector<Vec3> points;
  for (int i = 0; i < 200; ++i) {
    const double z = -1.0 + (2.0 * i + 1.0) / 200.0, phi = 2.399963229728653 * i;
    const double r = std::sqrt(1.0 - z * z);
    points.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  const Result<ConvexHull> hull = convex_hull(points);
  ASSERT_TRUE(hull.ok()) << hull.error();
  std::size_t edge_ends = 0;
  for (const auto& face : hull->faces) edge_ends += face.size();
  const auto vertices = static_cast<long>(hull->vertices.size());
  const auto faces = static_cast<long>(hull->faces.size());
  EXPECT_EQ(vertices - static_cast<long>(edge_ends / 2) + faces, 2);
  EXPECT_EQ(vertices, 200);
  for (std::size_t f = 0; f < hull->faces.size(); ++f) {
    const double offset = hull->vertices[hull->faces[f][0]].dot(hull->normals[f]);
    for (const Vec3& p : points) EXPECT_LE(p.dot(hull->normals[f]), offset + 1e-12);
  }
}

TEST(ConvexHull, PointsWithoutVolumeAreRefused) {
  const Result<ConvexHull> three =
      convex_hull(std::vector<Vec3>{Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()});
  ASSERT_FALSE(three.ok());
  EXPECT_NE(three.error().find("at least 4 points"), std::string::npos) << three.error();
  EXPECT_NE(three.error().find("got 3"), std::string::npos) << three.error();
  const Result<ConvexHull> flat = convex_hull(std::vector<Vec3>{
      Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3(1.0, 1.0, 0.0), Vec3(0.5, 0.5, 0.0)});
  ASSERT_FALSE(flat.ok());
  EXPECT_NE(flat.error().find("one plane"), std::string::npos) << flat.error();
  const Result<ConvexHull> line = convex_hull(
      std::vector<Vec3>{Vec3::Zero(), Vec3::UnitX(), 2.0 * Vec3::UnitX(), 3.0 * Vec3::UnitX()});
  EXPECT_FALSE(line.ok());
  const Result<ConvexHull> point = convex_hull(std::vector<Vec3>(5, Vec3::Ones()));
  EXPECT_FALSE(point.ok());
}

}  // namespace
}  // namespace tumble::physics
