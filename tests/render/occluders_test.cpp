// The bodies a box receives ambient occlusion from (render/occluders.hpp): those whose reach
// (kOcclusionReach times their longest edge) spans the gap between the bounding spheres, the
// nearest kOccludersPerBody of them, and the texels the body shader reads.
#include "render/occluders.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::render {
namespace {

Box cube_at(double x, double y, double z, double edge = 1.0) {
  return Box{.position = Vec3(x, y, z), .size = Vec3::Constant(edge)};
}

TEST(NearestOccluders, AreThoseWhoseReachSpansTheGap) {
  // Unit cubes: bounding radius sqrt(3)/2, reach 1.25. Centres 3.0 m apart leave a gap of
  // 3 - sqrt(3) = 1.27 m: beyond the reach. 2.9 m leave 1.17 m: within it.
  const std::vector<Box> apart = {cube_at(0, 0.5, 0), cube_at(3.0, 0.5, 0)};
  const auto far = nearest_occluders(apart);
  EXPECT_EQ(far[0][0], -1);
  EXPECT_EQ(far[1][0], -1);
  const std::vector<Box> near = {cube_at(0, 0.5, 0), cube_at(2.9, 0.5, 0)};
  const auto close = nearest_occluders(near);
  EXPECT_EQ(close[0][0], 1);
  EXPECT_EQ(close[0][1], -1);
  EXPECT_EQ(close[1][0], 0);
  // A small cube beside a large one: the large one reaches the small one, not the other way.
  // Edge 2 (radius 1.73, reach 2.5) and edge 0.2 (radius 0.17, reach 0.25), centres 2.5 m apart:
  // a gap of 0.60 m.
  const std::vector<Box> sizes = {cube_at(0, 1, 0, 2.0), cube_at(0, 1, 2.5, 0.2)};
  const auto reach = nearest_occluders(sizes);
  EXPECT_EQ(reach[0][0], -1);
  EXPECT_EQ(reach[1][0], 0);
}

TEST(NearestOccluders, KeepsTheNearestFourInOrderOfTheirGap) {
  // A cube with six neighbours along the axes and diagonals, at six distances, given in an
  // order unlike their distances and unlike x.
  std::vector<Box> boxes = {cube_at(0, 0, 0)};
  const double distances[] = {2.5, 1.9, 2.95, 2.2, 2.9, 2.0};  // gaps of d - sqrt(3)
  const Vec3 directions[] = {Vec3(1, 0, 0),  Vec3(-1, 0, 0),    Vec3(0, 1, 0),
                             Vec3(0, 0, -1), Vec3(0.6, 0.8, 0), Vec3(0, -0.6, 0.8)};
  for (int k = 0; k < 6; ++k) {
    const Vec3 at = distances[k] * directions[k];
    boxes.push_back(cube_at(at.x(), at.y(), at.z()));
  }
  const auto lists = nearest_occluders(boxes);
  // 1.9 (box 2), 2.0 (box 6), 2.2 (box 4), 2.5 (box 1); 2.9 and 2.95 reach it but are not kept.
  EXPECT_EQ(lists[0][0], 2);
  EXPECT_EQ(lists[0][1], 6);
  EXPECT_EQ(lists[0][2], 4);
  EXPECT_EQ(lists[0][3], 1);
  // The same bodies in any order give the same neighbours (as indices of that order).
  std::vector<Box> reversed(boxes.rbegin(), boxes.rend());
  const auto other = nearest_occluders(reversed);
  const int n = static_cast<int>(boxes.size());
  for (int k = 0; k < kOccludersPerBody; ++k) EXPECT_EQ(n - 1 - other[n - 1][k], lists[0][k]);
}

TEST(OccluderTexels, HoldTheShapeAsTheShaderReadsIt) {
  Box ball = cube_at(1, 2, 3, 0.5);
  ball.solid = Solid::ball;
  Box box{.position = Vec3(-1, 0.5, 4),
          .orientation = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY())),
          .size = Vec3(1.0, 0.4, 2.0)};
  const std::vector<float> texels = occluder_texels({ball, box});
  ASSERT_EQ(texels.size(), 16u * kOccludersPerRow);  // one row, padded
  EXPECT_FLOAT_EQ(texels[0], 1.0f);
  EXPECT_FLOAT_EQ(texels[2], 3.0f);
  EXPECT_FLOAT_EQ(texels[3], -0.625f);  // a ball: its reach, 1.25 × 0.5, negative
  EXPECT_FLOAT_EQ(texels[7], 0.25f);    // radius
  const float* b = texels.data() + 16;
  EXPECT_FLOAT_EQ(b[3], 2.5f);  // 1.25 × the longest edge
  // The body's x axis turned a quarter about y is world -z; half edges 0.5, 0.2, 1.0.
  EXPECT_NEAR(b[4], 0.0f, 1e-7);
  EXPECT_NEAR(b[6], -1.0f, 1e-7);
  EXPECT_FLOAT_EQ(b[7], 0.5f);
  EXPECT_FLOAT_EQ(b[11], 0.2f);
  EXPECT_NEAR(b[12], 1.0f, 1e-7);
  EXPECT_FLOAT_EQ(b[15], 1.0f);
  EXPECT_EQ(texels[32], 0.0f);  // padding
}

}  // namespace
}  // namespace tumble::render
