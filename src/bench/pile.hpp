// The pile of `tumble bench contact` (issue 12): boxes of mixed sizes poured from a column into a
// walled bin. Plain data, the same for every engine that runs it (tumble, and Bullet as a peer),
// and a pure function of (body count, seed), so two runs and two engines start from equal bits.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "physics/box_box.hpp"
#include "physics/broad_phase.hpp"
#include "physics/hull_shape.hpp"
#include "physics/rigid_body.hpp"
#include "physics/shapes.hpp"

namespace tumble::bench {

// What a pile is poured of: boxes, balls (spheres of the same size range: diameters 0.2 to
// 0.6 m), or mixed: a box, a ball, a capsule, a cylinder and a hull in turn, each from the same
// three edges drawn (the capsule's diameter half the first edge, its length between its end
// centres the second; the cylinder's diameter the first, its length the second; the hull the
// cuboctahedron of the box: the hull of its edges' midpoints, 12 corners, 14 faces).
enum class PileShapes { boxes, balls, mixed };
// Their names on command lines and in the pile's summary.
inline const std::map<std::string, PileShapes> kPileShapesByName = {
    {"boxes", PileShapes::boxes}, {"balls", PileShapes::balls}, {"mixed", PileShapes::mixed}};
const char* pile_shapes_name(PileShapes shapes);

enum class PileKind : std::uint8_t { box, ball, capsule, cylinder, hull };

// One body at the start of the pour.
struct PileBox {
  PileKind kind = PileKind::box;
  physics::Vec3 size;   // edge lengths along the body axes (m); the box another shape fits
  double radius = 0.0;  // m: a ball's, a capsule's or a cylinder's
  double length = 0.0;  // m: a capsule's (between its end centres) or a cylinder's
  // A hull's corners and constants (body frame: its centre of mass, its principal axes).
  std::shared_ptr<const physics::HullBody> hull;
  double mass = 0.0;               // kg
  physics::Vec3 position;          // centre of mass, world frame (m)
  physics::Quat orientation;       // body-to-world rotation, unit, (w, x, y, z)
  physics::Vec3 velocity;          // world frame (m/s)
  physics::Vec3 angular_velocity;  // world frame (rad/s)
};

struct Pile {
  std::vector<PileBox> boxes;
  physics::Material box_material;  // every box's surface
  // The floor (first), then the walls at x = +-half_width and z = +-half_width, normals pointing
  // into the bin. Each plane's point is normal * offset.
  std::vector<physics::Plane> planes;
  double bin_half_width = 0.0;  // m: the walls' distance from the bin's vertical axis
  physics::Vec3 gravity;        // world frame (m/s²)
  double dt = 0.0;              // s per step
  int steps = 0;                // steps in the run
  // One line for people: the count, seed, size range, density, materials, bin and step.
  std::string summary;
};

// The pile of `bodies` boxes or balls (>= 0) drawn from `seed`, run for `seconds` (s, rounded to
// whole steps of 1/60 s).
Pile make_pile(int bodies, std::uint64_t seed, double seconds = 20.0,
               PileShapes shapes = PileShapes::boxes);

// A pile body's shape for tumble's contact: its box, or its ball.
physics::Shape shape_of(const PileBox& box);
// Its constants: a uniform box's, or a uniform ball's.
physics::BodyConstants constants_of(const PileBox& box);

// Whether a box centre (world frame, m) is still in the bin: |x|, |z| <= half width and y >= 0.
bool inside_bin(const Pile& pile, const physics::Vec3& centre);

// The deepest any body of the pile is inside a plane or another body (m, >= 0), measured from the
// poses alone (every pair whose bounds overlap, by its manifold, physics/pair_contact.hpp), so
// that every engine's poses are judged alike, at the end of each step.
// Not an engine's own manifolds: they are found at the start of a step (or a sub-step), and a box
// that a landing neighbour stops within the step can end it far inside that neighbour (tumble's
// pour, seed 1: 13.7 cm, while its manifolds said 1.5 cm). Keeps its scratch between calls.
class PileDepth {
 public:
  // `poses[i]` is body i's centre (world, m) and rotation (body to world).
  double operator()(const Pile& pile, std::span<const physics::BoxPose> poses);

 private:
  std::vector<physics::Shape> shapes_;
  std::vector<physics::Bounds> bounds_;
  std::vector<std::uint32_t> order_;
  std::vector<physics::BodyPair> pairs_;
};

// The radius of a box's bounding sphere (m): half its diagonal.
double bounding_radius(const PileBox& box);

// splitmix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number generators", OOPSLA
// 2014; constants as in Vigna's reference code): one 64-bit state, passes BigCrush, and gives
// the same numbers on every compiler, which std distributions do not promise.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  // Uniform in [0, 1): the top 53 bits as a double's mantissa.
  double uniform();
  // Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

 private:
  std::uint64_t state_;
};

}  // namespace tumble::bench
