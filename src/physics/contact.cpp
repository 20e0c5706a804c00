#include "physics/contact.hpp"

#include <algorithm>

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

Manifold box_plane_manifold(const BodyState& state, const Vec3& half_size, const Plane& plane,
                            double margin) {
  // n·(x + R c) - offset = n·x - offset + (Rᵀ n)·c: one rotation for all eight corners.
  const Vec3 body_normal = state.orientation().conjugate() * plane.normal;
  const double centre = separation(plane, state.position());
  int features[8];
  double separations[8];
  int count = 0;
  for (int feature = 0; feature < 8; ++feature) {
    const double s = centre + body_normal.dot(corner(half_size, feature));
    if (!(s < margin)) continue;
    // Deepest first (insertion, so stable): equal depths, a face flat on the plane, stay in
    // corner order, and the manifold is the same on every machine.
    int at = count++;
    for (; at > 0 && s < separations[at - 1]; --at) {
      features[at] = features[at - 1];
      separations[at] = separations[at - 1];
    }
    features[at] = feature;
    separations[at] = s;
  }
  Manifold out;
  out.count = std::min(count, kMaxManifoldPoints);
  for (int i = 0; i < out.count; ++i) {
    ContactPoint& point = out.points[static_cast<std::size_t>(i)];
    point.feature = features[i];
    point.body_point = corner(half_size, features[i]);
    point.separation = separations[i];
  }
  return out;
}

}  // namespace tumble::physics
