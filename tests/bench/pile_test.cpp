// The pile of `contact_bench`: a pure function of (count, seed), and a start that no engine can
// object to (no two boxes touching, every box inside the bin, the materials and step it states).
#include "bench/pile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace tumble::bench {
namespace {

using physics::Vec3;

// The reference output of splitmix64 from state 0 (Vigna's splitmix64.c).
TEST(Pile, SplitMixGivesTheReferenceSequence) {
  SplitMix64 random(0);
  EXPECT_EQ(random.next(), 0xe220a8397b1dcdafull);
  EXPECT_EQ(random.next(), 0x6e789e6aa1b965f4ull);
}

TEST(Pile, UniformStaysInItsHalfOpenRange) {
  SplitMix64 random(7);
  for (int n = 0; n < 100000; ++n) {
    const double u = random.uniform(0.2, 0.6);
    ASSERT_GE(u, 0.2);
    ASSERT_LT(u, 0.6);
  }
}

TEST(Pile, NoTwoStartBoxesOverlap) {
  for (const std::uint64_t seed : {1ull, 2ull, 12345ull}) {
    const Pile pile = make_pile(1000, seed);
    for (std::size_t i = 0; i < pile.boxes.size(); ++i) {
      for (std::size_t j = i + 1; j < pile.boxes.size(); ++j) {
        const double gap = (pile.boxes[i].position - pile.boxes[j].position).norm() -
                           bounding_radius(pile.boxes[i]) - bounding_radius(pile.boxes[j]);
        ASSERT_GT(gap, 0.0) << "boxes " << i << " and " << j << ", seed " << seed;
      }
    }
  }
}

// Whole bounding spheres inside the walls and above the floor, not only the centres.
TEST(Pile, EveryStartBoxIsInsideTheBin) {
  const Pile pile = make_pile(1000, 1);
  for (const PileBox& box : pile.boxes) {
    EXPECT_TRUE(inside_bin(pile, box.position));
    for (const physics::Plane& plane : pile.planes) {
      EXPECT_GT(separation(plane, box.position), bounding_radius(box));
    }
  }
}

TEST(Pile, BoxesHaveTheStatedSizesMassesAndMotion) {
  const Pile pile = make_pile(1000, 1);
  ASSERT_EQ(pile.boxes.size(), 1000u);
  for (const PileBox& box : pile.boxes) {
    EXPECT_GE(box.size.minCoeff(), 0.2);
    EXPECT_LT(box.size.maxCoeff(), 0.6);
    EXPECT_NEAR(box.mass, 500.0 * box.size.prod(), 1e-12);  // kg at 500 kg/m³
    EXPECT_NEAR(box.orientation.norm(), 1.0, 1e-15);
    EXPECT_LE(box.velocity.cwiseAbs().maxCoeff(), 0.25);
    EXPECT_LE(box.angular_velocity.cwiseAbs().maxCoeff(), 1.0);
  }
  // Mixed, not all alike: the sizes spread over most of their range.
  double smallest = 1.0, largest = 0.0;
  for (const PileBox& box : pile.boxes) {
    smallest = std::min(smallest, box.size.minCoeff());
    largest = std::max(largest, box.size.maxCoeff());
  }
  EXPECT_LT(smallest, 0.21);
  EXPECT_GT(largest, 0.59);
}

// A mixed pile: a box, a ball, a capsule, a cylinder and a hull in turn, each of the same draws
// as the box pile's, its mass from its own volume (a capsule's: π r² l + 4/3 π r³; a cylinder's
// π r² l; the hull's, the box's cuboctahedron, 5/6 of the box's); a capsule reaches at most half
// the drawn box's x edge past its y edge, at most 0.9 m end to end, inside the 1.04 m diagonal of
// the largest box its start cell is made for; the others fit in the drawn box.
TEST(Pile, AMixedPileIsEveryShapeInTurn) {
  const Pile boxes = make_pile(300, 4);
  const Pile mixed = make_pile(300, 4, 20.0, PileShapes::mixed);
  ASSERT_EQ(mixed.boxes.size(), 300u);
  for (std::size_t i = 0; i < mixed.boxes.size(); ++i) {
    const PileBox& box = mixed.boxes[i];
    const PileBox& drawn = boxes.boxes[i];
    EXPECT_EQ(box.position, drawn.position);
    const Vec3& d = drawn.size;
    switch (i % 5) {
      case 0:
        EXPECT_EQ(shape_of(box).kind, physics::ShapeKind::box);
        EXPECT_EQ(box.size, d);
        break;
      case 1:
        EXPECT_EQ(shape_of(box).kind, physics::ShapeKind::sphere);
        EXPECT_EQ(box.radius, 0.5 * d.x());
        break;
      case 2: {
        const double r = 0.25 * d.x(), l = d.y();
        EXPECT_EQ(shape_of(box).kind, physics::ShapeKind::capsule);
        EXPECT_EQ(box.radius, r);
        EXPECT_EQ(box.length, l);
        EXPECT_NEAR(box.mass, 500.0 * std::numbers::pi * r * r * (l + 4.0 / 3.0 * r), 1e-12);
        EXPECT_LE(box.size.y(), d.y() + d.x() / 2.0 + 1e-15);
        break;
      }
      case 3: {
        const double r = 0.5 * d.x(), l = d.y();
        EXPECT_EQ(shape_of(box).kind, physics::ShapeKind::cylinder);
        EXPECT_NEAR(box.mass, 500.0 * std::numbers::pi * r * r * l, 1e-12);
        EXPECT_NEAR(constants_of(box).inertia.y(), 0.5 * box.mass * r * r, 1e-15);
        break;
      }
      default: {
        EXPECT_EQ(shape_of(box).kind, physics::ShapeKind::hull);
        ASSERT_NE(box.hull, nullptr);
        EXPECT_EQ(box.hull->hull->vertices.size(), 12u);
        EXPECT_EQ(box.hull->hull->faces.size(), 14u);
        EXPECT_NEAR(box.mass, 500.0 * 5.0 / 6.0 * d.x() * d.y() * d.z(), 1e-12);
        EXPECT_LT(box.hull->centre.norm(), 1e-12);
        for (const Vec3& c : box.hull->hull->vertices) EXPECT_LE(c.norm(), 0.5 * d.norm());
        break;
      }
    }
  }
  EXPECT_NE(mixed.summary.find("mixed"), std::string::npos) << mixed.summary;
}

TEST(Pile, TheBinIsAFloorAndFourWallsThreeMetresOut) {
  const Pile pile = make_pile(10, 1);
  ASSERT_EQ(pile.planes.size(), 5u);
  EXPECT_EQ(pile.planes[0].normal, Vec3::UnitY());
  EXPECT_EQ(pile.planes[0].offset, 0.0);
  for (std::size_t n = 1; n < pile.planes.size(); ++n) {
    const physics::Plane& wall = pile.planes[n];
    EXPECT_EQ(wall.normal.y(), 0.0);
    EXPECT_EQ(wall.offset, -3.0);                             // 3 m from the axis
    EXPECT_NEAR(separation(wall, Vec3::Zero()), 3.0, 1e-15);  // facing into the bin
  }
  for (const physics::Plane& plane : pile.planes) {
    EXPECT_EQ(plane.material.restitution, 0.1);
    EXPECT_EQ(plane.material.friction, 0.5);
  }
  EXPECT_EQ(pile.box_material.restitution, 0.1);
  EXPECT_EQ(pile.box_material.friction, 0.5);
  EXPECT_EQ(pile.gravity, Vec3(0.0, -9.81, 0.0));
}

TEST(Pile, RunsTwentySecondsInStepsOfOneSixtieth) {
  const Pile pile = make_pile(10, 1);
  EXPECT_EQ(pile.dt, 1.0 / 60.0);
  EXPECT_EQ(pile.steps, 1200);
  EXPECT_EQ(make_pile(10, 1, 4.0).steps, 240);
}

TEST(Pile, TheSameCountAndSeedGiveTheSameBits) {
  const Pile a = make_pile(200, 9), b = make_pile(200, 9), c = make_pile(200, 10);
  bool differs = false;
  for (std::size_t n = 0; n < a.boxes.size(); ++n) {
    EXPECT_EQ(a.boxes[n].size, b.boxes[n].size);
    EXPECT_EQ(a.boxes[n].position, b.boxes[n].position);
    EXPECT_EQ(a.boxes[n].orientation.coeffs(), b.boxes[n].orientation.coeffs());
    EXPECT_EQ(a.boxes[n].velocity, b.boxes[n].velocity);
    EXPECT_EQ(a.boxes[n].angular_velocity, b.boxes[n].angular_velocity);
    differs = differs || a.boxes[n].size != c.boxes[n].size;
  }
  EXPECT_TRUE(differs);
}

// Fewer boxes are a prefix of more: the pile grows by adding boxes on top, so a small test pile
// is the bottom of the benchmark's.
TEST(Pile, AFewerBoxPileIsThePrefixOfALargerOne) {
  const Pile small = make_pile(60, 1), large = make_pile(1000, 1);
  for (std::size_t n = 0; n < small.boxes.size(); ++n) {
    EXPECT_EQ(small.boxes[n].size, large.boxes[n].size);
    EXPECT_EQ(small.boxes[n].position, large.boxes[n].position);
  }
}

TEST(Pile, InsideBinIsTheWallsAndTheFloor) {
  const Pile pile = make_pile(0, 1);
  EXPECT_TRUE(inside_bin(pile, Vec3(3.0, 0.0, -3.0)));
  EXPECT_FALSE(inside_bin(pile, Vec3(3.01, 1.0, 0.0)));
  EXPECT_FALSE(inside_bin(pile, Vec3(0.0, 1.0, -3.01)));
  EXPECT_FALSE(inside_bin(pile, Vec3(0.0, -0.01, 0.0)));
}

// The depth of a pile's poses is the deepest of the boxes' overlaps with each other and with the
// planes, from the poses alone: two unit cubes 3 cm into each other face-on, a third 2 cm into
// the floor, a fourth turned 45 degrees about y and 5 cm into the wall at x = 3 with a corner.
TEST(Pile, DepthIsTheDeepestOverlapOfThePoses) {
  Pile pile = make_pile(0, 1);
  PileBox unit;
  unit.size = Vec3::Ones();
  unit.mass = 1.0;
  pile.boxes.assign(4, unit);
  const Vec3 half(0.5, 0.5, 0.5);
  const physics::Mat3 turned =
      Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitY()).toRotationMatrix();
  std::vector<physics::BoxPose> poses = {
      {.position = Vec3(-1.0, 2.0, 0.0), .rotation = physics::Mat3::Identity(), .half_size = half},
      {.position = Vec3(-0.03, 2.0, 0.0), .rotation = physics::Mat3::Identity(), .half_size = half},
      {.position = Vec3(0.0, 0.48, -1.5),
       .rotation = physics::Mat3::Identity(),
       .half_size = half}};
  PileDepth depth;
  EXPECT_NEAR(depth(pile, poses), 0.03, 1e-12);
  poses[1].position.x() = 0.1;  // apart: the floor's 2 cm is the deepest
  EXPECT_NEAR(depth(pile, poses), 0.02, 1e-12);
  poses.push_back(
      {.position = Vec3(3.05 - std::sqrt(0.5), 1.0, 1.5), .rotation = turned, .half_size = half});
  EXPECT_NEAR(depth(pile, poses), 0.05, 1e-12);
  // The fourth a ball of radius 0.5 instead, 0.1 m into the third's top face.
  pile.boxes[3].kind = PileKind::ball;
  pile.boxes[3].radius = 0.5;
  poses[3] = {.position = Vec3(0.0, 1.38, -1.5), .half_size = half};
  EXPECT_NEAR(depth(pile, poses), 0.1, 1e-12);
}

}  // namespace
}  // namespace tumble::bench
