// render::solid_mesh and quad_mesh: each solid's surface at its size, closed and wound
// counter-clockwise seen from outside, with unit normals pointing out.
#include "render/solid_mesh.hpp"

#include <gtest/gtest.h>

namespace tumble::render {
namespace {

// The mesh's box (m), and whether every triangle faces away from the origin (the solids are
// convex about it) and every normal is unit and points out.
struct Shape {
  Eigen::Vector3f low = Eigen::Vector3f::Constant(1e9f), high = -low;
  bool outward = true;
};
Shape shape_of(const SolidMesh& mesh) {
  Shape out;
  EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
  EXPECT_EQ(mesh.triangles.size() % 3, 0u);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    out.low = out.low.cwiseMin(mesh.positions[i]);
    out.high = out.high.cwiseMax(mesh.positions[i]);
    if (std::abs(mesh.normals[i].norm() - 1.0f) > 1e-5f ||
        mesh.normals[i].dot(mesh.positions[i]) <= 0.0f) {
      out.outward = false;
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
    const Eigen::Vector3f& a = mesh.positions.at(mesh.triangles[t]);
    const Eigen::Vector3f& b = mesh.positions.at(mesh.triangles[t + 1]);
    const Eigen::Vector3f& c = mesh.positions.at(mesh.triangles[t + 2]);
    const Eigen::Vector3f facing = (b - a).cross(c - a);
    // Degenerate triangles (the capsule's band when its length is 0) face nowhere.
    if (facing.norm() > 1e-9f && facing.dot(a + b + c) <= 0.0f) out.outward = false;
  }
  return out;
}

void expect_box(const Shape& shape, const Vec3& size) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(shape.high[i], 0.5 * size[i], 1e-6) << i;
    EXPECT_NEAR(shape.low[i], -0.5 * size[i], 1e-6) << i;
  }
}

TEST(SolidMesh, EverySolidFillsItsBoxFacingOut) {
  const Vec3 box_size(0.5, 1.0, 2.0);
  Shape shape = shape_of(solid_mesh(Solid::box, box_size));
  EXPECT_TRUE(shape.outward);
  expect_box(shape, box_size);
  shape = shape_of(solid_mesh(Solid::ball, Vec3::Constant(0.6)));
  EXPECT_TRUE(shape.outward);
  expect_box(shape, Vec3::Constant(0.6));
  // A capsule of radius 0.1 and length 0.6: its box is (2r, length + 2r, 2r).
  shape = shape_of(solid_mesh(Solid::capsule, Vec3(0.2, 0.8, 0.2)));
  EXPECT_TRUE(shape.outward);
  expect_box(shape, Vec3(0.2, 0.8, 0.2));
  shape = shape_of(solid_mesh(Solid::cylinder, Vec3(0.4, 0.3, 0.4)));
  EXPECT_TRUE(shape.outward);
  expect_box(shape, Vec3(0.4, 0.3, 0.4));
}

TEST(SolidMesh, AStretchedBallsNormalsTurnWithItsSurface) {
  // An ellipsoid of semi-axes (1, 0.25, 0.25): at the point (0.5·cos, 0.125·sin, 0) the surface's
  // normal is along (cos / 1, sin / 0.25, 0), not along the point.
  const SolidMesh mesh = solid_mesh(Solid::ball, Vec3(2.0, 0.5, 0.5));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    const Eigen::Vector3f expected =
        Eigen::Vector3f(p.x() / 1.0f, p.y() / 0.0625f, p.z() / 0.0625f).normalized();
    ASSERT_NEAR(mesh.normals[i].dot(expected), 1.0f, 1e-5f) << i;
  }
}

TEST(SolidMesh, AHullIsItsCornersWithItsFacesNormals) {
  const HullMesh tetrahedron{
      .corners = {Vec3(-0.25, -0.25, -0.25), Vec3(0.75, -0.25, -0.25), Vec3(-0.25, 0.75, -0.25),
                  Vec3(-0.25, -0.25, 0.75)},
      .faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}},
      .normals = {-Vec3::UnitZ(), -Vec3::UnitY(), -Vec3::UnitX(), Vec3::Ones().normalized()}};
  const SolidMesh mesh = solid_mesh(Solid::hull, Vec3::Ones(), &tetrahedron);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_TRUE(shape_of(mesh).outward);
  EXPECT_NEAR(mesh.positions[0].x(), -0.25f, 1e-6f);
  EXPECT_NEAR(mesh.normals.back().dot(Eigen::Vector3f::Ones().normalized()), 1.0f, 1e-6f);
}

TEST(SolidMesh, AQuadFacesItsLocalY) {
  const SolidMesh quad = quad_mesh(4.0, 2.0);
  ASSERT_EQ(quad.triangles.size(), 6u);
  for (std::size_t t = 0; t < 6; t += 3) {
    const Eigen::Vector3f& a = quad.positions[quad.triangles[t]];
    const Eigen::Vector3f facing = (quad.positions[quad.triangles[t + 1]] - a)
                                       .cross(quad.positions[quad.triangles[t + 2]] - a);
    EXPECT_GT(facing.y(), 0.0f);
  }
  EXPECT_EQ(quad.positions[3], Eigen::Vector3f(2.0f, 0.0f, 1.0f));
}

}  // namespace
}  // namespace tumble::render
