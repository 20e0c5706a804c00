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

Closest closest_corner(const BodyState& state, const Vec3& half_size, const Plane& plane) {
  // The corner furthest against the normal has the sign opposite to the normal's body-frame
  // components: one rotation instead of eight corner positions.
  const Vec3 body_normal = state.orientation().conjugate() * plane.normal;
  int feature = 0;
  for (int axis = 0; axis < 3; ++axis) {
    if (body_normal[axis] < 0.0) feature |= 1 << axis;
  }
  const Vec3 point = body_point_to_world(state, corner(half_size, feature));
  return {.separation = separation(plane, point), .feature = feature};
}

Manifold box_plane_manifold(const BodyState& state, const Vec3& half_size, const Plane& plane,
                            double margin) {
  std::array<ContactPoint, 8> candidates;
  int count = 0;
  // n·(x + R c) - offset = n·x - offset + (Rᵀ n)·c: one rotation for all eight corners.
  const Vec3 body_normal = state.orientation().conjugate() * plane.normal;
  const double centre = separation(plane, state.position());
  for (int feature = 0; feature < 8; ++feature) {
    const Vec3 body_point = corner(half_size, feature);
    const double s = centre + body_normal.dot(body_point);
    if (s < margin)
      candidates[count++] = {.feature = feature, .body_point = body_point, .separation = s};
  }
  // Deepest first; equal depths (a face flat on the plane) stay in corner order, so the
  // manifold is the same on every machine. Insertion sort: stable, and for at most eight points
  // cheaper than std::stable_sort, which takes a buffer from the heap.
  for (int i = 1; i < count; ++i) {
    const ContactPoint moving = candidates[static_cast<std::size_t>(i)];
    int j = i;
    for (; j > 0 && moving.separation < candidates[static_cast<std::size_t>(j - 1)].separation;
         --j) {
      candidates[static_cast<std::size_t>(j)] = candidates[static_cast<std::size_t>(j - 1)];
    }
    candidates[static_cast<std::size_t>(j)] = moving;
  }
  Manifold out;
  out.count = std::min(count, kMaxManifoldPoints);
  std::copy(candidates.begin(), candidates.begin() + out.count, out.points.begin());
  return out;
}

}  // namespace tumble::physics
