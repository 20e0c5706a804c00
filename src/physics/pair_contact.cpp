#include "physics/pair_contact.hpp"

#include "physics/capsule_contact.hpp"
#include "physics/convex_manifold.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace tumble::physics {
PairManifold one_point(const ShapePose& a, const ShapePose& b, const Vec3& normal, const Vec3& at,
                       double gap, std::uint32_t feature) {
  PairManifold out;
  out.normal = normal;
  add_point(out, a, b, at, gap, feature);
  return out;
}

void add_point(PairManifold& m, const ShapePose& a, const ShapePose& b, const Vec3& at, double gap,
               std::uint32_t feature) {
  PairPoint& point = m.points[static_cast<std::size_t>(m.count++)];
  point.feature = feature;
  point.point_a = a.rotation.transpose() * (at - a.position);
  point.point_b = b.rotation.transpose() * (at - b.position);
  point.separation = gap;
}

PairManifold swapped(PairManifold m) {
  m.normal = -m.normal;
  for (int k = 0; k < m.count; ++k) {
    PairPoint& p = m.points[static_cast<std::size_t>(k)];
    std::swap(p.point_a, p.point_b);
    p.on_axis = static_cast<std::uint8_t>((p.on_axis & 1) << 1 | (p.on_axis & 2) >> 1);
  }
  return m;
}

PairManifold sphere_sphere_manifold(const ShapePose& a, double ra, const ShapePose& b, double rb,
                                    double margin) {
  const Vec3 d = b.position - a.position;
  const double distance = d.norm();
  const double gap = distance - ra - rb;
  if (!(gap < margin)) return {};
  const Vec3 normal = distance > 0.0 ? Vec3(d / distance) : Vec3(Vec3::UnitY());
  // The middle of the gap: A's surface point plus half the gap along the normal.
  const Vec3 at = a.position + (ra + 0.5 * gap) * normal;
  return one_point(a, b, normal, at, gap, 0);
}

PairManifold box_sphere_manifold(const BoxPose& box, const ShapePose& sphere, double radius,
                                 double margin) {
  const Vec3& h = box.half_size;
  const Vec3 local = box.rotation.transpose() * (sphere.position - box.position);
  const Vec3 closest = local.cwiseMax(-h).cwiseMin(h);
  std::uint32_t feature = 0;
  for (int axis = 2; axis >= 0; --axis) {
    const std::uint32_t region = local[axis] < -h[axis] ? 0 : local[axis] > h[axis] ? 2 : 1;
    feature = 3 * feature + region;
  }
  Vec3 normal_local;
  double gap = 0.0;
  Vec3 surface_local = closest;  // the box's surface point under the sphere
  const Vec3 outside = local - closest;
  if (outside.squaredNorm() > 0.0) {
    const double distance = outside.norm();
    normal_local = outside / distance;
    gap = distance - radius;
  } else {
    // The centre is inside: out of the face it is nearest (the lowest axis on a tie).
    int axis = 0;
    double least = h.x() - std::abs(local.x());
    for (int k = 1; k < 3; ++k) {
      const double depth = h[k] - std::abs(local[k]);
      if (depth < least) {
        least = depth;
        axis = k;
      }
    }
    const double side = local[axis] < 0.0 ? -1.0 : 1.0;
    normal_local = Vec3::Zero();
    normal_local[axis] = side;
    surface_local[axis] = side * h[axis];
    gap = -least - radius;
  }
  if (!(gap < margin)) return {};
  const Vec3 normal = box.rotation * normal_local;
  const Vec3 at = box.position + box.rotation * surface_local + 0.5 * gap * normal;
  return one_point({box.position, box.rotation, nullptr}, sphere, normal, at, gap, feature);
}

PairManifold cylinder_sphere_manifold(const ShapePose& cylinder, const ShapePose& sphere,
                                      double margin) {
  const double r = cylinder.shape->radius;
  const double half_length = cylinder.shape->half_length;
  const Vec3 local = cylinder.rotation.transpose() * (sphere.position - cylinder.position);
  const double across = std::hypot(local.x(), local.z());  // from the axis
  // The cylinder's closest point: the centre's height clamped to the ends, its distance from the
  // axis to the radius.
  Vec3 surface = local;
  surface.y() = std::clamp(local.y(), -half_length, half_length);
  if (across > r) {
    surface.x() *= r / across;
    surface.z() *= r / across;
  }
  const std::uint32_t along = local.y() < -half_length ? 0 : local.y() > half_length ? 2 : 1;
  const std::uint32_t feature = 2 * along + (across > r ? 1 : 0);
  Vec3 normal_local;
  double gap = 0.0;
  const Vec3 outside = local - surface;
  if (outside.squaredNorm() > 0.0) {
    const double distance = outside.norm();
    normal_local = outside / distance;
    gap = distance - sphere.shape->radius;
  } else {
    // The centre is inside: out through the side or the end it is nearest (the side on a tie).
    const double to_side = r - across;
    const double to_end = half_length - std::abs(local.y());
    if (to_end < to_side) {
      const double side = local.y() < 0.0 ? -1.0 : 1.0;
      normal_local = Vec3(0.0, side, 0.0);
      surface.y() = side * half_length;
      gap = -to_end - sphere.shape->radius;
    } else {
      normal_local =
          across > 0.0 ? Vec3(local.x() / across, 0.0, local.z() / across) : Vec3(Vec3::UnitX());
      surface.x() = r * normal_local.x();
      surface.z() = r * normal_local.z();
      gap = -to_side - sphere.shape->radius;
    }
  }
  if (!(gap < margin)) return {};
  const Vec3 normal = cylinder.rotation * normal_local;
  const Vec3 at = cylinder.position + cylinder.rotation * surface + 0.5 * gap * normal;
  return one_point(cylinder, sphere, normal, at, gap, feature);
}

PairManifold hull_sphere_manifold(const ShapePose& hull, const ShapePose& sphere, double margin) {
  const ConvexHull& h = *hull.shape->hull;
  const Vec3 c = hull.rotation.transpose() * (sphere.position - hull.position);
  // The face the centre stands furthest out of (or least deep inside).
  // How far the centre stands out of face f's plane (m; negative inside it): recomputed where
  // needed rather than kept, so that a step's contact allocates nothing.
  const auto out_of = [&](std::size_t f) {
    return h.normals[f].dot(c - h.vertices[h.faces[f][0]]);
  };
  std::size_t out_face = 0;
  double out_distance = -std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < h.faces.size(); ++f) {
    const double d = out_of(f);
    if (d > out_distance) {
      out_distance = d;
      out_face = f;
    }
  }
  Vec3 surface = c, normal_local = Vec3::UnitY();
  double gap = 0.0;
  std::uint32_t feature = static_cast<std::uint32_t>(out_face);
  if (!(out_distance > 0.0)) {
    // Inside: out through the face it is nearest.
    normal_local = h.normals[out_face];
    surface = c - out_distance * normal_local;
    gap = out_distance - sphere.shape->radius;
  } else {
    // Outside: the nearest point of the faces it stands out of, on a face or on its edges.
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < h.faces.size(); ++f) {
      const double d = out_of(f);
      if (!(d > 0.0)) continue;
      const std::vector<std::uint32_t>& face = h.faces[f];
      const Vec3 q = c - d * h.normals[f];
      bool inside = true;
      for (std::size_t k = 0; k < face.size() && inside; ++k) {
        const Vec3& a = h.vertices[face[k]];
        const Vec3& b = h.vertices[face[(k + 1) % face.size()]];
        inside = (b - a).cross(q - a).dot(h.normals[f]) >= 0.0;
      }
      if (inside) {
        if (d < nearest) {
          nearest = d;
          surface = q;
          feature = static_cast<std::uint32_t>(f);
        }
        continue;
      }
      for (std::size_t k = 0; k < face.size(); ++k) {
        const std::uint32_t i = face[k], j = face[(k + 1) % face.size()];
        const Vec3& a = h.vertices[i];
        const Vec3 ab = h.vertices[j] - a;
        const double t = std::clamp((c - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        const Vec3 p = a + t * ab;
        const double d = (c - p).norm();
        if (d < nearest) {
          nearest = d;
          surface = p;
          // An edge by its two corners, a corner by itself (past the faces' numbers).
          const std::uint32_t lo = std::min(i, j), hi = std::max(i, j);
          feature = t <= 0.0   ? 1'000'000 + i
                    : t >= 1.0 ? 1'000'000 + j
                               : 2'000'000 + 4096 * lo + hi;
        }
      }
    }
    normal_local = (c - surface) / nearest;
    gap = nearest - sphere.shape->radius;
  }
  if (!(gap < margin)) return {};
  const Vec3 normal = hull.rotation * normal_local;
  const Vec3 at = hull.position + hull.rotation * surface + 0.5 * gap * normal;
  return one_point(hull, sphere, normal, at, gap, feature);
}

double pair_separation(const ShapePose& a, const ShapePose& b, double margin) {
  if (a.shape->kind == ShapeKind::box && b.shape->kind == ShapeKind::box) {
    return box_box_axis({a.position, a.rotation, a.shape->half_size},
                        {b.position, b.rotation, b.shape->half_size})
        .separation;
  }
  const PairManifold m = pair_manifold(a, b, margin);
  double deepest = margin;
  for (int k = 0; k < m.count; ++k) {
    deepest = std::min(deepest, m.points[static_cast<std::size_t>(k)].separation);
  }
  return deepest;
}

PairManifold pair_manifold(const ShapePose& a, const ShapePose& b, double margin,
                           const Vec3& guess) {
  const Shape& sa = *a.shape;
  const Shape& sb = *b.shape;
  if (sa.kind == ShapeKind::box && sb.kind == ShapeKind::box) {
    return box_box_manifold({a.position, a.rotation, sa.half_size},
                            {b.position, b.rotation, sb.half_size}, margin);
  }
  if (sa.kind == ShapeKind::sphere && sb.kind == ShapeKind::sphere) {
    return sphere_sphere_manifold(a, sa.radius, b, sb.radius, margin);
  }
  const auto round = [](ShapeKind k) { return k == ShapeKind::sphere || k == ShapeKind::capsule; };
  if (round(sa.kind) && round(sb.kind)) return round_round_manifold(a, b, margin);
  if (sa.kind == ShapeKind::sphere ||
      (sa.kind == ShapeKind::capsule && sb.kind == ShapeKind::box)) {
    return swapped(pair_manifold(b, a, margin, -guess));
  }
  if (sb.kind == ShapeKind::sphere) {
    switch (sa.kind) {
      case ShapeKind::box:
        return box_sphere_manifold({a.position, a.rotation, sa.half_size}, b, sb.radius, margin);
      case ShapeKind::cylinder:
        return cylinder_sphere_manifold(a, b, margin);
      case ShapeKind::hull:
        return hull_sphere_manifold(a, b, margin);
      default:
        break;
    }
  }
  if (sa.kind == ShapeKind::box && sb.kind == ShapeKind::capsule) {
    return box_capsule_manifold({a.position, a.rotation, sa.half_size}, b, margin);
  }
  return convex_manifold(a, b, margin, guess);
}

}  // namespace tumble::physics
