// A convex hull as a body's shape: the hull of a point set (or of a mesh's vertices), moved so that
// its centre of mass (uniform density) is the body's origin and turned so that its principal axes
// are the body's axes, with the body's constants. A hull of many corners is reduced to
// kMostHullCorners of them (the hull of those corners, picked farthest first), so that its contact
// stays cheap.
#pragma once

#include <memory>
#include <span>

#include "common/result.hpp"
#include "physics/convex_hull.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::physics {

inline constexpr std::size_t kMostHullCorners = 64;

struct HullBody {
  std::shared_ptr<const ConvexHull> hull;  // body frame: centred on its centre of mass, principal
  BodyConstants constants;
  Vec3 centre = Vec3::Zero();     // its centre of mass in the points' frame (m)
  Mat3 axes = Mat3::Identity();   // its body axes in the points' frame (columns)
  std::size_t given_corners = 0;  // the corners of the hull of all the points, before reducing

  // A point given in the points' frame (m) in the body frame.
  Vec3 body_point(const Vec3& given) const { return axes.transpose() * (given - centre); }
};

// The hull of `points` (m, any frame) as a body of `mass` (kg): an error when fewer than four of
// them span a volume (convex_hull's message).
Result<HullBody> hull_body(std::span<const Vec3> points, double mass);

// The separation of each corner of `hull` from a plane, the body at `rotation` and `position`.
// (m, negative inside), into `out` (sized to the corners).
void hull_separations(const ConvexHull& hull, const Mat3& rotation, const Vec3& position,
                      const Vec3& normal, double offset, std::vector<double>& out);

}  // namespace tumble::physics
