#include "physics/hull_shape.hpp"

#include <algorithm>
#include <limits>

#include "physics/mass_properties.hpp"

namespace tumble::physics {
namespace {

// At most `count` of `corners`, picked farthest first: the one farthest from their mean, then
// each time the one farthest from those picked (in the order given, on a tie).
std::vector<Vec3> farthest_first(const std::vector<Vec3>& corners, std::size_t count) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& c : corners) mean += c;
  mean /= static_cast<double>(corners.size());
  std::vector<double> nearest(corners.size(), std::numeric_limits<double>::infinity());
  std::vector<Vec3> out;
  std::size_t next = 0;
  double best = -1.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const double d = (corners[i] - mean).squaredNorm();
    if (d > best) {
      best = d;
      next = i;
    }
  }
  while (out.size() < count) {
    const Vec3 picked = corners[next];
    out.push_back(picked);
    best = -1.0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      nearest[i] = std::min(nearest[i], (corners[i] - picked).squaredNorm());
      if (nearest[i] > best) {
        best = nearest[i];
        next = i;
      }
    }
    if (!(best > 0.0)) break;  // every corner picked
  }
  return out;
}

}  // namespace

Result<HullBody> hull_body(std::span<const Vec3> points, double mass) {
  Result<ConvexHull> made = convex_hull(points);
  if (!made) return Error{made.error()};
  ConvexHull hull = std::move(made).value();
  HullBody out;
  out.given_corners = hull.vertices.size();
  if (hull.vertices.size() > kMostHullCorners) {
    const std::vector<Vec3> kept = farthest_first(hull.vertices, kMostHullCorners);
    Result<ConvexHull> reduced = convex_hull(kept);
    if (!reduced) return Error{reduced.error()};
    hull = std::move(reduced).value();
  }
  const std::vector<std::array<std::uint32_t, 3>> triangles = hull.triangles();
  const MassProperties unit = polyhedron_mass_properties(hull.vertices, triangles, 1.0);
  const double density = mass / unit.mass;  // unit.mass is the volume
  const PrincipalAxes axes = principal_axes(density * unit.inertia);
  out.centre = unit.centre;
  out.axes = axes.rotation;
  out.constants = constants_from_moments(mass, axes.moments);
  const Mat3 to_body = axes.rotation.transpose();
  for (Vec3& v : hull.vertices) v = to_body * (v - unit.centre);
  for (Vec3& n : hull.normals) n = to_body * n;
  out.hull = std::make_shared<const ConvexHull>(std::move(hull));
  return out;
}

void hull_separations(const ConvexHull& hull, const Mat3& rotation, const Vec3& position,
                      const Vec3& normal, double offset, std::vector<double>& out) {
  // n·(x + R v) − offset = (n·x − offset) + (Rᵀ n)·v: one rotation of the normal for every corner.
  const Vec3 reach = rotation.transpose() * normal;
  const double centre = normal.dot(position) - offset;
  out.resize(hull.vertices.size());
  for (std::size_t i = 0; i < hull.vertices.size(); ++i)
    out[i] = centre + reach.dot(hull.vertices[i]);
}

}  // namespace tumble::physics
