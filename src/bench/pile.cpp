#include "bench/pile.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "physics/contact.hpp"
#include "physics/mass_properties.hpp"
#include "physics/pair_contact.hpp"

namespace tumble::bench {
namespace {

using physics::Quat;
using physics::Vec3;

constexpr double kStep = 1.0 / 60.0;   // s: the video rate, no sub-steps
constexpr double kBinHalfWidth = 3.0;  // m: a 6 x 6 m bin
constexpr double kMinEdge = 0.2;       // m, per axis, drawn independently
constexpr double kMaxEdge = 0.6;       // m
constexpr double kDensity = 500.0;     // kg/m³ (soft wood): 4 kg to 108 kg
constexpr double kRestitution = 0.1;   // boxes and planes alike: a dull knock, no rebound show
constexpr double kFriction = 0.5;      // boxes and planes alike: wood on wood
constexpr double kMaxSpeed = 0.25;     // m/s, per axis, of the initial velocity
constexpr double kMaxSpin = 1.0;       // rad/s, per world axis, of the initial spin
constexpr int kColumns = 5;            // boxes per row and per column of a layer
// Cell pitch, horizontal and vertical (m): above the largest bounding diameter, √3 · 0.6 =
// 1.039 m, so that no two boxes touch in any orientation. A 5 x 5 grid keeps the column (40
// layers for 1000 boxes, top at 44 m, landing at ≤ 29 m/s) lower than a 3 x 3 one would (112
// layers, 123 m, 49 m/s: more than a box per step, which measures tunnelling, not piling), and
// its outer boxes reach 2.2 + 0.52 m from the axis, inside the 3 m walls.
constexpr double kPitch = 1.1;
constexpr double kFirstLayerHeight = 1.0;  // m: the lowest centres; their spheres clear the floor

static_assert(kPitch > 2.0 * 0.5 * kMaxEdge * std::numbers::sqrt3);
static_assert(0.5 * (kColumns - 1) * kPitch + 0.5 * kMaxEdge * std::numbers::sqrt3 < kBinHalfWidth);

// A uniformly distributed rotation from three uniforms in [0, 1) (Shoemake, "Uniform random
// rotations", Graphics Gems III, 1992).
Quat random_orientation(SplitMix64& random) {
  const double u1 = random.uniform(), u2 = random.uniform(), u3 = random.uniform();
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double turn = 2.0 * std::numbers::pi;
  return Quat(b * std::cos(turn * u3), a * std::sin(turn * u2), a * std::cos(turn * u2),
              b * std::sin(turn * u3))
      .normalized();
}

Vec3 random_vector(SplitMix64& random, double half_range) {
  const double x = random.uniform(-half_range, half_range);
  const double y = random.uniform(-half_range, half_range);
  const double z = random.uniform(-half_range, half_range);
  return Vec3(x, y, z);
}

// The centre of the cell of box `index`: layers of kColumns² from the bottom up, each filled row
// by row, centred on the bin's axis.
Vec3 cell_centre(int index) {
  const int per_layer = kColumns * kColumns;
  const int layer = index / per_layer, row = index % per_layer / kColumns;
  const int column = index % kColumns;
  const double first = -0.5 * (kColumns - 1) * kPitch;
  return Vec3(first + column * kPitch, kFirstLayerHeight + layer * kPitch, first + row * kPitch);
}

std::vector<physics::Plane> bin_planes(const physics::Material& material) {
  const double w = kBinHalfWidth;
  // n·x >= offset inside: the floor y >= 0, then x >= -w, -x >= -w, z >= -w, -z >= -w.
  return {{.normal = Vec3::UnitY(), .offset = 0.0, .material = material},
          {.normal = Vec3::UnitX(), .offset = -w, .material = material},
          {.normal = -Vec3::UnitX(), .offset = -w, .material = material},
          {.normal = Vec3::UnitZ(), .offset = -w, .material = material},
          {.normal = -Vec3::UnitZ(), .offset = -w, .material = material}};
}

std::string summary(int bodies, std::uint64_t seed, const Pile& pile, PileShapes shapes) {
  char text[256];
  std::snprintf(text, sizeof text,
                "%d %s (seed %llu), %s %.1f-%.1f m, %.0f kg/m3, restitution %.2f, friction "
                "%.2f, bin %.0f x %.0f m, dt 1/%.0f s, %d steps",
                bodies, pile_shapes_name(shapes), static_cast<unsigned long long>(seed),
                shapes == PileShapes::balls ? "diameters"
                : shapes == PileShapes::mixed
                    ? "boxes, balls, capsules, cylinders and hulls in turn, edges"
                    : "edges",
                kMinEdge, kMaxEdge, kDensity, kRestitution, kFriction, 2 * kBinHalfWidth,
                2 * kBinHalfWidth, 1.0 / kStep, pile.steps);
  return text;
}

}  // namespace

std::uint64_t SplitMix64::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double SplitMix64::uniform() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

Pile make_pile(int bodies, std::uint64_t seed, double seconds, PileShapes shapes) {
  assert(bodies >= 0 && seconds >= 0.0);
  Pile pile;
  pile.box_material = {.restitution = kRestitution, .friction = kFriction};
  pile.planes = bin_planes(pile.box_material);
  pile.bin_half_width = kBinHalfWidth;
  pile.gravity = Vec3(0.0, -9.81, 0.0);
  pile.dt = kStep;
  pile.steps = static_cast<int>(std::lround(seconds / kStep));
  SplitMix64 random(seed);
  pile.boxes.reserve(static_cast<std::size_t>(bodies));
  for (int i = 0; i < bodies; ++i) {
    PileBox box;
    const double x = random.uniform(kMinEdge, kMaxEdge);
    const double y = random.uniform(kMinEdge, kMaxEdge);
    const double z = random.uniform(kMinEdge, kMaxEdge);
    box.kind = shapes == PileShapes::mixed   ? static_cast<PileKind>(i % 5)
               : shapes == PileShapes::balls ? PileKind::ball
                                             : PileKind::box;
    switch (box.kind) {
      case PileKind::ball:  // a ball of the first edge's diameter
        box.radius = 0.5 * x;
        box.size = Vec3::Constant(x);
        box.mass = kDensity * std::numbers::pi / 6.0 * x * x * x;
        break;
      case PileKind::capsule: {  // diameter x / 2, length y between its end centres
        box.radius = 0.25 * x;
        box.length = y;
        box.size = Vec3(2.0 * box.radius, y + 2.0 * box.radius, 2.0 * box.radius);
        const double r = box.radius;
        box.mass = kDensity * std::numbers::pi * r * r * (y + 4.0 / 3.0 * r);
        break;
      }
      case PileKind::cylinder:  // diameter x, length y
        box.radius = 0.5 * x;
        box.length = y;
        box.size = Vec3(x, y, x);
        box.mass = kDensity * std::numbers::pi * box.radius * box.radius * y;
        break;
      case PileKind::hull: {  // the box's cuboctahedron: 5/6 of its volume
        box.size = Vec3(x, y, z);
        box.mass = kDensity * 5.0 / 6.0 * x * y * z;
        const Vec3 h = 0.5 * box.size;
        std::vector<Vec3> middles;
        for (const double s : {-1.0, 1.0}) {
          for (const double t : {-1.0, 1.0}) {
            middles.push_back(Vec3(s * h.x(), t * h.y(), 0.0));
            middles.push_back(Vec3(s * h.x(), 0.0, t * h.z()));
            middles.push_back(Vec3(0.0, s * h.y(), t * h.z()));
          }
        }
        box.hull = std::make_shared<const physics::HullBody>(
            physics::hull_body(middles, box.mass).value());
        break;
      }
      case PileKind::box:
        box.size = Vec3(x, y, z);
        box.mass = kDensity * x * y * z;
        break;
    }
    box.position = cell_centre(i);
    box.orientation = random_orientation(random);
    box.velocity = random_vector(random, kMaxSpeed);
    box.angular_velocity = random_vector(random, kMaxSpin);
    pile.boxes.push_back(box);
  }
  pile.summary = summary(bodies, seed, pile, shapes);
  return pile;
}

bool inside_bin(const Pile& pile, const physics::Vec3& centre) {
  const double w = pile.bin_half_width;
  return std::abs(centre.x()) <= w && std::abs(centre.z()) <= w && centre.y() >= 0.0;
}

const char* pile_shapes_name(PileShapes shapes) {
  return shapes == PileShapes::balls ? "balls" : shapes == PileShapes::mixed ? "mixed" : "boxes";
}

physics::Shape shape_of(const PileBox& box) {
  switch (box.kind) {
    case PileKind::ball:
      return physics::sphere_shape(box.radius);
    case PileKind::capsule:
      return physics::capsule_shape(box.radius, 0.5 * box.length);
    case PileKind::cylinder:
      return physics::cylinder_shape(box.radius, 0.5 * box.length);
    case PileKind::hull:
      return physics::hull_shape(box.hull->hull);
    case PileKind::box:
      break;
  }
  return physics::box_shape(0.5 * box.size);
}

physics::BodyConstants constants_of(const PileBox& box) {
  switch (box.kind) {
    case PileKind::ball:
      return physics::sphere_constants(box.mass, box.radius);
    case PileKind::capsule:
      return physics::constants_from_moments(
          box.mass, physics::capsule_inertia(box.mass, box.radius, box.length).diagonal());
    case PileKind::cylinder:
      return physics::constants_from_moments(
          box.mass, physics::cylinder_inertia(box.mass, box.radius, box.length).diagonal());
    case PileKind::hull:
      return box.hull->constants;
    case PileKind::box:
      break;
  }
  return physics::box_constants(box.mass, box.size);
}

double PileDepth::operator()(const Pile& pile, std::span<const physics::BoxPose> poses) {
  double deepest = 0.0;
  bounds_.clear();
  shapes_.clear();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const physics::BoxPose& pose = poses[i];
    shapes_.push_back(shape_of(pile.boxes[i]));
    for (const physics::Plane& plane : pile.planes) {
      const physics::CornerSeparations s =
          physics::plane_separations(shapes_.back(), pose.rotation, pose.position, plane);
      deepest = std::max(deepest, -*std::min_element(s.begin(), s.end()));
    }
    bounds_.push_back(physics::box_bounds(pose.position, pose.rotation, pose.half_size, 0.0));
  }
  physics::overlapping_pairs(bounds_, order_, pairs_);
  for (const auto& [a, b] : pairs_) {
    const physics::PairManifold m =
        physics::pair_manifold({poses[a].position, poses[a].rotation, &shapes_[a]},
                               {poses[b].position, poses[b].rotation, &shapes_[b]}, 0.0);
    for (int k = 0; k < m.count; ++k) {
      deepest = std::max(deepest, -m.points[static_cast<std::size_t>(k)].separation);
    }
  }
  return deepest;
}

double bounding_radius(const PileBox& box) {
  return 0.5 * box.size.norm();
}

}  // namespace tumble::bench
