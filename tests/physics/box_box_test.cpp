// The box–box narrow phase (physics/box_box.cpp) against closed-form geometry: resting, sunk,
// rotated and tilted cubes, crossing edges, a vertex, thin plates, margins; and, over random
// poses, against a brute-force separating-axis test built from the boxes' corners.
#include "physics/box_box.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <vector>

namespace tumble::physics {
namespace {

constexpr double kMargin = 0.02;  // m
constexpr double kExact = 1e-12;  // rounding of a few operations on unit-sized values (m)

BoxPose box(const Vec3& position, const Vec3& half_size, const Mat3& rotation = Mat3::Identity()) {
  return BoxPose{.position = position, .rotation = rotation, .half_size = half_size};
}

Mat3 rotation(double angle /* rad */, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// The world position of a point, as A's body frame has it.
Vec3 world_from_a(const BoxPose& a, const PairPoint& p) {
  return a.position + a.rotation * p.point_a;
}
Vec3 world_from_b(const BoxPose& b, const PairPoint& p) {
  return b.position + b.rotation * p.point_b;
}

std::vector<Vec3> world_points(const BoxPose& a, const PairManifold& m) {
  std::vector<Vec3> out;
  for (int i = 0; i < m.count; ++i) out.push_back(world_from_a(a, m.points[i]));
  return out;
}

// Each expected point matched by exactly one manifold point within `tolerance` (m).
void expect_points(const BoxPose& a, const PairManifold& m, const std::vector<Vec3>& expected,
                   double tolerance) {
  ASSERT_EQ(m.count, static_cast<int>(expected.size()));
  const std::vector<Vec3> got = world_points(a, m);
  for (const Vec3& e : expected) {
    const auto near = [&](const Vec3& g) { return (g - e).norm() <= tolerance; };
    EXPECT_EQ(std::count_if(got.begin(), got.end(), near), 1) << "expected " << e.transpose();
  }
}

std::vector<Vec3> corners(const BoxPose& box) {
  std::vector<Vec3> out;
  for (int bits = 0; bits < 8; ++bits)
    out.push_back(box.position + box.rotation * corner(box.half_size, bits));
  return out;
}

bool inside(const BoxPose& box, const Vec3& world, double grown /* m */) {
  const Vec3 local = box.rotation.transpose() * (world - box.position);
  return (local.cwiseAbs() - box.half_size).maxCoeff() <= grown;
}

std::set<std::uint32_t> features(const PairManifold& m) {
  std::set<std::uint32_t> out;
  for (int i = 0; i < m.count; ++i) out.insert(m.points[i].feature);
  return out;
}

TEST(BoxBox, UnitCubeRestingFaceOnGivesTheFourCornersOfTheTopFace) {
  const BoxPose a = box(Vec3::Zero(), Vec3::Constant(0.5));
  const BoxPose b = box(Vec3(0.0, 1.0, 0.0), Vec3::Constant(0.5));
  const PairManifold m = box_box_manifold(a, b, kMargin);
  EXPECT_LE((m.normal - Vec3::UnitY()).norm(), kExact);
  expect_points(a, m, {{-0.5, 0.5, -0.5}, {0.5, 0.5, -0.5}, {0.5, 0.5, 0.5}, {-0.5, 0.5, 0.5}},
                kExact);
  for (int i = 0; i < m.count; ++i) EXPECT_NEAR(m.points[i].separation, 0.0, kExact);
  EXPECT_EQ(features(m).size(), 4u);
}

TEST(BoxBox, CubeSunkOneCentimetreIntoALargerBoxHasSeparationsOfMinusOneCentimetre) {
  const BoxPose a = box(Vec3::Zero(), Vec3(2.0, 0.5, 2.0));
  const BoxPose b = box(Vec3(0.3, 0.99, -0.4), Vec3::Constant(0.5));
  const PairManifold m = box_box_manifold(a, b, kMargin);
  EXPECT_LE((m.normal - Vec3::UnitY()).norm(), kExact);
  // Halfway between B's bottom face (y = 0.49) and A's top face (y = 0.5).
  expect_points(a, m,
                {{-0.2, 0.495, -0.9}, {0.8, 0.495, -0.9}, {0.8, 0.495, 0.1}, {-0.2, 0.495, 0.1}},
                kExact);
  for (int i = 0; i < m.count; ++i) EXPECT_NEAR(m.points[i].separation, -0.01, kExact);
}

TEST(BoxBox, SmallCubeOnALargeBoxGivesItsCornersInAnyFrame) {
  // The whole pair turned and moved: the contact turns and moves with it.
  const Mat3 turn = rotation(0.7, Vec3(0.3, -1.0, 0.5));
  const Vec3 shift(4.0, -2.0, 1.5);
  const BoxPose a = box(shift, Vec3(1.0, 0.25, 0.8), turn);
  const BoxPose small_local =
      box(Vec3(0.3, 0.35, -0.2), Vec3::Constant(0.1), rotation(0.4, Vec3::UnitY()));
  const BoxPose b =
      box(shift + turn * small_local.position, small_local.half_size, turn * small_local.rotation);
  const PairManifold m = box_box_manifold(a, b, kMargin);
  EXPECT_LE((m.normal - turn * Vec3::UnitY()).norm(), kExact);
  std::vector<Vec3> bottom;
  for (const Vec3& c : corners(b)) {
    if (std::abs((turn.transpose() * (c - shift)).y() - 0.25) < 1e-9) bottom.push_back(c);
  }
  ASSERT_EQ(bottom.size(), 4u);
  expect_points(a, m, bottom, kExact);
  for (int i = 0; i < m.count; ++i) EXPECT_NEAR(m.points[i].separation, 0.0, kExact);
}

// The area of the convex quadrilateral through four points, in the xz-plane (m²).
double quad_area_xz(std::vector<Vec3> points) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : points) centre += p / 4.0;
  std::sort(points.begin(), points.end(), [&](const Vec3& p, const Vec3& q) {
    return std::atan2(p.z() - centre.z(), p.x() - centre.x()) <
           std::atan2(q.z() - centre.z(), q.x() - centre.x());
  });
  double area = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3& p = points[i];
    const Vec3& q = points[(i + 1) % 4];
    area += p.x() * q.z() - q.x() * p.z();
  }
  return 0.5 * std::abs(area);
}

TEST(BoxBox, CubeTurnedFortyFiveDegreesKeepsTheLargestSquareOfTheOctagon) {
  // Two unit squares at 45° overlap in a regular octagon of inradius 0.5, circumradius
  // R = 0.5 / cos(π/8); the largest quadrilateral on its corners is the square of area 2 R².
  const BoxPose a = box(Vec3::Zero(), Vec3::Constant(0.5));
  const BoxPose b = box(Vec3(0.0, 0.99, 0.0), Vec3::Constant(0.5),
                        rotation(std::numbers::pi / 4.0, Vec3::UnitY()));
  const PairManifold m = box_box_manifold(a, b, kMargin);
  ASSERT_EQ(m.count, 4);
  EXPECT_LE((m.normal - Vec3::UnitY()).norm(), kExact);
  const double circumradius = 0.5 / std::cos(std::numbers::pi / 8.0);
  const std::vector<Vec3> points = world_points(a, m);
  for (int i = 0; i < m.count; ++i) {
    EXPECT_NEAR(m.points[i].separation, -0.01, kExact);
    const Vec3& p = points[static_cast<std::size_t>(i)];
    EXPECT_LE(std::max(std::abs(p.x()), std::abs(p.z())), 0.5 + 1e-9);  // A's top face
    EXPECT_LE(std::max(std::abs(p.x() + p.z()), std::abs(p.x() - p.z())) / std::sqrt(2.0),
              0.5 + 1e-9);                                      // B's bottom face
    EXPECT_NEAR(std::hypot(p.x(), p.z()), circumradius, 1e-9);  // a corner of the octagon
  }
  EXPECT_NEAR(quad_area_xz(points), 2.0 * circumradius * circumradius, 1e-9);
}

// The deepest point, under A's top face (y = 0.5, |x|, |z| <= 0.5), of the plane of B's bottom
// face within B's bottom face: a linear height over a convex polygon is lowest at a corner of it,
// and every corner is one of B's, a crossing of B's edges with A's sides, or one of A's corners.
double deepest_under_top_face(const BoxPose& b) {
  const auto on_b_face = [&](double s, double t) -> Vec3 {
    return b.position +
           b.rotation * Vec3(s * b.half_size.x(), -b.half_size.y(), t * b.half_size.z());
  };
  const auto in_a_face = [](const Vec3& p) {
    return std::max(std::abs(p.x()), std::abs(p.z())) <= 0.5 + 1e-12;
  };
  std::vector<Vec3> candidates;
  const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k) {
    const Vec3 p = on_b_face(signs[k][0], signs[k][1]);
    const Vec3 q = on_b_face(signs[(k + 1) % 4][0], signs[(k + 1) % 4][1]);
    if (in_a_face(p)) candidates.push_back(p);
    for (int coordinate : {0, 2}) {
      for (double side : {-0.5, 0.5}) {
        const double t = (side - p[coordinate]) / (q[coordinate] - p[coordinate]);
        const Vec3 crossing = p + t * (q - p);
        if (t >= 0.0 && t <= 1.0 && in_a_face(crossing)) candidates.push_back(crossing);
      }
    }
  }
  const Vec3 down = b.rotation.col(1);  // the bottom face's plane: down·(x − x₀) = 0
  const Vec3 origin = on_b_face(0.0, 0.0);
  for (double x : {-0.5, 0.5}) {
    for (double z : {-0.5, 0.5}) {
      const double y =
          origin.y() - (down.x() * (x - origin.x()) + down.z() * (z - origin.z())) / down.y();
      const Vec3 local = b.rotation.transpose() * (Vec3(x, y, z) - b.position);
      if (std::abs(local.x()) <= b.half_size.x() && std::abs(local.z()) <= b.half_size.z()) {
        candidates.push_back(Vec3(x, y, z));
      }
    }
  }
  double deepest = INFINITY;
  for (const Vec3& c : candidates) deepest = std::min(deepest, c.y() - 0.5);
  return deepest;
}

TEST(BoxBox, TiltedCubeTurnedFortyFiveDegreesKeepsTheDeepestPointOfTheOverlap) {
  const BoxPose a = box(Vec3::Zero(), Vec3::Constant(0.5));
  const BoxPose b =
      box(Vec3(0.03, 0.995, -0.02), Vec3::Constant(0.5),
          rotation(0.001, Vec3(1.0, 0.0, 0.3)) * rotation(std::numbers::pi / 4.0, Vec3::UnitY()));
  ASSERT_EQ(box_box_axis(a, b).kind, BoxAxisKind::face_a);
  const PairManifold m = box_box_manifold(a, b, kMargin);
  ASSERT_EQ(m.count, 4);
  double deepest = INFINITY;
  for (int i = 0; i < m.count; ++i) {
    deepest = std::min(deepest, m.points[i].separation);
    EXPECT_TRUE(inside(a, world_from_a(a, m.points[i]), 1e-9));
    // A point on one of B's bottom edges, moved up by half its depth (< 3 mm) to the midway,
    // leaves B's tilted side by up to 3 mm × sin(0.001 rad).
    EXPECT_TRUE(inside(b, world_from_b(b, m.points[i]), 3e-6));
  }
  EXPECT_LT(deepest, -0.0055);  // the tilt makes one side clearly deeper than the -5 mm sink
  EXPECT_NEAR(deepest, deepest_under_top_face(b), kExact);
}

// A unit cube turned 45° about z (its top an edge along z at height √2/2 above its centre) under
// one turned 45° about x (its bottom an edge along x), the bottom edge `gap` above the top edge.
struct CrossingEdges {
  BoxPose a;
  BoxPose b;
};
CrossingEdges crossing_edges(double gap /* m */) {
  const double half_diagonal = std::sqrt(0.5);
  return {box(Vec3(0.0, 0.0, 0.05), Vec3::Constant(0.5),
              rotation(std::numbers::pi / 4.0, Vec3::UnitZ())),
          box(Vec3(0.1, 2.0 * half_diagonal + gap, 0.0), Vec3::Constant(0.5),
              rotation(std::numbers::pi / 4.0, Vec3::UnitX()))};
}

TEST(BoxBox, CrossingEdgesGiveOnePointBetweenTheEdges) {
  for (const double gap : {-0.01, 0.0, 0.01}) {
    const auto [a, b] = crossing_edges(gap);
    ASSERT_EQ(box_box_axis(a, b).kind, BoxAxisKind::edge_pair) << gap;
    const PairManifold m = box_box_manifold(a, b, kMargin);
    ASSERT_EQ(m.count, 1) << gap;
    EXPECT_LE((m.normal - Vec3::UnitY()).norm(), kExact);
    EXPECT_NEAR(m.points[0].separation, gap, kExact);
    EXPECT_LE((world_from_a(a, m.points[0]) - Vec3(0.0, std::sqrt(0.5) + 0.5 * gap, 0.0)).norm(),
              kExact);
    EXPECT_LE((world_from_b(b, m.points[0]) - world_from_a(a, m.points[0])).norm(), kExact);
    EXPECT_EQ(m.points[0].feature & 3u, 2u);  // an edge pair
  }
  const auto [a, b] = crossing_edges(0.03);
  EXPECT_EQ(box_box_manifold(a, b, kMargin).count, 0);
}

TEST(BoxBox, CubeOnTheTopVertexOfATiltedCubeTouchesAtThatVertex) {
  // A's body diagonal turned upright puts a corner √3/2 above its centre.
  const Mat3 upright =
      Eigen::Quaterniond::FromTwoVectors(Vec3(1.0, 1.0, 1.0).normalized(), Vec3::UnitY())
          .toRotationMatrix();
  const double top = std::sqrt(3.0) / 2.0;
  for (const double gap : {-0.002, 0.005}) {
    const BoxPose a = box(Vec3::Zero(), Vec3::Constant(0.5), upright);
    const BoxPose b = box(Vec3(0.1, top + 0.5 + gap, -0.05), Vec3::Constant(0.5));
    EXPECT_EQ(box_box_axis(a, b).kind, BoxAxisKind::face_b);
    const PairManifold m = box_box_manifold(a, b, kMargin);
    ASSERT_EQ(m.count, 1) << gap;
    EXPECT_LE((m.normal - Vec3::UnitY()).norm(), kExact);
    EXPECT_NEAR(m.points[0].separation, gap, kExact);
    EXPECT_LE((world_from_a(a, m.points[0]) - Vec3(0.0, top + 0.5 * gap, 0.0)).norm(), kExact);
  }
}

TEST(BoxBox, ThinPlatesLyingAndStanding) {
  // A cube on a 2 cm plate: its four bottom corners.
  const BoxPose plate = box(Vec3::Zero(), Vec3(0.5, 0.01, 0.5));
  const BoxPose cube = box(Vec3(0.2, 0.01 + 0.2, -0.1), Vec3::Constant(0.2));
  const PairManifold on_plate = box_box_manifold(plate, cube, kMargin);
  expect_points(plate, on_plate,
                {{0.0, 0.01, -0.3}, {0.4, 0.01, -0.3}, {0.4, 0.01, 0.1}, {0.0, 0.01, 0.1}}, kExact);
  // A 2 cm plate standing on its long thin edge on a box, sunk 1 mm: the four corners of that edge.
  const BoxPose ground = box(Vec3::Zero(), Vec3(1.0, 0.5, 1.0));
  const BoxPose standing = box(Vec3(0.1, 0.5 + 0.3 - 0.001, 0.0), Vec3(0.4, 0.3, 0.01));
  const PairManifold on_edge = box_box_manifold(ground, standing, kMargin);
  expect_points(
      ground, on_edge,
      {{-0.3, 0.4995, -0.01}, {0.5, 0.4995, -0.01}, {0.5, 0.4995, 0.01}, {-0.3, 0.4995, 0.01}},
      kExact);
  for (int i = 0; i < on_edge.count; ++i) EXPECT_NEAR(on_edge.points[i].separation, -0.001, kExact);
}

TEST(BoxBox, BeyondTheMarginNothingWithinItSpeculativePoints) {
  const BoxPose a = box(Vec3::Zero(), Vec3::Constant(0.5));
  EXPECT_EQ(
      box_box_manifold(a, box(Vec3(0.0, 1.0 + kMargin + 1e-6, 0.0), Vec3::Constant(0.5)), kMargin)
          .count,
      0);
  EXPECT_EQ(
      box_box_manifold(a, box(Vec3(0.0, 1.0 + kMargin, 0.0), Vec3::Constant(0.5)), kMargin).count,
      0);
  const PairManifold near =
      box_box_manifold(a, box(Vec3(0.0, 1.012, 0.0), Vec3::Constant(0.5)), kMargin);
  ASSERT_EQ(near.count, 4);
  for (int i = 0; i < near.count; ++i) {
    EXPECT_NEAR(near.points[i].separation, 0.012, kExact);
    EXPECT_NEAR(world_from_a(a, near.points[i]).y(), 0.506, kExact);  // halfway across the gap
  }
  // Sideways: B beside A along −x.
  const PairManifold side =
      box_box_manifold(a, box(Vec3(-1.005, 0.2, 0.0), Vec3::Constant(0.5)), kMargin);
  EXPECT_EQ(side.count, 4);
  EXPECT_LE((side.normal + Vec3::UnitX()).norm(), kExact);
}

// (B, A) gives the normal negated and the same points, separations and count.
void expect_mirrored(const BoxPose& a, const BoxPose& b, double margin) {
  const PairManifold forward = box_box_manifold(a, b, margin);
  const PairManifold backward = box_box_manifold(b, a, margin);
  ASSERT_EQ(forward.count, backward.count);
  if (forward.count == 0) return;
  EXPECT_LE((forward.normal + backward.normal).norm(), kExact);
  for (int i = 0; i < forward.count; ++i) {
    const Vec3 p = world_from_a(a, forward.points[i]);
    int matches = 0;
    for (int j = 0; j < backward.count; ++j) {
      const PairPoint& q = backward.points[j];
      if ((world_from_b(a, q) - p).norm() <= kExact &&
          std::abs(q.separation - forward.points[i].separation) <= kExact) {
        ++matches;
      }
    }
    EXPECT_EQ(matches, 1) << "point " << p.transpose();
  }
}

TEST(BoxBox, SwappingTheBoxesMirrorsTheManifold) {
  const BoxPose unit = box(Vec3::Zero(), Vec3::Constant(0.5));
  expect_mirrored(unit, box(Vec3(0.0, 1.0, 0.0), Vec3::Constant(0.5)), kMargin);
  expect_mirrored(box(Vec3::Zero(), Vec3(2.0, 0.5, 2.0)),
                  box(Vec3(0.3, 0.99, -0.4), Vec3::Constant(0.5)), kMargin);
  expect_mirrored(unit,
                  box(Vec3(0.0, 0.99, 0.0), Vec3::Constant(0.5),
                      rotation(std::numbers::pi / 4.0, Vec3::UnitY())),
                  kMargin);
  for (const double gap : {-0.01, 0.01}) {
    const auto [a, b] = crossing_edges(gap);
    expect_mirrored(a, b, kMargin);
  }
}

TEST(BoxBox, SameInputsGiveTheSameBits) {
  const BoxPose a =
      box(Vec3(0.1, 0.2, 0.3), Vec3(0.4, 0.3, 0.2), rotation(0.3, Vec3(1.0, 2.0, 3.0)));
  const BoxPose b =
      box(Vec3(0.2, 0.75, 0.1), Vec3(0.3, 0.2, 0.25), rotation(1.1, Vec3(-1.0, 0.5, 2.0)));
  const PairManifold first = box_box_manifold(a, b, kMargin);
  const PairManifold second = box_box_manifold(a, b, kMargin);
  ASSERT_GT(first.count, 0);
  ASSERT_EQ(first.count, second.count);
  EXPECT_EQ(first.normal, second.normal);
  for (int i = 0; i < first.count; ++i) {
    EXPECT_EQ(first.points[i].feature, second.points[i].feature);
    EXPECT_EQ(first.points[i].point_a, second.points[i].point_a);
    EXPECT_EQ(first.points[i].point_b, second.points[i].point_b);
    EXPECT_EQ(first.points[i].separation, second.points[i].separation);
  }
}

// splitmix64 (Steele, Lea & Flood 2014): a fixed sequence on every platform, unlike std
// distributions.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform(double low, double high) {  // in [low, high)
    return low + (high - low) * static_cast<double>(next() >> 11) * 0x1.0p-53;
  }
  Vec3 vector(double low, double high) {
    return Vec3(uniform(low, high), uniform(low, high), uniform(low, high));
  }
  Mat3 rotation() {  // a uniform-enough rotation: a normalised quaternion from a ball
    for (;;) {
      const Eigen::Vector4d q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      if (q.norm() > 0.1 && q.norm() < 1.0)
        return Quat(q.x(), q.y(), q.z(), q.w()).normalized().toRotationMatrix();
    }
  }
};

TEST(BoxBox, FeatureIdsSurviveATinyMotionOfARestingPair) {
  const std::vector<std::pair<BoxPose, BoxPose>> resting = {
      {box(Vec3::Zero(), Vec3::Constant(0.5)), box(Vec3(0.0, 1.0, 0.0), Vec3::Constant(0.5))},
      {box(Vec3::Zero(), Vec3(1.0, 0.25, 0.8)),
       box(Vec3(0.3, 0.35, -0.2), Vec3::Constant(0.1), rotation(0.4, Vec3::UnitY()))},
      {box(Vec3::Zero(), Vec3(1.0, 0.5, 1.0)), box(Vec3(0.1, 0.8, 0.0), Vec3(0.4, 0.3, 0.01))},
  };
  SplitMix64 random{12};
  for (const auto& [a, b] : resting) {
    const PairManifold still = box_box_manifold(a, b, kMargin);
    ASSERT_EQ(still.count, 4);
    for (int trial = 0; trial < 50; ++trial) {
      BoxPose moved = b;
      moved.position += random.vector(-1e-6, 1e-6);
      moved.rotation = rotation(1e-6, random.vector(-1.0, 1.0)) * moved.rotation;
      const PairManifold m = box_box_manifold(a, moved, kMargin);
      EXPECT_EQ(features(m), features(still)) << "trial " << trial;
    }
  }
}

// The corner-projection separation along a unit axis from A towards B (m).
double corner_separation(const BoxPose& a, const BoxPose& b, const Vec3& normal) {
  double a_high = -INFINITY, b_low = INFINITY;
  for (const Vec3& c : corners(a)) a_high = std::max(a_high, normal.dot(c));
  for (const Vec3& c : corners(b)) b_low = std::min(b_low, normal.dot(c));
  return b_low - a_high;
}

// The separation along a unit axis either way round, from the corners (m).
double corner_separation_any_way(const BoxPose& a, const BoxPose& b, const Vec3& axis) {
  return std::max(corner_separation(a, b, axis), corner_separation(a, b, -axis));
}

// The choice box_box_axis should make, from corner projections: the largest separation among
// A's faces, B's faces and the non-parallel edge pairs, and which kind the bias picks.
struct BruteForceAxes {
  double face_a = -INFINITY, face_b = -INFINITY, edge = -INFINITY;
  double largest() const { return std::max({face_a, face_b, edge}); }
  BoxAxisKind expected_kind() const {
    const bool b_wins = face_b > face_a + box_axis_bias(face_a);
    const double face = b_wins ? face_b : face_a;
    if (edge > face + box_axis_bias(face)) return BoxAxisKind::edge_pair;
    return b_wins ? BoxAxisKind::face_b : BoxAxisKind::face_a;
  }
  // Within 1e-9 m of a bias threshold, either choice is right.
  bool near_a_threshold() const {
    const double face = std::max(face_a, face_b);
    return std::abs(face_b - face_a - box_axis_bias(face_a)) < 1e-9 ||
           std::abs(edge - face_a - box_axis_bias(face_a)) < 1e-9 ||
           std::abs(edge - face - box_axis_bias(face)) < 1e-9;
  }
};

BruteForceAxes brute_force_axes(const BoxPose& a, const BoxPose& b) {
  BruteForceAxes out;
  for (int k = 0; k < 3; ++k) {
    out.face_a = std::max(out.face_a, corner_separation_any_way(a, b, a.rotation.col(k)));
    out.face_b = std::max(out.face_b, corner_separation_any_way(a, b, b.rotation.col(k)));
    for (int j = 0; j < 3; ++j) {
      const Vec3 cross = a.rotation.col(k).cross(b.rotation.col(j));
      if (cross.norm() < kParallelEdgeSine) continue;
      out.edge = std::max(out.edge, corner_separation_any_way(a, b, cross.normalized()));
    }
  }
  return out;
}

// Random boxes from 1 cm to 1.2 m a side, turned anyhow, placed near touching: separations from
// −5 cm to 5 cm.
std::vector<std::pair<BoxPose, BoxPose>> random_near_pairs(int count) {
  SplitMix64 random{20261201};
  std::vector<std::pair<BoxPose, BoxPose>> out;
  while (static_cast<int>(out.size()) < count) {
    const BoxPose a = box(random.vector(-1.0, 1.0), random.vector(0.005, 0.6), random.rotation());
    const Vec3 half_b = random.vector(0.005, 0.6);
    const double reach = a.half_size.norm() + half_b.norm();
    const BoxPose b = box(a.position + random.vector(-reach, reach), half_b, random.rotation());
    const double separation = box_box_axis(a, b).separation;
    if (separation > -0.05 && separation < 0.05) out.emplace_back(a, b);
  }
  return out;
}

TEST(BoxBox, RandomPosesAgreeWithABruteForceSeparatingAxisTest) {
  int overlapping = 0;
  for (const auto& [a, b] : random_near_pairs(3000)) {
    const BoxAxis axis = box_box_axis(a, b);
    const BruteForceAxes brute = brute_force_axes(a, b);
    EXPECT_NEAR(axis.normal.norm(), 1.0, kExact);
    EXPECT_NEAR(axis.separation, corner_separation(a, b, axis.normal), 1e-9);
    if (!brute.near_a_threshold()) {
      EXPECT_EQ(axis.kind, brute.expected_kind());
    }
    EXPECT_LE(axis.separation, brute.largest() + 1e-9);
    EXPECT_GE(axis.separation, brute.largest() - 2.0 * box_axis_bias(brute.largest()) - 1e-9);

    const PairManifold m = box_box_manifold(a, b, kMargin);
    ASSERT_LE(m.count, 4);
    if (brute.largest() < 0.0) {
      ++overlapping;
      EXPECT_GE(m.count, 1) << "overlapping boxes with no contact";
    }
    if (m.count == 0) continue;
    EXPECT_NEAR(m.normal.norm(), 1.0, kExact);
    EXPECT_EQ(features(m).size(), static_cast<std::size_t>(m.count)) << "ids not unique";
    for (int i = 0; i < m.count; ++i) {
      const PairPoint& p = m.points[i];
      const Vec3 world = world_from_a(a, p);
      EXPECT_LE((world_from_b(b, p) - world).norm(), kExact);
      EXPECT_TRUE(inside(a, world, kMargin + 1e-9)) << world.transpose();
      EXPECT_TRUE(inside(b, world, kMargin + 1e-9)) << world.transpose();
      EXPECT_LT(p.separation, kMargin);
      // No point is deeper than the boxes overlap along the normal.
      if ((m.normal - axis.normal).norm() < kExact) {
        EXPECT_GE(p.separation, axis.separation - 1e-9);
      }
    }
  }
  EXPECT_GT(overlapping, 500);  // the sample exercises overlap, not only speculative contact
}

TEST(BoxBox, NearlyFlushEqualCubesGiveAtMostFourUniquePoints) {
  // Corners within a few clip slacks (10 µm) of the other cube's sides, turned by 0.1 µrad to
  // 1 mrad: the slack's own corner cases.
  SplitMix64 random{7};
  const BoxPose a = box(Vec3::Zero(), Vec3::Constant(0.5));
  for (int trial = 0; trial < 2000; ++trial) {
    const double angle = std::pow(10.0, random.uniform(-7.0, -3.0));
    Vec3 offset = random.vector(-3e-5, 3e-5);
    offset.y() = 1.0 + random.uniform(-1e-3, 1e-3);
    const BoxPose b = box(offset, Vec3::Constant(0.5), rotation(angle, random.vector(-1.0, 1.0)));
    const PairManifold m = box_box_manifold(a, b, kMargin);
    ASSERT_GE(m.count, 1);
    ASSERT_LE(m.count, 4);
    EXPECT_EQ(features(m).size(), static_cast<std::size_t>(m.count)) << "trial " << trial;
    for (int i = 0; i < m.count; ++i) {
      EXPECT_TRUE(inside(a, world_from_a(a, m.points[i]), 1e-3 + 1e-9)) << "trial " << trial;
      EXPECT_TRUE(inside(b, world_from_b(b, m.points[i]), 1e-3 + 1e-9)) << "trial " << trial;
    }
  }
}

TEST(BoxBox, RandomPosesMirrorWhenBothOrdersChooseTheSameFeature) {
  int mirrored = 0;
  const auto pairs = random_near_pairs(1000);
  for (const auto& [a, b] : pairs) {
    const BoxAxisKind forward = box_box_axis(a, b).kind;
    const BoxAxisKind backward = box_box_axis(b, a).kind;
    const bool same_feature =
        (forward == BoxAxisKind::edge_pair && backward == BoxAxisKind::edge_pair) ||
        (forward == BoxAxisKind::face_a && backward == BoxAxisKind::face_b) ||
        (forward == BoxAxisKind::face_b && backward == BoxAxisKind::face_a);
    if (!same_feature) continue;  // a tie inside the bias: each order keeps its own A's face
    ++mirrored;
    expect_mirrored(a, b, kMargin);
  }
  EXPECT_GT(mirrored, 800);
}

}  // namespace
}  // namespace tumble::physics
