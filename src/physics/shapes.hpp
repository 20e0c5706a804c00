// The shapes bodies touch: static planes (floor, walls, slopes), and the surface material that a
// contact between two shapes combines.
#pragma once

#include "physics/rigid_body.hpp"

namespace tumble::physics {

// Surface properties of one shape.
struct Material {
  double restitution = 0.0;  // e in [0, 1]: normal speed kept by a bounce
  double friction = 0.5;     // Coulomb coefficient μ >= 0
};

// What a pair of shapes uses: restitution = max(a, b), friction = sqrt(a b) (as Box2D mixes
// them), so a bouncy ball bounces on any floor and an ice surface is slippery under any shoe.
Material combine(const Material& a, const Material& b);

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
