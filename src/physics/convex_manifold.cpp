#include "physics/convex_manifold.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "physics/gjk.hpp"
#include "physics/hull_shape.hpp"

namespace tumble::physics {
namespace {

// A facet's corners at most: a hull's face may have all of a reduced hull's corners.
constexpr int kMostCorners = static_cast<int>(kMostHullCorners);
// A clipped polygon has at most the corners of both polygons.
constexpr int kMostClipped = 2 * kMostCorners + 4;

// Line ids in a point's feature: an incident polygon's edge k is k (0–63), the reference face's
// side j is 64 + j, an incident segment's line is 130 and its ends 128 and 129.
constexpr std::uint32_t kSide = 64;
constexpr std::uint32_t kSegmentEnd = 128;
constexpr std::uint32_t kSegmentLine = 130;

// A face (three corners or more, counter-clockwise seen from outside) or a line (two corners) of a
// shape's core, world frame.
struct Facet {
  Vec3 normal = Vec3::Zero();  // unit, out of the shape
  std::array<Vec3, kMostCorners> corner;
  int count = 0;  // 0: none
  std::uint32_t index = 0;
};

// A point of a clipped polygon and the two lines it lies on.
struct ClipPoint {
  Vec3 p;
  std::uint32_t line0, line1;
};

// The face of a box's, a hull's or a cylinder's core whose outward normal lies nearest `direction`
// (unit, world); none for a capsule.
Facet face_along(const ShapePose& pose, const Vec3& direction) {
  const Shape& shape = *pose.shape;
  const Vec3 d = pose.rotation.transpose() * direction;
  Facet out;
  const auto place = [&](const Vec3& local) { return pose.position + pose.rotation * local; };
  switch (shape.kind) {
    case ShapeKind::box: {
      int k = 0;
      for (int i = 1; i < 3; ++i) {
        if (std::abs(d[i]) > std::abs(d[k])) k = i;
      }
      const double s = d[k] >= 0.0 ? 1.0 : -1.0;
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const Vec3& h = shape.half_size;
      // Counter-clockwise about +axis k in the (i, j) plane, reversed on the − side.
      const std::array<std::array<double, 2>, 4> square{{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}};
      for (int c = 0; c < 4; ++c) {
        const auto& q = square[static_cast<std::size_t>(s > 0.0 ? c : 3 - c)];
        Vec3 local;
        local[k] = s * h[k];
        local[i] = q[0] * h[i];
        local[j] = q[1] * h[j];
        out.corner[static_cast<std::size_t>(c)] = place(local);
      }
      out.count = 4;
      out.normal = s * pose.rotation.col(k);
      out.index = static_cast<std::uint32_t>(2 * k + (s > 0.0 ? 1 : 0));
      return out;
    }
    case ShapeKind::hull: {
      const ConvexHull& hull = *shape.hull;
      std::size_t best = 0;
      for (std::size_t f = 1; f < hull.normals.size(); ++f) {
        if (hull.normals[f].dot(d) > hull.normals[best].dot(d)) best = f;
      }
      const std::vector<std::uint32_t>& face = hull.faces[best];
      out.count = std::min(static_cast<int>(face.size()), kMostCorners);
      for (int c = 0; c < out.count; ++c) {
        out.corner[static_cast<std::size_t>(c)] =
            place(hull.vertices[face[static_cast<std::size_t>(c)]]);
      }
      out.normal = pose.rotation * hull.normals[best];
      out.index = static_cast<std::uint32_t>(best);
      return out;
    }
    case ShapeKind::cylinder: {
      // The end, as its inscribed octagon, counter-clockwise seen from outside.
      const bool top = d.y() >= 0.0;
      for (int c = 0; c < 8; ++c) {
        const double angle = (top ? -1.0 : 1.0) * c * std::numbers::pi / 4.0;
        out.corner[static_cast<std::size_t>(c)] =
            place(Vec3(shape.radius * std::cos(angle), top ? shape.half_length : -shape.half_length,
                       shape.radius * std::sin(angle)));
      }
      out.count = 8;
      out.normal = (top ? 1.0 : -1.0) * pose.rotation.col(1);
      out.index = top ? 1 : 0;
      return out;
    }
    case ShapeKind::sphere:
    case ShapeKind::capsule:
      break;
  }
  return out;
}

// The line of a cylinder's side or of a capsule's segment facing `direction` (unit, world), with
// the outward normal across the axis; none for another shape or a direction along the axis.
Facet line_along(const ShapePose& pose, const Vec3& direction) {
  const Shape& shape = *pose.shape;
  Facet out;
  if (shape.kind != ShapeKind::cylinder && shape.kind != ShapeKind::capsule) return out;
  const Vec3 d = pose.rotation.transpose() * direction;
  const Vec3 across(d.x(), 0.0, d.z());
  if (!(across.norm() > 1e-9)) return out;
  const Vec3 u = across.normalized();
  const double r = shape.kind == ShapeKind::cylinder ? shape.radius : 0.0;
  out.corner[0] = pose.position + pose.rotation * Vec3(r * u.x(), -shape.half_length, r * u.z());
  out.corner[1] = pose.position + pose.rotation * Vec3(r * u.x(), shape.half_length, r * u.z());
  out.count = 2;
  out.normal = pose.rotation * u;
  out.index = 2;
  return out;
}

// How far apart the shapes are along a facet's outward normal (the separating-axis test's value
// for that axis; m): `own` holds the facet, `other` is the other shape, `rounding` both roundings.
double axis_separation(const Facet& facet, const ShapePose& other, double rounding) {
  const Vec3& m = facet.normal;
  return m.dot(core_support(other, -m)) - m.dot(facet.corner[0]) - rounding;
}

// Clips a closed polygon (`count` ≥ 3) or a segment (2) to the side planes of the reference face.
int clip(std::array<ClipPoint, kMostClipped>& points, int count, const Facet& reference) {
  const bool closed = count > 2;
  std::array<ClipPoint, kMostClipped> next;
  for (int j = 0; j < reference.count && count > 0; ++j) {
    const Vec3& c0 = reference.corner[static_cast<std::size_t>(j)];
    const Vec3& c1 = reference.corner[static_cast<std::size_t>((j + 1) % reference.count)];
    const Vec3 out = (c1 - c0).cross(reference.normal);
    const std::uint32_t side = kSide + static_cast<std::uint32_t>(j);
    const auto height = [&](const ClipPoint& q) { return out.dot(q.p - c0); };
    const auto crossing = [&](const ClipPoint& p, const ClipPoint& q) {
      const double hp = height(p), hq = height(q);
      const std::uint32_t line =
          p.line0 == q.line0 || p.line0 == q.line1 ? p.line0 : p.line1;  // the edge p–q lies on
      return ClipPoint{p.p + (hp / (hp - hq)) * (q.p - p.p), std::min(line, side),
                       std::max(line, side)};
    };
    int n = 0;
    if (!closed) {
      const ClipPoint &p = points[0], &q = points[1];
      const bool p_in = height(p) <= 0.0, q_in = height(q) <= 0.0;
      if (!p_in && !q_in) return 0;
      next[0] = p_in ? p : crossing(p, q);
      next[1] = q_in ? q : crossing(p, q);
      n = 2;
    } else {
      for (int k = 0; k < count; ++k) {
        const ClipPoint& p = points[static_cast<std::size_t>((k + count - 1) % count)];
        const ClipPoint& q = points[static_cast<std::size_t>(k)];
        const bool p_in = height(p) <= 0.0, q_in = height(q) <= 0.0;
        if (p_in != q_in) next[static_cast<std::size_t>(n++)] = crossing(p, q);
        if (q_in) next[static_cast<std::size_t>(n++)] = q;
      }
    }
    points = next;
    count = n;
  }
  return count;
}

// A point found: where, how far apart, and its feature.
struct Found {
  Vec3 at;
  double separation;
  std::uint32_t feature;
  std::uint8_t on_axis;  // bit 0: on the reference's axis, bit 1: on the incident's (PairPoint)
};

struct FoundPoints {
  std::array<Found, kMostClipped> list;
  int count = 0;
};

// The manifold's candidate from a point `p` of the incident core, against the reference facet:
// its separation along the reference normal `m` and the middle of the gap.
void add_found(FoundPoints& found, const Vec3& p, const Facet& reference, double reference_rounding,
               double incident_rounding, double margin, std::uint32_t feature,
               std::uint8_t on_axis) {
  const Vec3& m = reference.normal;
  const double d = m.dot(p - reference.corner[0]);
  const double separation = d - reference_rounding - incident_rounding;
  if (!(separation < margin)) return;
  const Vec3 on_reference = p - (d - reference_rounding) * m;
  const Vec3 on_incident = p - incident_rounding * m;
  const Vec3 at = 0.5 * (on_reference + on_incident);
  for (int k = 0; k < found.count; ++k) {
    if ((found.list[static_cast<std::size_t>(k)].at - at).squaredNorm() < 1e-18) return;
  }
  found.list[static_cast<std::size_t>(found.count++)] = {at, separation, feature, on_axis};
}

std::uint32_t feature_id(bool reference_b, std::uint32_t reference, std::uint32_t incident,
                         std::uint32_t line0, std::uint32_t line1) {
  return 1u << 31 | (reference_b ? 1u : 0u) | (reference & 127u) << 1 | (incident & 127u) << 8 |
         (std::min(line0, line1) & 255u) << 15 | (std::max(line0, line1) & 255u) << 23;
}

// The incident shape's points clipped to a reference face.
void clip_incident(FoundPoints& found, const Facet& reference, bool reference_b,
                   const ShapePose& inc, double reference_rounding, double margin) {
  const Shape& shape = *inc.shape;
  const double incident_rounding = rounding(shape);
  std::array<ClipPoint, kMostClipped> points;
  const auto keep = [&](int count, std::uint32_t incident, std::uint8_t on_axis) {
    count = clip(points, count, reference);
    for (int k = 0; k < count; ++k) {
      const ClipPoint& q = points[static_cast<std::size_t>(k)];
      add_found(found, q.p, reference, reference_rounding, incident_rounding, margin,
                feature_id(reference_b, reference.index, incident, q.line0, q.line1), on_axis);
    }
  };
  const auto polygon = [&](const Facet& face, std::uint32_t incident) {
    for (int k = 0; k < face.count; ++k) {
      points[static_cast<std::size_t>(k)] = {
          face.corner[static_cast<std::size_t>(k)],
          static_cast<std::uint32_t>((k + face.count - 1) % face.count),
          static_cast<std::uint32_t>(k)};
    }
    keep(face.count, incident, 0);
  };
  const auto segment = [&](const Vec3& p0, const Vec3& p1, std::uint32_t incident,
                           std::uint8_t on_axis) {
    points[0] = {p0, kSegmentEnd, kSegmentLine};
    points[1] = {p1, kSegmentEnd + 1, kSegmentLine};
    keep(2, incident, on_axis);
  };
  switch (shape.kind) {
    case ShapeKind::box:
    case ShapeKind::hull: {
      const Facet face = face_along(inc, -reference.normal);
      polygon(face, face.index);
      return;
    }
    case ShapeKind::capsule: {
      const Vec3 end = shape.half_length * inc.rotation.col(1);
      segment(inc.position - end, inc.position + end, 0, 0);
      return;
    }
    case ShapeKind::cylinder: {
      // The four rim points of the end nearer the face (physics/contact.hpp's RimFrame), and the
      // line along the side between the two ends' lowest points. The two share the lowest point:
      // the line's is kept (anchored on the axis, for rolling) when the cylinder lies within
      // kSideBySideSine of flat, the rim's (fixed in the body, for tipping) otherwise.
      const RimFrame frame = rim_frame(inc.rotation, reference.normal);
      const double along = (inc.rotation.transpose() * reference.normal).y();
      const bool low_minus = along >= 0.0;
      const int first = low_minus ? 0 : 4;
      Facet square;
      for (int k = 0; k < 4; ++k) {
        square.corner[static_cast<std::size_t>(k)] =
            inc.position + inc.rotation * rim_point(shape, frame, first + k);
      }
      square.count = 4;
      const bool lying = std::abs(along) <= kSideBySideSine;
      if (!lying) polygon(square, low_minus ? 4 : 5);
      segment(inc.position + inc.rotation * rim_point(shape, frame, 0),
              inc.position + inc.rotation * rim_point(shape, frame, 4), 6, lying ? 2 : 0);
      if (lying) polygon(square, low_minus ? 4 : 5);
      return;
    }
    case ShapeKind::sphere:
      return;
  }
}

// Two lines side by side: the ends of the stretch of the incident line beside the reference line.
void lines_side_by_side(FoundPoints& found, const Facet& reference, bool reference_b,
                        const Facet& incident, double reference_rounding, double incident_rounding,
                        double margin, std::uint8_t on_axis) {
  const Vec3 dr = reference.corner[1] - reference.corner[0];
  const Vec3 di = incident.corner[1] - incident.corner[0];
  if (!(dr.cross(di).norm() <= kSideBySideSine * dr.norm() * di.norm())) return;
  const double length2 = dr.squaredNorm();
  if (!(length2 > 0.0 && di.squaredNorm() > 0.0)) return;  // a capsule of no length: a point
  const double u0 = (incident.corner[0] - reference.corner[0]).dot(dr) / length2;
  const double u1 = (incident.corner[1] - reference.corner[0]).dot(dr) / length2;
  if (!(std::abs(u1 - u0) > 0.0)) return;
  const double lo = std::max(0.0, std::min(u0, u1));
  const double hi = std::min(1.0, std::max(u0, u1));
  if (!(hi >= lo)) return;
  for (const double u : {lo, hi}) {
    const double t = (u - u0) / (u1 - u0);  // along the incident line
    const std::uint32_t end = t <= 0.0 ? 0 : t >= 1.0 ? 1 : 2;
    add_found(found, incident.corner[0] + t * di, reference, reference_rounding, incident_rounding,
              margin,
              feature_id(reference_b, reference.index, incident.index, end, u == lo ? 0 : 1),
              on_axis);
  }
}

// At most four of the points: the deepest, the farthest from it, the one that makes the widest
// triangle with them, and the one that widens that triangle most (about the normal).
void reduce_to_four(FoundPoints& found, const Vec3& normal) {
  if (found.count <= kMaxManifoldPoints) return;
  std::array<int, 4> pick{0, -1, -1, -1};
  const auto& list = found.list;
  const auto p = [&](int k) -> const Vec3& { return list[static_cast<std::size_t>(k)].at; };
  for (int k = 1; k < found.count; ++k) {
    if (list[static_cast<std::size_t>(k)].separation <
        list[static_cast<std::size_t>(pick[0])].separation) {
      pick[0] = k;
    }
  }
  const auto best = [&](auto&& score) {
    int chosen = -1;
    double most = -1.0;
    for (int k = 0; k < found.count; ++k) {
      if (std::find(pick.begin(), pick.end(), k) != pick.end()) continue;
      const double s = score(k);
      if (s > most) {
        most = s;
        chosen = k;
      }
    }
    return chosen;
  };
  pick[1] = best([&](int k) { return (p(k) - p(pick[0])).squaredNorm(); });
  pick[2] = best([&](int k) {
    return std::abs((p(pick[1]) - p(pick[0])).cross(p(k) - p(pick[0])).dot(normal));
  });
  // Wind the triangle counter-clockwise about the normal, then widen it across an edge.
  if ((p(pick[1]) - p(pick[0])).cross(p(pick[2]) - p(pick[0])).dot(normal) < 0.0) {
    std::swap(pick[1], pick[2]);
  }
  pick[3] = best([&](int k) {
    double most = 0.0;
    for (int e = 0; e < 3; ++e) {
      const Vec3& e0 = p(pick[static_cast<std::size_t>(e)]);
      const Vec3& e1 = p(pick[static_cast<std::size_t>((e + 1) % 3)]);
      most = std::max(most, -(e1 - e0).cross(p(k) - e0).dot(normal));
    }
    return most;
  });
  std::sort(pick.begin(), pick.end());
  FoundPoints out;
  for (const int k : pick) {
    if (k >= 0) out.list[static_cast<std::size_t>(out.count++)] = list[static_cast<std::size_t>(k)];
  }
  found = out;
}

}  // namespace

PairManifold convex_manifold(const ShapePose& a, const ShapePose& b, double margin,
                             const Vec3& guess) {
  const double ra = rounding(*a.shape), rb = rounding(*b.shape);
  if (!((b.position - a.position).norm() - bounding_radius(*a.shape) - bounding_radius(*b.shape) <
        margin)) {
    return {};
  }
  const CoreDistance core = core_distance(a, b, guess);
  const double s = core.distance - ra - rb;
  if (!(s < margin)) return {};
  const Vec3& n = core.normal;

  FoundPoints found;
  bool reference_b = false;
  Vec3 reference_normal = n;
  const auto choose = [&](const Facet& fa, const Facet& fb) -> int {
    const double sa = fa.count > 0 ? axis_separation(fa, b, ra + rb) : -1e300;
    const double sb = fb.count > 0 ? axis_separation(fb, a, ra + rb) : -1e300;
    const bool use_b = fb.count > 0 && (fa.count == 0 || sb > sa + box_axis_bias(sa));
    const double chosen = use_b ? sb : sa;
    if (s > chosen + box_axis_bias(chosen)) return 0;
    return use_b ? 2 : 1;
  };
  const Facet face_a = face_along(a, n);
  const Facet face_b = face_along(b, -n);
  const int face = choose(face_a, face_b);
  if (face != 0) {
    reference_b = face == 2;
    const Facet& reference = reference_b ? face_b : face_a;
    clip_incident(found, reference, reference_b, reference_b ? a : b, reference_b ? rb : ra,
                  margin);
    reference_normal = reference.normal;
  } else {
    const Facet line_a = line_along(a, n);
    const Facet line_b = line_along(b, -n);
    const int line = choose(line_a, line_b);
    if (line != 0) {
      reference_b = line == 2;
      const Facet& reference = reference_b ? line_b : line_a;
      const Facet incident = line_along(reference_b ? a : b, -reference.normal);
      if (incident.count > 0) {
        const auto cylinder = [](const ShapePose& p) {
          return p.shape->kind == ShapeKind::cylinder;
        };
        const std::uint8_t on_axis = static_cast<std::uint8_t>(
            (cylinder(reference_b ? b : a) ? 1 : 0) | (cylinder(reference_b ? a : b) ? 2 : 0));
        lines_side_by_side(found, reference, reference_b, incident, reference_b ? rb : ra,
                           reference_b ? ra : rb, margin, on_axis);
        reference_normal = reference.normal;
      }
    }
  }
  if (found.count == 0) {
    // One point, between the nearest (or deepest) points of the two surfaces.
    const Vec3 at = 0.5 * (core.on_a + ra * n + core.on_b - rb * n);
    return one_point(a, b, n, at, s, 0xFFFFFFFFu);
  }
  reduce_to_four(found, reference_normal);
  PairManifold out;
  out.normal = reference_b ? Vec3(-reference_normal) : reference_normal;
  for (int k = 0; k < found.count; ++k) {
    const Found& f = found.list[static_cast<std::size_t>(k)];
    add_point(out, a, b, f.at, f.separation, f.feature);
    // Reference and incident to A and B.
    out.points[static_cast<std::size_t>(k)].on_axis =
        reference_b ? static_cast<std::uint8_t>((f.on_axis & 1) << 1 | (f.on_axis & 2) >> 1)
                    : f.on_axis;
  }
  return out;
}

}  // namespace tumble::physics
