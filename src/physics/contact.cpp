#include "physics/contact.hpp"

#include <algorithm>
#include <limits>

namespace tumble::physics {

const char* contact_method_name(ContactMethod method) {
  switch (method) {
    case ContactMethod::impulse:
      return "impulse";
    case ContactMethod::penalty:
      return "penalty";
  }
  return "unknown";
}

double closest_corner_separation(const BodyState& state, const Vec3& half_size,
                                 const Plane& plane) {
  // The corner furthest against the normal has the sign opposite to the normal's body-frame
  // components: one rotation instead of eight corner positions.
  const Vec3 body_normal = state.orientation().conjugate() * plane.normal;
  int feature = 0;
  for (int axis = 0; axis < 3; ++axis) {
    if (body_normal[axis] < 0.0) feature |= 1 << axis;
  }
  const Vec3 point = body_point_to_world(state, corner(half_size, feature));
  return separation(plane, point);
}

CornerSeparations corner_separations(const Mat3& rotation, const Vec3& position,
                                     const Vec3& half_size, const Plane& plane) {
  // n·(x + R c) - offset = n·x - offset + (Rᵀ n)·c: one rotation of the normal for all eight,
  // and each corner's term is a sum of ± (Rᵀ n)_i h_i.
  const Vec3 reach = (rotation.transpose() * plane.normal).cwiseProduct(half_size);
  const double centre = separation(plane, position);
  CornerSeparations out;
  for (int feature = 0; feature < 8; ++feature) {
    out[static_cast<std::size_t>(feature)] = centre + (((feature & 1) ? reach.x() : -reach.x()) +
                                                       ((feature & 2) ? reach.y() : -reach.y()) +
                                                       ((feature & 4) ? reach.z() : -reach.z()));
  }
  return out;
}

Manifold deepest_features(const CornerSeparations& separations, double margin) {
  int features[8];
  double depths[8];
  int count = 0;
  for (int feature = 0; feature < 8; ++feature) {
    const double s = separations[static_cast<std::size_t>(feature)];
    if (!(s < margin)) continue;
    // Deepest first (insertion, so stable): equal depths, a face flat on the plane, stay in
    // corner order, and the manifold is the same on every machine.
    int at = count++;
    for (; at > 0 && s < depths[at - 1]; --at) {
      features[at] = features[at - 1];
      depths[at] = depths[at - 1];
    }
    features[at] = feature;
    depths[at] = s;
  }
  Manifold out;
  out.count = std::min(count, kMaxManifoldPoints);
  for (int i = 0; i < out.count; ++i) {
    ContactPoint& point = out.points[static_cast<std::size_t>(i)];
    point.feature = features[i];
    point.separation = depths[i];
  }
  return out;
}

Manifold box_plane_manifold(const CornerSeparations& separations, const Vec3& half_size,
                            double margin) {
  Manifold out = deepest_features(separations, margin);
  for (int i = 0; i < out.count; ++i) {
    ContactPoint& point = out.points[static_cast<std::size_t>(i)];
    point.body_point = corner(half_size, point.feature);
  }
  return out;
}

RimFrame rim_frame(const Mat3& rotation, const Vec3& normal) {
  const Vec3 down = -(rotation.transpose() * normal);
  Vec3 across(down.x(), 0.0, down.z());
  const double length = across.norm();
  // Standing on an end (within 1e-6 rad): the points are fixed in the body instead.
  across = length > 1e-6 ? Vec3(across / length) : Vec3(Vec3::UnitX());
  return {.down = across, .side = Vec3::UnitY().cross(across)};
}

Vec3 rim_point(const Shape& cylinder, const RimFrame& frame, int feature) {
  const double end = feature < 4 ? -cylinder.half_length : cylinder.half_length;
  const double r = cylinder.radius;
  Vec3 out;
  switch (feature % 4) {
    case 0:
      out = r * frame.down;
      break;
    case 1:
      out = r * frame.side;
      break;
    case 2:
      out = -r * frame.down;
      break;
    default:
      out = -r * frame.side;
      break;
  }
  out.y() = end;
  return out;
}

HullRanks lowest_hull_corners(const ConvexHull& hull, const Mat3& rotation, const Vec3& normal) {
  const Vec3 reach = rotation.transpose() * normal;
  HullRanks out;
  out.corner.fill(-1);
  out.height.fill(std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < hull.vertices.size(); ++i) {
    const double h = reach.dot(hull.vertices[i]);
    // Insertion into the eight lowest, lowest first (a tie keeps the lower index first).
    if (!(h < out.height[7])) continue;
    int at = 7;
    for (; at > 0 && h < out.height[static_cast<std::size_t>(at - 1)]; --at) {
      out.height[static_cast<std::size_t>(at)] = out.height[static_cast<std::size_t>(at - 1)];
      out.corner[static_cast<std::size_t>(at)] = out.corner[static_cast<std::size_t>(at - 1)];
    }
    out.height[static_cast<std::size_t>(at)] = h;
    out.corner[static_cast<std::size_t>(at)] = static_cast<int>(i);
  }
  return out;
}

CornerSeparations plane_separations(const Shape& shape, const Mat3& rotation, const Vec3& position,
                                    const Plane& plane) {
  if (shape.kind == ShapeKind::box) {
    return corner_separations(rotation, position, shape.half_size, plane);
  }
  CornerSeparations out;
  if (shape.kind == ShapeKind::hull) {
    const HullRanks ranks = lowest_hull_corners(*shape.hull, rotation, plane.normal);
    const double centre = separation(plane, position);
    for (std::size_t k = 0; k < 8; ++k) out[k] = centre + ranks.height[k];
    return out;
  }
  if (shape.kind == ShapeKind::cylinder) {
    const RimFrame frame = rim_frame(rotation, plane.normal);
    const Vec3 reach = rotation.transpose() * plane.normal;
    const double centre = separation(plane, position);
    for (int feature = 0; feature < 8; ++feature) {
      out[static_cast<std::size_t>(feature)] = centre + reach.dot(rim_point(shape, frame, feature));
    }
    return out;
  }
  out.fill(std::numeric_limits<double>::infinity());
  if (shape.kind == ShapeKind::capsule) {
    const Vec3 end = shape.half_length * rotation.col(1);
    out[0] = separation(plane, position - end) - shape.radius;
    out[1] = separation(plane, position + end) - shape.radius;
    return out;
  }
  out[0] = separation(plane, position) - shape.radius;
  return out;
}

Manifold hull_plane_manifold(const ConvexHull& hull, const CornerSeparations& separations,
                             const Mat3& rotation, const Vec3& normal, double margin) {
  const HullRanks ranks = lowest_hull_corners(hull, rotation, normal);
  int count = 0;
  while (count < 8 && separations[static_cast<std::size_t>(count)] < margin) ++count;
  // More than four within the margin (a face of five corners or more flat on the plane): the
  // deepest, then each time the one that widens the patch most (farthest from the one picked,
  // then farthest from their line, then on the far side of the three), so that the points hold
  // the body as its face does.
  std::array<int, 4> picked{};
  int kept = 0;
  const auto corner = [&](int k) {
    return hull.vertices[static_cast<std::size_t>(ranks.corner[static_cast<std::size_t>(k)])];
  };
  if (count <= kMaxManifoldPoints) {
    for (int k = 0; k < count; ++k) picked[static_cast<std::size_t>(kept++)] = k;
  } else {
    picked[0] = 0;
    kept = 1;
    const Vec3 n = rotation.transpose() * normal;  // body frame
    const auto best = [&](auto score) {
      int at = -1;
      double most = 0.0;
      for (int k = 1; k < count; ++k) {
        if (std::find(picked.begin(), picked.begin() + kept, k) != picked.begin() + kept) continue;
        const double value = score(corner(k));
        if (value > most) {
          most = value;
          at = k;
        }
      }
      if (at >= 0) picked[static_cast<std::size_t>(kept++)] = at;
    };
    const Vec3 a = corner(0);
    best([&](const Vec3& p) { return (p - a).squaredNorm(); });
    if (kept == 2) {
      const Vec3 b = corner(picked[1]);
      best([&](const Vec3& p) { return std::abs(n.dot((b - a).cross(p - a))); });
    }
    if (kept == 3) {
      const Vec3 b = corner(picked[1]), c = corner(picked[2]);
      const double side = n.dot((b - a).cross(c - a));
      // Beyond the edge of the triangle it faces most: the largest area outside it.
      best([&](const Vec3& p) {
        return std::max({-side * n.dot((b - a).cross(p - a)), -side * n.dot((c - b).cross(p - b)),
                         -side * n.dot((a - c).cross(p - c))});
      });
    }
  }
  Manifold out;
  out.count = kept;
  for (int i = 0; i < kept; ++i) {
    const int k = picked[static_cast<std::size_t>(i)];
    ContactPoint& point = out.points[static_cast<std::size_t>(i)];
    point.feature = ranks.corner[static_cast<std::size_t>(k)];
    point.body_point = corner(k);
    point.separation = separations[static_cast<std::size_t>(k)];
  }
  return out;
}

Manifold plane_manifold(const Shape& shape, const CornerSeparations& separations,
                        const Mat3& rotation, const Vec3& normal, double margin) {
  if (shape.kind == ShapeKind::box) return box_plane_manifold(separations, shape.half_size, margin);
  if (shape.kind == ShapeKind::hull)
    return hull_plane_manifold(*shape.hull, separations, rotation, normal, margin);
  if (shape.kind == ShapeKind::cylinder) {
    Manifold out = deepest_features(separations, margin);
    const RimFrame frame = rim_frame(rotation, normal);
    for (int i = 0; i < out.count; ++i) {
      ContactPoint& point = out.points[static_cast<std::size_t>(i)];
      point.body_point = rim_point(shape, frame, point.feature);
    }
    return out;
  }
  Manifold out;
  const int ends = shape.kind == ShapeKind::capsule ? 2 : 1;
  for (int feature = 0; feature < ends; ++feature) {
    const double s = separations[static_cast<std::size_t>(feature)];
    if (!(s < margin)) continue;
    ContactPoint& point = out.points[static_cast<std::size_t>(out.count++)];
    point.feature = feature;
    point.body_point = plane_point(shape, feature, rotation, normal).core;
    point.separation = s;
  }
  return out;
}

double closest_separation(const BodyState& state, const Shape& shape, const Plane& plane) {
  if (shape.kind == ShapeKind::box) return closest_corner_separation(state, shape.half_size, plane);
  if (shape.kind != ShapeKind::sphere) {
    const CornerSeparations points =
        plane_separations(shape, state.rotation(), state.position(), plane);
    return *std::min_element(points.begin(), points.end());
  }
  return separation(plane, state.position()) - shape.radius;
}

RoundedPoint plane_point(const Shape& shape, int feature, const Mat3& rotation,
                         const Vec3& normal) {
  if (shape.kind == ShapeKind::box) return {.core = corner(shape.half_size, feature)};
  if (shape.kind == ShapeKind::cylinder) {
    return {.core = rim_point(shape, rim_frame(rotation, normal), feature)};
  }
  if (shape.kind == ShapeKind::hull) {
    const int corner = lowest_hull_corners(*shape.hull, rotation, normal)
                           .corner[static_cast<std::size_t>(feature)];
    return {.core = shape.hull->vertices[static_cast<std::size_t>(std::max(corner, 0))]};
  }
  if (shape.kind == ShapeKind::capsule) {
    return {.core = Vec3(0.0, feature == 0 ? -shape.half_length : shape.half_length, 0.0),
            .radius = shape.radius};
  }
  return {.core = Vec3::Zero(), .radius = shape.radius};
}

}  // namespace tumble::physics
