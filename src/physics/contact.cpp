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

CornerSeparations plane_separations(const Shape& shape, const Mat3& rotation, const Vec3& position,
                                    const Plane& plane) {
  if (shape.kind == ShapeKind::box) {
    return corner_separations(rotation, position, shape.half_size, plane);
  }
  CornerSeparations out;
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

Manifold plane_manifold(const Shape& shape, const CornerSeparations& separations,
                        const Mat3& rotation, const Vec3& normal, double margin) {
  if (shape.kind == ShapeKind::box) return box_plane_manifold(separations, shape.half_size, margin);
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
  if (shape.kind == ShapeKind::capsule) {
    return {.core = Vec3(0.0, feature == 0 ? -shape.half_length : shape.half_length, 0.0),
            .radius = shape.radius};
  }
  return {.core = Vec3::Zero(), .radius = shape.radius};
}

}  // namespace tumble::physics
