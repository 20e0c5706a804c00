#include "physics/box_box.hpp"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <utility>

namespace tumble::physics {
namespace {

// An incident corner this close outside a side of the reference face counts as inside and is
// moved onto the side: the corners of two equal stacked cubes sit on each other's sides, and
// without it they would flip between "corner" and "clipped point" ids under rounding (m).
constexpr double kClipSlack = 1.0e-5;
// Depths closer than this are equal when the reduction looks for the deepest point, so the
// choice does not flicker between steps (Box3D keeps a 0.95 "pecking order" bias for the same
// reason, erincatto/box3d src/convex_manifold.c) (m).
constexpr double kDepthTie = 1.0e-6;
// A point adding less area than this to the reduced manifold adds nothing (m²).
constexpr double kMinArea = kClipSlack * kClipSlack;
// Distances² and areas closer than this are equal when the reduction compares them: far above
// the rounding of unit-sized values, far below any difference that matters (m²).
constexpr double kScoreTie = 1.0e-12;

constexpr std::uint32_t kFaceAKind = 0;
constexpr std::uint32_t kFaceBKind = 1;
constexpr std::uint32_t kEdgeKind = 2;

// The best face axis (A's unless B's is clearly better) and the best edge pair, kept apart so
// that a face contact that clips to nothing can fall back on the edges.
struct AxisSearch {
  BoxAxis face;
  BoxAxis edge;
  bool has_edge = false;
  double largest_separation = 0.0;  // over every axis tested: a bound on the gap (m)
};

// The separating-axis test (Gottschalk, Lin & Manocha 1996, "OBBTree", §4) with the projections
// of both boxes read off the cosines C_ij = a_i · b_j of their axes, found once: on A's face axis
// a_i a box B projects to Σ_j h_j |C_ij|, on an edge axis a_i × b_j each box projects through the
// two cosines of its other axes. Every value that reaches a separation is formed so that
// swapping A and B gives the same bits (products and sums of the same terms in the same order,
// the offset a dot product of the same two vectors negated), as the manifold promises. Stops at
// the first axis whose gap is `stop` or more: the boxes are then that far apart.
AxisSearch search_axes(const BoxPose& a, const BoxPose& b, double stop = INFINITY) {
  AxisSearch search;
  const Vec3 d = b.position - a.position;
  double cosine[3][3];  // |a_i · b_j|
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) cosine[i][j] = std::abs(a.rotation.col(i).dot(b.rotation.col(j)));
  }
  const Vec3& ha = a.half_size;
  const Vec3& hb = b.half_size;
  const auto face = [&](BoxAxisKind kind, int i, int j, const Vec3& axis, double radius) {
    const double offset = axis.dot(d);
    return BoxAxis{kind, i, j, offset < 0.0 ? Vec3(-axis) : axis, std::abs(offset) - radius};
  };
  BoxAxis best_a{.separation = -INFINITY};
  BoxAxis best_b{.kind = BoxAxisKind::face_b, .separation = -INFINITY};
  for (int k = 0; k < 3; ++k) {  // strict > keeps the lowest index on exact ties
    const double radius_b = hb.x() * cosine[k][0] + hb.y() * cosine[k][1] + hb.z() * cosine[k][2];
    const BoxAxis on_a = face(BoxAxisKind::face_a, k, 0, a.rotation.col(k), ha[k] + radius_b);
    if (on_a.separation > best_a.separation) best_a = on_a;
    const double radius_a = ha.x() * cosine[0][k] + ha.y() * cosine[1][k] + ha.z() * cosine[2][k];
    const BoxAxis on_b = face(BoxAxisKind::face_b, 0, k, b.rotation.col(k), radius_a + hb[k]);
    if (on_b.separation > best_b.separation) best_b = on_b;
  }
  const bool b_wins = best_b.separation > best_a.separation + box_axis_bias(best_a.separation);
  search.face = b_wins ? best_b : best_a;
  search.largest_separation = std::max(best_a.separation, best_b.separation);
  if (!(search.largest_separation < stop)) return search;
  search.edge.separation = -INFINITY;
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const Vec3 cross = a.rotation.col(i).cross(b.rotation.col(j));
      const double sine = cross.norm();  // both axes are unit
      if (sine < kParallelEdgeSine) continue;
      // |(a_i × b_j) · a_i1| = |C_i2j| and |(a_i × b_j) · a_i2| = |C_i1j|; likewise for B.
      const double radius_a = ha[i1] * cosine[i2][j] + ha[i2] * cosine[i1][j];
      const double radius_b = hb[j1] * cosine[i][j2] + hb[j2] * cosine[i][j1];
      const double offset = cross.dot(d);
      const double separation = (std::abs(offset) - (radius_a + radius_b)) / sine;
      if (separation > search.edge.separation) {
        const Vec3 axis = cross / sine;
        search.edge = {BoxAxisKind::edge_pair, i, j, offset < 0.0 ? Vec3(-axis) : axis, separation};
        search.has_edge = true;
      }
    }
  }
  if (search.has_edge) {
    search.largest_separation = std::max(search.largest_separation, search.edge.separation);
  }
  return search;
}

bool edge_wins(const AxisSearch& search) {
  return search.has_edge &&
         search.edge.separation > search.face.separation + box_axis_bias(search.face.separation);
}

// The two body axes other than `axis`, the lower first.
std::array<int, 2> other_axes(int axis) {
  return {axis == 0 ? 1 : 0, axis == 2 ? 1 : 2};
}

int face_index(int axis, double sign) {
  return 2 * axis + (sign > 0.0 ? 1 : 0);
}

// A vertex of the polygon being clipped, in the reference box's body frame, with the two lines
// it lies on (the feature-id labels of box_box.hpp).
struct ClipVertex {
  Vec3 position;
  std::array<std::uint8_t, 2> lines;
};

// A quad clipped by four sides has at most eight corners. Moving corners in the slack onto a side
// can fold a sliver of the polygon onto that side, which a later side may cross twice more, so
// there is room for more; a polygon that would still overflow drops the excess in release builds.
constexpr int kMaxClipVertices = 16;

struct ClipPolygon {
  std::array<ClipVertex, kMaxClipVertices> vertices;
  int count = 0;
  void push(const ClipVertex& v) {
    assert(count < kMaxClipVertices);
    if (count < kMaxClipVertices) vertices[static_cast<std::size_t>(count++)] = v;
  }
};

// The line an edge of the polygon lies on: consecutive vertices share one, since a clip keeps
// sub-segments of edges and joins an exit to an entry along the clipping side.
std::uint8_t shared_line(const ClipVertex& p, const ClipVertex& q) {
  for (std::uint8_t line : p.lines) {
    if (line == q.lines[0] || line == q.lines[1]) return line;
  }
  assert(false && "consecutive clip vertices share no line");
  return p.lines[1];
}

// Keeps the part of the polygon with sign x[axis] <= limit (one pass of Sutherland & Hodgman
// 1974, "Reentrant polygon clipping"). A corner up to kClipSlack outside still counts as inside
// and is moved onto the side, along the side's normal, so its height is unchanged. Crossings are
// on the side itself; a segment leaving from a corner in the slack crosses at that corner, which
// leaves an exact duplicate for merge_duplicates.
ClipPolygon clip(const ClipPolygon& in, int axis, double sign, double limit, std::uint8_t line) {
  ClipPolygon out;
  for (int i = 0; i < in.count; ++i) {
    const ClipVertex& p = in.vertices[static_cast<std::size_t>(i)];
    const ClipVertex& q = in.vertices[static_cast<std::size_t>((i + 1) % in.count)];
    const double p_out = sign * p.position[axis] - limit;  // > 0 outside the side (m)
    const double q_out = sign * q.position[axis] - limit;
    const bool p_in = p_out <= kClipSlack;
    if (p_in) out.push(p);
    if (p_in != (q_out <= kClipSlack)) {
      const double t = p_out / (p_out - q_out);
      const Vec3 crossing = t <= 0.0   ? p.position
                            : t >= 1.0 ? q.position
                                       : Vec3(p.position + t * (q.position - p.position));
      const std::uint8_t edge = shared_line(p, q);
      out.push({crossing, {std::min(edge, line), std::max(edge, line)}});
    }
  }
  for (int i = 0; i < out.count; ++i) {
    double& coordinate = out.vertices[static_cast<std::size_t>(i)].position[axis];
    if (sign * coordinate > limit) coordinate = sign * limit;
  }
  return out;
}

// Merges neighbours at the same position into one, keeping the lower pair of lines: an incident
// corner in the slack keeps its corner id rather than that of the crossing it stands for.
ClipPolygon merge_duplicates(const ClipPolygon& in) {
  ClipPolygon out;
  for (int i = 0; i < in.count; ++i) {
    const ClipVertex& v = in.vertices[static_cast<std::size_t>(i)];
    ClipVertex* last =
        out.count > 0 ? &out.vertices[static_cast<std::size_t>(out.count - 1)] : nullptr;
    if (last != nullptr && last->position == v.position) {
      last->lines = std::min(last->lines, v.lines);
    } else {
      out.push(v);
    }
  }
  if (out.count > 1 &&
      out.vertices[0].position == out.vertices[static_cast<std::size_t>(out.count - 1)].position) {
    out.vertices[0].lines = std::min(out.vertices[0].lines,
                                     out.vertices[static_cast<std::size_t>(out.count - 1)].lines);
    --out.count;
  }
  return out;
}

// A clipped point below the reference face plus margin.
struct Candidate {
  Vec3 position;      // on the incident face, reference body frame (m)
  Vec3 world;         // halfway down to the reference face, world frame (m)
  double separation;  // above the reference face (m)
  std::uint32_t feature;
};

// z of the cross product of two tangent-plane vectors: twice a signed triangle area (m²).
double signed_area(const Vec3& a, const Vec3& b, const Vec3& c, int u, int v) {
  return (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
}

// Among candidates [from, count), the one with the largest score, scores within `tie` of it
// counting as equal; equals are told apart by how far they lie along a fixed world direction
// with irrational ratios. So a symmetric set (the octagon of two equal cubes at 45°) keeps the
// same points whichever box gave the reference face, not the ones the clip happened to list
// first. `best` returns the largest score.
template <class Score>
int pick(const std::array<Candidate, kMaxClipVertices>& candidates, int from, int count, double tie,
         Score score, double& best) {
  const Vec3 tie_direction(1.0, 1.4142135623730951, 1.7320508075688772);  // (1, √2, √3)
  best = -INFINITY;
  for (int i = from; i < count; ++i) best = std::max(best, score(candidates[i]));
  int chosen = from;
  double farthest_along = -INFINITY;
  for (int i = from; i < count; ++i) {
    const double along = tie_direction.dot(candidates[i].world);
    if (score(candidates[i]) >= best - tie && along > farthest_along) {
      chosen = i;
      farthest_along = along;
    }
  }
  return chosen;
}

// Four of the candidates that hold the box as the whole set would: the deepest, the farthest
// from it in the tangent plane, the one making the largest triangle with those two, and the one
// adding the most area outside that triangle (Box3D's b3ReduceManifoldPoints, erincatto/box3d
// src/convex_manifold.c, without its depth term in the distance; Bullet's
// btPersistentManifold::sortCachedPoints also keeps the deepest and maximises the area).
int reduce(std::array<Candidate, kMaxClipVertices>& candidates, int count, int normal_axis) {
  if (count <= kMaxManifoldPoints) return count;
  // (No structured binding: clang 14 cannot capture one in a lambda.)
  const std::array<int, 2> axes = other_axes(normal_axis);
  const int u = axes[0], v = axes[1];
  const auto take = [&](int chosen, int slot) { std::swap(candidates[chosen], candidates[slot]); };
  double best = 0.0;
  take(pick(
           candidates, 0, count, kDepthTie, [](const Candidate& c) { return -c.separation; }, best),
       0);
  const Vec3 first = candidates[0].position;
  const auto distance_squared = [&](const Candidate& c) {
    return (c.position[u] - first[u]) * (c.position[u] - first[u]) +
           (c.position[v] - first[v]) * (c.position[v] - first[v]);
  };
  const int farthest = pick(candidates, 1, count, kScoreTie, distance_squared, best);
  if (best < kMinArea) return 1;
  take(farthest, 1);
  const Vec3 second = candidates[1].position;
  const auto area = [&](const Candidate& c) {
    return std::abs(signed_area(first, second, c.position, u, v));
  };
  const int widest = pick(candidates, 2, count, kScoreTie, area, best);
  if (!(best > kMinArea)) return 2;
  take(widest, 2);
  const Vec3 third = candidates[2].position;
  // A point beyond a side of the triangle is on the side's other hand from the third corner.
  const double outward = signed_area(first, second, third, u, v) < 0.0 ? 1.0 : -1.0;
  const auto added_area = [&](const Candidate& c) {
    return std::max({outward * signed_area(first, second, c.position, u, v),
                     outward * signed_area(second, third, c.position, u, v),
                     outward * signed_area(third, first, c.position, u, v)});
  };
  const int outside = pick(candidates, 3, count, kScoreTie, added_area, best);
  if (!(best > kMinArea)) return 3;
  take(outside, 3);
  return 4;
}

// The incident quad: the face of `incident` most anti-parallel to the reference normal, in the
// reference body frame, its corners in order round the face with their two edges as labels.
ClipPolygon incident_face(const BoxPose& reference, const BoxPose& incident,
                          const Vec3& reference_normal, int& face_out) {
  int axis = 0;
  double largest = -1.0;
  for (int k = 0; k < 3; ++k) {
    const double alignment = std::abs(reference_normal.dot(incident.rotation.col(k)));
    if (alignment > largest) {
      axis = k;
      largest = alignment;
    }
  }
  const double sign = reference_normal.dot(incident.rotation.col(axis)) > 0.0 ? -1.0 : 1.0;
  face_out = face_index(axis, sign);
  const std::array<int, 2> axes = other_axes(axis);
  const int u = axes[0], v = axes[1];
  const Mat3 to_reference = reference.rotation.transpose() * incident.rotation;
  const Vec3 centre = reference.rotation.transpose() * (incident.position - reference.position);
  constexpr double kCornerU[4] = {-1.0, 1.0, 1.0, -1.0};
  constexpr double kCornerV[4] = {-1.0, -1.0, 1.0, 1.0};
  ClipPolygon quad;
  for (int corner = 0; corner < 4; ++corner) {
    Vec3 local = Vec3::Zero();
    local[axis] = sign * incident.half_size[axis];
    local[u] = kCornerU[corner] * incident.half_size[u];
    local[v] = kCornerV[corner] * incident.half_size[v];
    // Corner k joins edge k − 1 (from the previous corner) and edge k (to the next).
    const auto before = static_cast<std::uint8_t>((corner + 3) % 4);
    const auto after = static_cast<std::uint8_t>(corner);
    quad.push({centre + to_reference * local, {std::min(before, after), std::max(before, after)}});
  }
  return quad;
}

// The contact point halfway between the incident surface and the reference face, stored
// relative to each body in its own frame.
PairPoint pair_point(const BoxPose& a, const BoxPose& b, const Vec3& world, double separation,
                     std::uint32_t feature) {
  PairPoint point;
  point.feature = feature;
  point.point_a = a.rotation.transpose() * (world - a.position);
  point.point_b = b.rotation.transpose() * (world - b.position);
  point.separation = separation;
  return point;
}

// The face contact: the incident face clipped to the reference face's four sides, the points
// below the reference face plus margin, at most four of them.
PairManifold face_contact(const BoxPose& a, const BoxPose& b, const BoxAxis& axis, double margin) {
  const bool a_is_reference = axis.kind == BoxAxisKind::face_a;
  const BoxPose& reference = a_is_reference ? a : b;
  const BoxPose& incident = a_is_reference ? b : a;
  const int normal_axis = a_is_reference ? axis.axis_a : axis.axis_b;
  // Out of the reference box, towards the other.
  const Vec3 reference_normal = a_is_reference ? axis.normal : Vec3(-axis.normal);
  const double sign = reference_normal.dot(reference.rotation.col(normal_axis)) > 0.0 ? 1.0 : -1.0;
  int incident_index = 0;
  ClipPolygon polygon = incident_face(reference, incident, reference_normal, incident_index);
  const std::array<int, 2> axes = other_axes(normal_axis);
  const int u = axes[0], v = axes[1];
  const int sides[2] = {u, v};
  for (int side = 0; side < 2; ++side) {
    for (int end = 0; end < 2; ++end) {
      const auto line = static_cast<std::uint8_t>(4 + 2 * side + end);
      const int side_axis = sides[side];
      polygon =
          clip(polygon, side_axis, end == 0 ? -1.0 : 1.0, reference.half_size[side_axis], line);
    }
  }
  polygon = merge_duplicates(polygon);
  const std::uint32_t face_bits = (a_is_reference ? kFaceAKind : kFaceBKind) |
                                  static_cast<std::uint32_t>(face_index(normal_axis, sign)) << 2 |
                                  static_cast<std::uint32_t>(incident_index) << 5;
  std::array<Candidate, kMaxClipVertices> candidates;
  int count = 0;
  for (int i = 0; i < polygon.count; ++i) {
    const ClipVertex& vertex = polygon.vertices[static_cast<std::size_t>(i)];
    const double separation =
        sign * vertex.position[normal_axis] - reference.half_size[normal_axis];
    if (!(separation < margin)) continue;
    const std::uint32_t lines = static_cast<std::uint32_t>(vertex.lines[0]) << 8 |
                                static_cast<std::uint32_t>(vertex.lines[1]) << 11;
    Vec3 midway = vertex.position;
    midway[normal_axis] -= 0.5 * sign * separation;  // halfway down to the reference face
    candidates[static_cast<std::size_t>(count++)] = {
        vertex.position, reference.position + reference.rotation * midway, separation,
        face_bits | lines};
  }
  count = reduce(candidates, count, normal_axis);
  PairManifold out;
  out.normal = axis.normal;
  out.count = count;
  for (int i = 0; i < count; ++i) {
    const Candidate& c = candidates[static_cast<std::size_t>(i)];
    out.points[static_cast<std::size_t>(i)] = pair_point(a, b, c.world, c.separation, c.feature);
  }
  return out;
}

// The supporting edge of a box along a direction: its middle (world, m) and its edge index.
struct SupportEdge {
  Vec3 middle;
  int index;
};

SupportEdge support_edge(const BoxPose& box, int axis, const Vec3& direction) {
  SupportEdge edge{box.position, 4 * axis};
  const auto others = other_axes(axis);
  for (int bit = 0; bit < 2; ++bit) {
    const int k = others[static_cast<std::size_t>(bit)];
    const bool plus = direction.dot(box.rotation.col(k)) >= 0.0;
    edge.middle += (plus ? 1.0 : -1.0) * box.half_size[k] * box.rotation.col(k);
    if (plus) edge.index |= 1 << bit;
  }
  return edge;
}

// Closest points of the segments p + s d, s in [0, 1], and q + t e, t in [0, 1], for segments
// that are not parallel (Ericson 2005, "Real-Time Collision Detection", §5.1.9).
std::array<Vec3, 2> closest_points(const Vec3& p, const Vec3& d, const Vec3& q, const Vec3& e) {
  const Vec3 r = p - q;
  const double dd = d.dot(d), ee = e.dot(e), de = d.dot(e), dr = d.dot(r), er = e.dot(r);
  const double denominator = dd * ee - de * de;  // > 0: not parallel
  double s = std::clamp((de * er - dr * ee) / denominator, 0.0, 1.0);
  double t = (de * s + er) / ee;
  if (t < 0.0 || t > 1.0) {
    t = std::clamp(t, 0.0, 1.0);
    s = std::clamp((de * t - dr) / dd, 0.0, 1.0);
  }
  return {p + s * d, q + t * e};
}

// The edge–edge contact: one point halfway between the closest points of the two edges that
// support the boxes along the axis (ODE's dBoxBox uses the same point, odedevs/ode box.cpp).
PairManifold edge_contact(const BoxPose& a, const BoxPose& b, const BoxAxis& axis, double margin) {
  const SupportEdge edge_a = support_edge(a, axis.axis_a, axis.normal);
  const SupportEdge edge_b = support_edge(b, axis.axis_b, -axis.normal);
  const Vec3 along_a = a.half_size[axis.axis_a] * a.rotation.col(axis.axis_a);
  const Vec3 along_b = b.half_size[axis.axis_b] * b.rotation.col(axis.axis_b);
  const auto [on_a, on_b] = closest_points(edge_a.middle - along_a, 2.0 * along_a,
                                           edge_b.middle - along_b, 2.0 * along_b);
  const double separation = axis.normal.dot(on_b - on_a);
  PairManifold out;
  out.normal = axis.normal;
  if (!(separation < margin)) return out;
  const std::uint32_t feature = kEdgeKind | static_cast<std::uint32_t>(edge_a.index) << 2 |
                                static_cast<std::uint32_t>(edge_b.index) << 6;
  out.points[0] = pair_point(a, b, 0.5 * (on_a + on_b), separation, feature);
  out.count = 1;
  return out;
}

}  // namespace

BoxAxis box_box_axis(const BoxPose& a, const BoxPose& b) {
  const AxisSearch search = search_axes(a, b);
  return edge_wins(search) ? search.edge : search.face;
}

PairManifold box_box_manifold(const BoxPose& a, const BoxPose& b, double margin) {
  const AxisSearch search = search_axes(a, b, margin);
  // Any axis with a gap of at least margin separates the boxes by at least margin.
  if (!(search.largest_separation < margin)) return PairManifold{};
  if (edge_wins(search)) return edge_contact(a, b, search.edge, margin);
  PairManifold out = face_contact(a, b, search.face, margin);
  // The face axis won by its bias alone and its face clips to nothing (edges crossing past the
  // face): the edge pair still holds the boxes apart (research/contact.md §3.3 notes Box3D
  // doing the same).
  if (out.count == 0 && search.has_edge) out = edge_contact(a, b, search.edge, margin);
  return out;
}

}  // namespace tumble::physics
