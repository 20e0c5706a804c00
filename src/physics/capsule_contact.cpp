#include "physics/capsule_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace tumble::physics {
namespace {

// Of the separating axes of a segment inside a box, an edge's crossing must overlap this much less
// than the best face to be chosen: a face's contact (up to two points, a steady normal) is the one
// to keep when the two are about equal.
constexpr double kFaceBias = 0.95;

struct Segment {
  Vec3 p0, p1;
};

// A round shape's core (world, m): a capsule's segment, a sphere's centre twice.
Segment core_of(const ShapePose& pose) {
  const Shape& shape = *pose.shape;
  if (shape.kind != ShapeKind::capsule) return {pose.position, pose.position};
  const Vec3 end = shape.half_length * pose.rotation.col(1);
  return {pose.position - end, pose.position + end};
}

// Where a parameter in [0, 1] lies: at the start, inside, at the end.
std::uint32_t region(double u) {
  return u <= 0.0 ? 0 : u >= 1.0 ? 2 : 1;
}

// The normal of two cores that meet (their closest points coincide): across both segments, else
// across the one, pointing from A's centre towards B's.
Vec3 normal_of_crossing(const Vec3& da, const Vec3& db, const Vec3& towards) {
  Vec3 n = da.cross(db);
  if (!(n.squaredNorm() > 1e-24 * da.squaredNorm() * db.squaredNorm())) {
    const Vec3& d = da.squaredNorm() >= db.squaredNorm() ? da : db;
    if (!(d.squaredNorm() > 0.0))
      return towards.squaredNorm() > 0.0 ? towards.normalized() : Vec3(Vec3::UnitY());
    const Vec3 across = towards - (towards.dot(d) / d.squaredNorm()) * d;
    n = across.squaredNorm() > 0.0 ? across : any_normal(d);
  }
  n.normalize();
  return n.dot(towards) < 0.0 ? Vec3(-n) : n;
}

// Two capsules side by side: the ends of the stretch of A's segment beside B's, each with its
// nearest point of B's segment, along the normal at the stretch's middle. Empty when they do not
// overlap along A or meet there.
PairManifold side_by_side(const ShapePose& a, const ShapePose& b, const Segment& sa,
                          const Segment& sb, double margin) {
  const Vec3 da = sa.p1 - sa.p0;
  const Vec3 db = sb.p1 - sb.p0;
  const double la2 = da.squaredNorm();
  const double lb2 = db.squaredNorm();
  const double u0 = (sb.p0 - sa.p0).dot(da) / la2;
  const double u1 = (sb.p1 - sa.p0).dot(da) / la2;
  const double lo = std::max(0.0, std::min(u0, u1));
  const double hi = std::min(1.0, std::max(u0, u1));
  if (!(hi > lo)) return {};
  const auto beside = [&](double u) {
    const Vec3 pa = sa.p0 + u * da;
    const double t = std::clamp((pa - sb.p0).dot(db) / lb2, 0.0, 1.0);
    return std::array<Vec3, 2>{pa, sb.p0 + t * db};
  };
  const auto middle = beside(0.5 * (lo + hi));
  const Vec3 apart = middle[1] - middle[0];
  if (!(apart.squaredNorm() > 0.0)) return {};
  PairManifold out;
  out.normal = apart.normalized();
  const double radii = a.shape->radius + b.shape->radius;
  for (const double u : {lo, hi}) {
    const auto [pa, pb] = beside(u);
    const double gap = out.normal.dot(pb - pa) - radii;
    if (!(gap < margin)) continue;
    const Vec3 at = pa + (a.shape->radius + 0.5 * gap) * out.normal;
    add_point(out, a, b, at, gap, 9 + (u == lo ? 0U : 1U));
  }
  return out;
}

// A capsule's segment in a box's frame (m).
struct LocalSegment {
  Vec3 p0, d;  // p0 + t d, t in [0, 1]
  Vec3 at(double t) const { return p0 + t * d; }
};

// The t in [0, 1] of the segment's point nearest the box of half edges `h` (centred, axis-aligned):
// the squared distance is piecewise quadratic in t, with pieces ending where the point crosses a
// face's plane; each piece's least value is found in closed form.
double nearest_to_box(const LocalSegment& s, const Vec3& h) {
  std::array<double, 8> cuts{};
  int count = 0;
  cuts[count++] = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (s.d[i] == 0.0) continue;
    for (const double side : {-1.0, 1.0}) {
      const double t = (side * h[i] - s.p0[i]) / s.d[i];
      if (!(t > 0.0 && t < 1.0)) continue;
      int at = count++;  // kept in order as they come
      for (; at > 0 && cuts[at - 1] > t; --at) cuts[at] = cuts[at - 1];
      cuts[at] = t;
    }
  }
  cuts[count++] = 1.0;
  double best_t = 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k + 1 < count; ++k) {
    const double t0 = cuts[k];
    const double t1 = cuts[k + 1];
    const Vec3 mid = s.at(0.5 * (t0 + t1));
    // Over the piece each coordinate stays below, within or above its slab: the squared distance
    // is Σ (p0_i + t d_i − bound_i)² over the coordinates outside it.
    double qa = 0.0;
    double qb = 0.0;
    for (int i = 0; i < 3; ++i) {
      if (std::abs(mid[i]) <= h[i]) continue;
      const double bound = mid[i] < 0.0 ? -h[i] : h[i];
      qa += s.d[i] * s.d[i];
      qb += 2.0 * s.d[i] * (s.p0[i] - bound);
    }
    const double t = qa > 0.0 ? std::clamp(-qb / (2.0 * qa), t0, t1) : t0;
    const Vec3 p = s.at(t);
    const double value = (p - p.cwiseMax(-h).cwiseMin(h)).squaredNorm();
    if (value < best) {
      best = value;
      best_t = t;
    }
  }
  return best_t;
}

// The box's face (normal axis `axis`, on the side `side`) against the capsule: the ends of the
// part of its segment over the face, those within `margin` of touching.
PairManifold face_contact(const BoxPose& box, const ShapePose& capsule, const LocalSegment& s,
                          int axis, double side, double fallback_t, double margin) {
  const Vec3& h = box.half_size;
  double lo = 0.0;
  double hi = 1.0;
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    if (s.d[j] == 0.0) {
      if (std::abs(s.p0[j]) > h[j]) hi = -1.0;
      continue;
    }
    const double ta = (-h[j] - s.p0[j]) / s.d[j];
    const double tb = (h[j] - s.p0[j]) / s.d[j];
    lo = std::max(lo, std::min(ta, tb));
    hi = std::min(hi, std::max(ta, tb));
  }
  if (!(hi >= lo)) lo = hi = fallback_t;
  Vec3 n_local = Vec3::Zero();
  n_local[axis] = side;
  PairManifold out;
  out.normal = box.rotation * n_local;
  const ShapePose box_pose{box.position, box.rotation, nullptr};
  const double radius = capsule.shape->radius;
  const std::uint32_t face = static_cast<std::uint32_t>(2 * axis + (side > 0.0 ? 1 : 0));
  const int ends = hi > lo ? 2 : 1;
  for (int k = 0; k < ends; ++k) {
    Vec3 p = s.at(k == 0 ? lo : hi);
    const double gap = side * p[axis] - h[axis] - radius;
    if (!(gap < margin)) continue;
    p[axis] = side * h[axis];  // onto the face
    const Vec3 at = box.position + box.rotation * (p + 0.5 * gap * n_local);
    add_point(out, box_pose, capsule, at, gap, 2 * face + static_cast<std::uint32_t>(k));
  }
  return out;
}

// The segment inside the box: the separating axis of least overlap (the box's three faces, and
// the crossings of its three edge directions with the segment), faces preferred.
PairManifold inside_contact(const BoxPose& box, const ShapePose& capsule, const LocalSegment& s,
                            double t_near, double margin) {
  const Vec3& h = box.half_size;
  const Vec3 c = s.at(0.5);
  const Vec3 u = 0.5 * s.d;
  int face_axis = 0;
  double face_overlap = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double overlap = h[i] + std::abs(u[i]) - std::abs(c[i]);
    if (overlap < face_overlap) {
      face_overlap = overlap;
      face_axis = i;
    }
  }
  int edge_axis = -1;
  Vec3 edge_normal = Vec3::Zero();
  double edge_overlap = kFaceBias * face_overlap;
  for (int i = 0; i < 3; ++i) {
    const Vec3 n = Vec3::Unit(i).cross(u);
    const double length = n.norm();
    if (!(length > 1e-9 * u.norm())) continue;
    const Vec3 unit = n / length;
    const double overlap = h.dot(unit.cwiseAbs()) - std::abs(c.dot(unit));
    if (overlap < edge_overlap) {
      edge_overlap = overlap;
      edge_axis = i;
      edge_normal = c.dot(unit) < 0.0 ? Vec3(-unit) : unit;
    }
  }
  if (edge_axis < 0) {
    return face_contact(box, capsule, s, face_axis, c[face_axis] < 0.0 ? -1.0 : 1.0, t_near,
                        margin);
  }
  // The box's edge along `edge_axis` on the normal's side, against the segment.
  Vec3 e0;
  for (int j = 0; j < 3; ++j) e0[j] = edge_normal[j] < 0.0 ? -h[j] : h[j];
  e0[edge_axis] = -h[edge_axis];
  Vec3 e1 = e0;
  e1[edge_axis] = h[edge_axis];
  const SegmentParameters st = closest_segment_points(e0, e1, s.p0, s.p0 + s.d);
  const Vec3 q = e0 + st.s * (e1 - e0);
  const Vec3 p = s.at(st.t);
  const double gap = edge_normal.dot(p - q) - capsule.shape->radius;
  if (!(gap < margin)) return {};
  const Vec3 at = box.position + box.rotation * (q + 0.5 * gap * edge_normal);
  return one_point({box.position, box.rotation, nullptr}, capsule, box.rotation * edge_normal, at,
                   gap, 60 + static_cast<std::uint32_t>(edge_axis));
}

}  // namespace

SegmentParameters closest_segment_points(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                         const Vec3& q1) {
  const Vec3 d1 = p1 - p0;
  const Vec3 d2 = q1 - q0;
  const Vec3 r = p0 - q0;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();
  const double f = d2.dot(r);
  if (!(a > 0.0) && !(e > 0.0)) return {};
  if (!(a > 0.0)) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (!(e > 0.0)) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double b = d1.dot(d2);
  const double denominator = a * e - b * b;  // >= 0; 0 when parallel
  double s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, t};
}

PairManifold round_round_manifold(const ShapePose& a, const ShapePose& b, double margin) {
  const Segment sa = core_of(a);
  const Segment sb = core_of(b);
  const Vec3 da = sa.p1 - sa.p0;
  const Vec3 db = sb.p1 - sb.p0;
  const double la2 = da.squaredNorm();
  const double lb2 = db.squaredNorm();
  if (la2 > 0.0 && lb2 > 0.0 &&
      da.cross(db).squaredNorm() < kSideBySideSine * kSideBySideSine * la2 * lb2) {
    PairManifold two = side_by_side(a, b, sa, sb, margin);
    if (two.count > 0) return two;
  }
  const SegmentParameters st = closest_segment_points(sa.p0, sa.p1, sb.p0, sb.p1);
  const Vec3 pa = sa.p0 + st.s * da;
  const Vec3 pb = sb.p0 + st.t * db;
  const Vec3 apart = pb - pa;
  const double distance = apart.norm();
  const double gap = distance - a.shape->radius - b.shape->radius;
  if (!(gap < margin)) return {};
  const Vec3 normal =
      distance > 0.0 ? Vec3(apart / distance) : normal_of_crossing(da, db, b.position - a.position);
  const Vec3 at = pa + (a.shape->radius + 0.5 * gap) * normal;
  return one_point(a, b, normal, at, gap, 3 * region(st.s) + region(st.t));
}

PairManifold box_capsule_manifold(const BoxPose& box, const ShapePose& capsule, double margin) {
  const Vec3& h = box.half_size;
  const Segment core = core_of(capsule);
  const Mat3 to_box = box.rotation.transpose();
  const LocalSegment s{to_box * (core.p0 - box.position), to_box * (core.p1 - core.p0)};
  const double t = nearest_to_box(s, h);
  const Vec3 p = s.at(t);
  const Vec3 q = p.cwiseMax(-h).cwiseMin(h);
  const Vec3 outside = p - q;
  const double distance = outside.norm();
  if (!(distance > 0.0)) return inside_contact(box, capsule, s, t, margin);
  if (!(distance - capsule.shape->radius < margin)) return {};
  int outside_axes = 0;
  int face_axis = 0;
  std::uint32_t feature = 0;
  for (int axis = 2; axis >= 0; --axis) {
    const std::uint32_t r = p[axis] < -h[axis] ? 0 : p[axis] > h[axis] ? 2 : 1;
    feature = 3 * feature + r;
    if (r != 1) {
      ++outside_axes;
      face_axis = axis;
    }
  }
  if (outside_axes == 1) {
    return face_contact(box, capsule, s, face_axis, p[face_axis] < 0.0 ? -1.0 : 1.0, t, margin);
  }
  // By an edge or a corner: the one closest point.
  const Vec3 n_local = outside / distance;
  const double gap = distance - capsule.shape->radius;
  const Vec3 at = box.position + box.rotation * (q + 0.5 * gap * n_local);
  return one_point({box.position, box.rotation, nullptr}, capsule, box.rotation * n_local, at, gap,
                   24 + feature);
}

}  // namespace tumble::physics
