// The convex hull of a point set, as a body's shape needs it: its corners, its faces as polygons
// (coplanar triangles merged) wound counter-clockwise seen from outside, and their outward
// normals. Computed by Qhull (Barber, Dobkin & Huhdanpaa, "The Quickhull Algorithm for Convex
// Hulls", ACM TOMS 22(4), 1996; Debian's libqhull-dev, its reentrant API), which merges facets
// that are coplanar within round-off, so a box's eight corners give six square faces.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "common/result.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::physics {

struct ConvexHull {
  std::vector<Vec3> vertices;                     // the hull's corners (m), by first appearance
  std::vector<std::vector<std::uint32_t>> faces;  // into vertices, counter-clockwise from outside
  std::vector<Vec3> normals;                      // per face: unit, outward

  // The faces cut into triangles (fans from each face's first corner), still wound outward.
  std::vector<std::array<std::uint32_t, 3>> triangles() const;
};

// The hull of `points` (m). An error when fewer than four of them span a volume (all on one
// plane, line or point): its message says so and how far the points reach off their plane.
Result<ConvexHull> convex_hull(std::span<const Vec3> points);

}  // namespace tumble::physics
