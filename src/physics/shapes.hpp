// The shapes of bodies (boxes and spheres), the static planes they touch (floor, walls, slopes),
// and the surface material that a contact between two shapes combines.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>

#include "physics/convex_hull.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::physics {

// Surface properties of one shape.
struct Material {
  double restitution = 0.0;  // e in [0, 1]: normal speed kept by a bounce
  double friction = 0.5;     // Coulomb coefficient μ >= 0
  // The lever arm of rolling friction (m, >= 0): a contact resists the turning of its bodies
  // against each other about any axis across its normal with a torque of at most this times its
  // normal force (MuJoCo's rolling friction; Box2D v3's and Box3D's rolling resistance), so a ball
  // rolling on a floor comes to rest. 0: no such row is solved.
  double rolling_resistance = 0.0;
};

// What a pair of shapes uses: restitution = max(a, b), friction = sqrt(a b) (as Box2D mixes
// them), so a bouncy ball bounces on any floor and an ice surface is slippery under any shoe;
// rolling resistance = max(a, b) (as Box3D mixes it).
Material combine(const Material& a, const Material& b);

// What a body is, for contact: a box, or a round shape that is a core with `radius` of rounding
// around it, as Box2D and Box3D model rounded shapes: a sphere (its core a point) or a capsule (its
// core a segment of `half_length` either side of the centre along the body's y axis); or a
// cylinder of `radius` along body y, its flat ends `half_length` either side of the centre; or a
// convex hull (physics/hull_shape.hpp). The shape is in the body frame, centred on the centre of
// mass.
enum class ShapeKind : std::uint8_t { box, sphere, capsule, cylinder, hull };

struct Shape {
  ShapeKind kind = ShapeKind::box;
  // Half the edges of the box the shape fits in, along the body axes (m): the box itself for a
  // box, (r, r, r) for a sphere. Bounds, reaches and swings read it for every shape.
  Vec3 half_size = Vec3::Constant(0.5);
  double radius = 0.0;       // m: the sphere's, capsule's or cylinder's; 0 for a box
  double half_length = 0.0;  // m: half a capsule's core segment or a cylinder's length, along y
  // A hull's corners, faces and their normals, body frame (shared by the bodies made from it).
  std::shared_ptr<const ConvexHull> hull = nullptr;
};

// A box of half edges `half_size` (m), a sphere of `radius` (m), or a capsule of `radius` whose
// end centres are `half_length` (m) either side of its centre along body y.
inline Shape box_shape(const Vec3& half_size) {
  return {.kind = ShapeKind::box, .half_size = half_size};
}
inline Shape sphere_shape(double radius) {
  return {.kind = ShapeKind::sphere, .half_size = Vec3::Constant(radius), .radius = radius};
}
inline Shape cylinder_shape(double radius, double half_length) {
  return {.kind = ShapeKind::cylinder,
          .half_size = Vec3(radius, half_length, radius),
          .radius = radius,
          .half_length = half_length};
}
inline Shape hull_shape(std::shared_ptr<const ConvexHull> hull) {
  Vec3 reach = Vec3::Zero();
  for (const Vec3& v : hull->vertices) reach = reach.cwiseMax(v.cwiseAbs());
  return {.kind = ShapeKind::hull, .half_size = reach, .hull = std::move(hull)};
}
inline Shape capsule_shape(double radius, double half_length) {
  return {.kind = ShapeKind::capsule,
          .half_size = Vec3(radius, half_length + radius, radius),
          .radius = radius,
          .half_length = half_length};
}

// How far the shape's surface stands out from its core (m): a sphere's radius around its centre, a
// capsule's around its segment; 0 for a box or a cylinder, which are all core.
inline double rounding(const Shape& shape) {
  return shape.kind == ShapeKind::sphere || shape.kind == ShapeKind::capsule ? shape.radius : 0.0;
}

// The point of a round shape's core nearest to `point` (body frame, m): the centre of a sphere, the
// nearest point of a capsule's segment.
inline Vec3 nearest_core_point(const Shape& shape, const Vec3& point) {
  if (shape.kind != ShapeKind::capsule) return Vec3::Zero();
  return Vec3(0.0, std::clamp(point.y(), -shape.half_length, shape.half_length), 0.0);
}

// How far the shape's core reaches from its centre (m): a box's or cylinder's half diagonal, a
// capsule's half length, nothing for a sphere. A turn of the body swings its surface by this times
// the angle.
inline double core_reach(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::box:
    case ShapeKind::cylinder:
    case ShapeKind::hull:
      return shape.half_size.norm();
    case ShapeKind::sphere:
      return 0.0;
    case ShapeKind::capsule:
      return shape.half_length;
  }
  return shape.half_size.norm();
}

// The radius of a sphere about the centre that holds the shape (m): its core's reach and its
// rounding (the smallest such sphere for a box, a ball or a capsule; for a cylinder or a hull, the
// one about the box they fit in).
inline double bounding_radius(const Shape& shape) {
  return core_reach(shape) + rounding(shape);
}

// A static, infinite plane: the half-space n·x >= offset is outside; bodies stay there.
struct Plane {
  Vec3 normal = Vec3::UnitY();  // unit, world frame, pointing out of the solid side
  double offset = 0.0;          // n·x of every point on the plane (m)
  Material material = {};
};

// Signed distance of a world point from a plane: positive outside (m).
inline double separation(const Plane& plane, const Vec3& world_point) {
  return plane.normal.dot(world_point) - plane.offset;
}

}  // namespace tumble::physics
