// The contact of two bodies of any shapes (narrow phase): the manifold of a pair, by the pair of
// shapes — two boxes by the separating-axis test (physics/box_box.hpp); a sphere with a sphere, a
// box, a cylinder or a hull in closed form; a capsule with a sphere, a capsule or a box by its
// segment (physics/capsule_contact.hpp); any other pair by GJK and EPA with a manifold builder
// (physics/convex_manifold.hpp). Pure geometry, as box_box.hpp.
#pragma once

#include <cmath>

#include "physics/box_box.hpp"
#include "physics/shapes.hpp"

namespace tumble::physics {

// Lines (a capsule's segments, a cylinder's sides) within this angle (rad, as its sine) of
// parallel lie side by side: they touch along a stretch, not at a point.
inline constexpr double kSideBySideSine = 0.1;

// A unit vector normal to `d` (not zero).
inline Vec3 any_normal(const Vec3& d) {
  const Vec3 other = std::abs(d.x()) < 0.9 * d.norm() ? Vec3::UnitX() : Vec3::UnitY();
  return d.cross(other).normalized();
}

// A shape placed in the world.
struct ShapePose {
  Vec3 position = Vec3::Zero();      // centre of mass, world frame (m)
  Mat3 rotation = Mat3::Identity();  // body to world
  const Shape* shape = nullptr;
};

// The contact of two shapes whose closest features are within `margin` (m) of touching: up to
// kMaxManifoldPoints points with separation below `margin`, the normal from A towards B; count 0
// otherwise. A sphere touches at one point, the middle of the gap (or overlap) between the two
// surfaces along the normal.
// `guess`: the normal the pair had lately (from A towards B), or zero; only pairs without a closed
// form use it (convex_manifold.hpp), to start their search from it.
PairManifold pair_manifold(const ShapePose& a, const ShapePose& b, double margin,
                           const Vec3& guess = Vec3::Zero());

// How far apart two shapes are (m; negative: how deep they overlap), if within `margin` of
// touching; `margin` or more otherwise: two boxes by the separating-axis test (the axis's
// separation), any other pair by its manifold's deepest point.
double pair_separation(const ShapePose& a, const ShapePose& b, double margin);

// The manifold of one point at world `at` (m), `gap` apart along `normal` (from A towards B).
PairManifold one_point(const ShapePose& a, const ShapePose& b, const Vec3& normal, const Vec3& at,
                       double gap, std::uint32_t feature);
// One point more of the same kind (m.count < kMaxManifoldPoints).
void add_point(PairManifold& m, const ShapePose& a, const ShapePose& b, const Vec3& at, double gap,
               std::uint32_t feature);
// The manifold of B against A made from A against B's: the normal turned round, the anchors
// swapped.
PairManifold swapped(PairManifold m);

// Two spheres of radii `ra`, `rb` (m) centred at `a`, `b` (rotations body to world): the normal
// along the line of centres (+y when the centres coincide), feature 0.
PairManifold sphere_sphere_manifold(const ShapePose& a, double ra, const ShapePose& b, double rb,
                                    double margin);

// A box and a sphere of `radius` (m) centred at `sphere.position`, the normal from the box towards
// the sphere: from the box's closest point to the centre, or, with the centre inside the box, out
// of the face it is nearest. The feature names the box's region that the centre projects into
// (per axis: below, within, above its face pair; 27 in all), so that a ball resting on a face keeps
// its id while it rolls across it.
PairManifold box_sphere_manifold(const BoxPose& box, const ShapePose& sphere, double radius,
                                 double margin);

// A cylinder and a sphere, the normal from the cylinder towards the sphere: from the cylinder's
// closest point to the centre (on its side, its rim or an end), or, with the centre inside, out
// through the side or the end it is nearest.
PairManifold cylinder_sphere_manifold(const ShapePose& cylinder, const ShapePose& sphere,
                                      double margin);

// A hull and a sphere, the normal from the hull towards the sphere: from the nearest point of the
// hull's faces (on a face, an edge or a corner; the feature names which) to the centre, or, with
// the centre inside, out of the face it is nearest.
PairManifold hull_sphere_manifold(const ShapePose& hull, const ShapePose& sphere, double margin);

}  // namespace tumble::physics
