#include "physics/gjk.hpp"

#include <array>
#include <cmath>
#include <limits>

namespace tumble::physics {
namespace {

// GJK stops when the distance is known to within kSettled (m), EPA when the depth is (a curved
// cylinder's needs more rounds the closer: 15 on average at 1e-8 m in the mixed pour, 20 at
// 1e-10). kTolerance is what tells points apart: a new corner from the simplex's, a face's plane.
constexpr double kSettled = 1e-8;
constexpr double kTolerance = 1e-10;
constexpr int kMostIterations = 64;

// A point of the cores' difference A − B and the two points it is made of (world, m).
struct Vertex {
  Vec3 w, a, b;
};

Vertex support_vertex(const ShapePose& a, const ShapePose& b, const Vec3& direction) {
  const Vec3 on_a = core_support(a, direction);
  const Vec3 on_b = core_support(b, -direction);
  return {on_a - on_b, on_a, on_b};
}

struct Simplex {
  std::array<Vertex, 4> v;
  std::array<double, 4> lambda{};  // barycentric weights of the point nearest the origin
  int n = 0;
};

// The barycentric weights of the point of the affine hull of `p` (k of them, 1 to 4) nearest the
// origin, by the normal equations of its k − 1 edges from p[0]; false when the points are
// degenerate (on a line, a plane) for that.
bool affine_nearest(const std::array<const Vec3*, 4>& p, int k, std::array<double, 4>& lambda) {
  const int m = k - 1;
  std::array<Vec3, 3> e;
  Vec3 rhs = Vec3::Zero();
  for (int i = 0; i < m; ++i) {
    e[static_cast<std::size_t>(i)] = *p[static_cast<std::size_t>(i) + 1] - *p[0];
    rhs[i] = -e[static_cast<std::size_t>(i)].dot(*p[0]);
  }
  Vec3 x = Vec3::Zero();
  if (m == 1) {
    const double g = e[0].squaredNorm();
    if (!(g > 0.0)) return false;
    x[0] = rhs[0] / g;
  } else if (m == 2) {
    const double g00 = e[0].squaredNorm(), g11 = e[1].squaredNorm(), g01 = e[0].dot(e[1]);
    const double det = g00 * g11 - g01 * g01;
    if (!(det > 1e-12 * g00 * g11)) return false;
    x[0] = (rhs[0] * g11 - rhs[1] * g01) / det;
    x[1] = (g00 * rhs[1] - g01 * rhs[0]) / det;
  } else if (m == 3) {
    Mat3 g;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        g(i, j) = e[static_cast<std::size_t>(i)].dot(e[static_cast<std::size_t>(j)]);
      }
    }
    const double det = g.determinant();
    if (!(det > 1e-12 * g(0, 0) * g(1, 1) * g(2, 2))) return false;
    x = g.inverse() * rhs;
  }
  double first = 1.0;
  for (int i = 0; i < m; ++i) first -= x[i];
  lambda = {first, x[0], x[1], x[2]};
  return true;
}

// Reduces the simplex, its newest point last, to the fewest of its points whose hull holds its
// point nearest the origin, and returns that point. Johnson's subset test, over the subsets that
// hold the newest point (the point nearest the origin moved towards it: it is in the answer),
// smaller subsets first.
Vec3 reduce(Simplex& s) {
  static constexpr std::array<std::array<int, 8>, 5> kSubsets{{{0, 0, 0, 0, 0, 0, 0, 0},
                                                               {1, 0, 0, 0, 0, 0, 0, 0},
                                                               {2, 3, 0, 0, 0, 0, 0, 0},
                                                               {4, 5, 6, 7, 0, 0, 0, 0},
                                                               {8, 9, 10, 12, 11, 13, 14, 15}}};
  double best = std::numeric_limits<double>::infinity();
  int best_mask = 1 << (s.n - 1);
  std::array<double, 4> best_lambda{1.0, 0.0, 0.0, 0.0};
  for (int m = 0; m < (1 << (s.n - 1)); ++m) {
    const int mask = kSubsets[static_cast<std::size_t>(s.n)][static_cast<std::size_t>(m)];
    std::array<const Vec3*, 4> p{};
    int k = 0;
    for (int i = 0; i < s.n; ++i) {
      if (mask & (1 << i)) p[static_cast<std::size_t>(k++)] = &s.v[static_cast<std::size_t>(i)].w;
    }
    std::array<double, 4> lambda{1.0, 0.0, 0.0, 0.0};
    if (k > 1 && !affine_nearest(p, k, lambda)) continue;
    bool inside = true;
    Vec3 x = Vec3::Zero();
    for (int i = 0; i < k; ++i) {
      inside = inside && lambda[static_cast<std::size_t>(i)] > 0.0;
      x += lambda[static_cast<std::size_t>(i)] * *p[static_cast<std::size_t>(i)];
    }
    if (!inside) continue;
    if (x.squaredNorm() < best) {
      best = x.squaredNorm();
      best_mask = mask;
      best_lambda = lambda;
    }
  }
  Simplex out;
  for (int i = 0; i < s.n; ++i) {
    if (best_mask & (1 << i)) {
      out.lambda[static_cast<std::size_t>(out.n)] = best_lambda[static_cast<std::size_t>(out.n)];
      out.v[static_cast<std::size_t>(out.n++)] = s.v[static_cast<std::size_t>(i)];
    }
  }
  s = out;
  Vec3 x = Vec3::Zero();
  for (int i = 0; i < s.n; ++i) {
    x += s.lambda[static_cast<std::size_t>(i)] * s.v[static_cast<std::size_t>(i)].w;
  }
  return x;
}

// Grows a simplex holding the origin (on its boundary, or inside when it has four points) into a
// tetrahedron of the difference's support points; false when the difference is too flat for one.
bool grow_to_tetrahedron(const ShapePose& a, const ShapePose& b, Simplex& s) {
  const auto try_add = [&](const Vec3& direction, auto&& off) {
    const Vertex w = support_vertex(a, b, direction);
    if (!(off(w.w) > kTolerance)) return false;
    s.v[static_cast<std::size_t>(s.n++)] = w;
    return true;
  };
  if (s.n == 1) {
    const auto off = [&](const Vec3& w) { return (w - s.v[0].w).norm(); };
    const std::array<Vec3, 6> directions{Vec3::UnitX(),  Vec3::UnitY(),  Vec3::UnitZ(),
                                         -Vec3::UnitX(), -Vec3::UnitY(), -Vec3::UnitZ()};
    for (const Vec3& d : directions) {
      if (try_add(d, off)) break;
    }
    if (s.n < 2) return false;
  }
  if (s.n == 2) {
    const Vec3 line = s.v[1].w - s.v[0].w;
    const Vec3 e1 = any_normal(line);
    const Vec3 e2 = line.normalized().cross(e1);
    const auto off = [&](const Vec3& w) {
      const Vec3 r = w - s.v[0].w;
      return (r - (r.dot(line) / line.squaredNorm()) * line).norm();
    };
    for (const Vec3& d : {e1, Vec3(-e1), e2, Vec3(-e2)}) {
      if (try_add(d, off)) break;
    }
    if (s.n < 3) return false;
  }
  if (s.n == 3) {
    const Vec3 normal = (s.v[1].w - s.v[0].w).cross(s.v[2].w - s.v[0].w);
    if (!(normal.norm() > 0.0)) return false;
    const Vec3 unit = normal.normalized();
    const auto off = [&](const Vec3& w) { return std::abs(unit.dot(w - s.v[0].w)); };
    if (!try_add(unit, off) && !try_add(-unit, off)) return false;
  }
  return true;
}

// EPA adds a corner a round; a hull's difference with another may need many.
constexpr int kMostExpansions = 128;
constexpr int kMostVertices = 4 + kMostExpansions;
constexpr int kMostFaces = 2 * kMostVertices;

struct Face {
  std::array<int, 3> corner;
  Vec3 normal;  // unit, out of the polytope (zero for a face of no area)
  double distance;
};

Face make_face(const std::array<Vertex, kMostVertices>& v, int i, int j, int k) {
  Vec3 n = (v[static_cast<std::size_t>(j)].w - v[static_cast<std::size_t>(i)].w)
               .cross(v[static_cast<std::size_t>(k)].w - v[static_cast<std::size_t>(i)].w);
  const double length = n.norm();
  if (!(length > 0.0)) return {{i, j, k}, Vec3::Zero(), std::numeric_limits<double>::infinity()};
  n /= length;
  return {{i, j, k}, n, n.dot(v[static_cast<std::size_t>(i)].w)};
}

// The depth, normal and deepest points that a face of the polytope gives: the origin's projection
// on it, by its barycentric weights.
CoreDistance through(const std::array<Vertex, kMostVertices>& v, const Face& face) {
  const Vertex& p0 = v[static_cast<std::size_t>(face.corner[0])];
  const Vertex& p1 = v[static_cast<std::size_t>(face.corner[1])];
  const Vertex& p2 = v[static_cast<std::size_t>(face.corner[2])];
  const Vec3 x = face.distance * face.normal;
  const double whole = (p1.w - p0.w).cross(p2.w - p0.w).dot(face.normal);
  const double l1 = (x - p0.w).cross(p2.w - p0.w).dot(face.normal) / whole;
  const double l2 = (p1.w - p0.w).cross(x - p0.w).dot(face.normal) / whole;
  const double l0 = 1.0 - l1 - l2;
  return {.distance = -face.distance,
          .normal = face.normal,
          .on_a = l0 * p0.a + l1 * p1.a + l2 * p2.a,
          .on_b = l0 * p0.b + l1 * p1.b + l2 * p2.b};
}

// The expanding polytope algorithm from a tetrahedron holding the origin: its face nearest the
// origin, grown towards until the difference's support along it is no farther (within
// kSettled). Should round-off turn a new face inwards (nearer the origin than the face it grew
// from, which exact arithmetic never does), or the corners run out, the last good face is the
// answer: its depth is then short of the true one.
CoreDistance expand(const ShapePose& a, const ShapePose& b, const Simplex& s) {
  std::array<Vertex, kMostVertices> v;
  int vertices = 4;
  for (std::size_t i = 0; i < 4; ++i) v[i] = s.v[i];
  // Wind the tetrahedron's faces outwards.
  if ((v[1].w - v[0].w).cross(v[2].w - v[0].w).dot(v[3].w - v[0].w) > 0.0) std::swap(v[1], v[2]);
  std::array<Face, kMostFaces> faces;
  int count = 0;
  for (const std::array<int, 3>& f :
       {std::array<int, 3>{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}) {
    faces[static_cast<std::size_t>(count++)] = make_face(v, f[0], f[1], f[2]);
  }
  std::array<std::array<int, 2>, kMostFaces> horizon;
  std::array<bool, kMostFaces> seen;
  while (true) {
    int best = 0;
    for (int f = 1; f < count; ++f) {
      if (faces[static_cast<std::size_t>(f)].distance <
          faces[static_cast<std::size_t>(best)].distance) {
        best = f;
      }
    }
    const Face closest = faces[static_cast<std::size_t>(best)];
    if (vertices == kMostVertices) return through(v, closest);
    const Vertex w = support_vertex(a, b, closest.normal);
    if (!(w.w.dot(closest.normal) - closest.distance > kSettled)) return through(v, closest);
    // The faces the new point sees go (those it lies in the plane of, to within the tolerance,
    // stay); the edges between them and the rest (the horizon) each make a face with it.
    int edges = 0;
    for (int f = 0; f < count; ++f) {
      const Face& face = faces[static_cast<std::size_t>(f)];
      const Vec3& corner = v[static_cast<std::size_t>(face.corner[0])].w;
      seen[static_cast<std::size_t>(f)] = face.normal.dot(w.w - corner) > kTolerance;
      if (!seen[static_cast<std::size_t>(f)]) continue;
      for (int e = 0; e < 3; ++e) {
        const std::array<int, 2> edge{face.corner[static_cast<std::size_t>(e)],
                                      face.corner[static_cast<std::size_t>((e + 1) % 3)]};
        int twin = -1;
        for (int h = 0; h < edges && twin < 0; ++h) {
          if (horizon[static_cast<std::size_t>(h)][0] == edge[1] &&
              horizon[static_cast<std::size_t>(h)][1] == edge[0]) {
            twin = h;
          }
        }
        if (twin >= 0) {
          horizon[static_cast<std::size_t>(twin)] = horizon[static_cast<std::size_t>(--edges)];
        } else {
          horizon[static_cast<std::size_t>(edges++)] = edge;
        }
      }
    }
    int kept = 0;
    for (int f = 0; f < count; ++f) {
      if (!seen[static_cast<std::size_t>(f)]) {
        faces[static_cast<std::size_t>(kept++)] = faces[static_cast<std::size_t>(f)];
      }
    }
    if (kept + edges > kMostFaces) return through(v, closest);  // (a polytope has ≤ 2V − 4)
    v[static_cast<std::size_t>(vertices)] = w;
    for (int h = 0; h < edges; ++h) {
      const Face face = make_face(v, horizon[static_cast<std::size_t>(h)][0],
                                  horizon[static_cast<std::size_t>(h)][1], vertices);
      if (face.distance < closest.distance - kTolerance) return through(v, closest);
      faces[static_cast<std::size_t>(kept++)] = face;
    }
    ++vertices;
    count = kept;
  }
}

}  // namespace

Vec3 core_support(const ShapePose& pose, const Vec3& direction) {
  const Shape& shape = *pose.shape;
  const Vec3 d = pose.rotation.transpose() * direction;
  Vec3 local = Vec3::Zero();
  switch (shape.kind) {
    case ShapeKind::box:
      for (int k = 0; k < 3; ++k) local[k] = d[k] >= 0.0 ? shape.half_size[k] : -shape.half_size[k];
      break;
    case ShapeKind::sphere:
      break;
    case ShapeKind::capsule:
      local.y() = d.y() >= 0.0 ? shape.half_length : -shape.half_length;
      break;
    case ShapeKind::cylinder: {
      local.y() = d.y() >= 0.0 ? shape.half_length : -shape.half_length;
      const double across = std::sqrt(d.x() * d.x() + d.z() * d.z());
      if (across > 0.0) {
        local.x() = shape.radius * d.x() / across;
        local.z() = shape.radius * d.z() / across;
      }
      break;
    }
    case ShapeKind::hull: {
      double most = -std::numeric_limits<double>::infinity();
      for (const Vec3& corner : shape.hull->vertices) {
        const double reach = corner.dot(d);
        if (reach > most) {
          most = reach;
          local = corner;
        }
      }
      break;
    }
  }
  return pose.position + pose.rotation * local;
}

CoreDistance core_distance(const ShapePose& a, const ShapePose& b, const Vec3& guess) {
  Simplex s;
  // The support points along the guess, or the difference of the centres: a point of A − B (each
  // centre lies in its core).
  s.v[0] = guess.squaredNorm() > 0.0 ? support_vertex(a, b, guess)
                                     : Vertex{a.position - b.position, a.position, b.position};
  s.lambda[0] = 1.0;
  s.n = 1;
  Vec3 v = s.v[0].w;
  double vv = v.squaredNorm();
  bool overlap = !(vv > 0.0);
  for (int iteration = 0; !overlap && iteration < kMostIterations; ++iteration) {
    const Vertex w = support_vertex(a, b, -v);
    // |v| bounds the distance from above, v·w / |v| from below.
    if (vv - v.dot(w.w) <= kSettled * std::sqrt(vv)) break;
    bool known = false;
    for (int i = 0; i < s.n; ++i) known = known || s.v[static_cast<std::size_t>(i)].w == w.w;
    if (known) break;
    Simplex grown = s;
    grown.v[static_cast<std::size_t>(grown.n++)] = w;
    const Vec3 next = reduce(grown);
    const double next_vv = next.squaredNorm();
    if (grown.n == 4 || !(next_vv > kTolerance * kTolerance)) {
      s = grown;
      overlap = true;
      break;
    }
    if (!(next_vv < vv)) break;  // no progress: round-off
    s = grown;
    v = next;
    vv = next_vv;
  }
  if (!overlap) {
    CoreDistance out;
    out.distance = std::sqrt(vv);
    out.normal = -v / out.distance;
    out.on_a = Vec3::Zero();
    out.on_b = Vec3::Zero();
    for (int i = 0; i < s.n; ++i) {
      out.on_a += s.lambda[static_cast<std::size_t>(i)] * s.v[static_cast<std::size_t>(i)].a;
      out.on_b += s.lambda[static_cast<std::size_t>(i)] * s.v[static_cast<std::size_t>(i)].b;
    }
    return out;
  }
  if (s.n < 4 && !grow_to_tetrahedron(a, b, s)) {
    // Too flat to expand (cannot happen for a solid): touching, along the line of centres.
    const Vec3 apart = b.position - a.position;
    return {.distance = 0.0,
            .normal = apart.squaredNorm() > 0.0 ? Vec3(apart.normalized()) : Vec3(Vec3::UnitY()),
            .on_a = s.v[0].a,
            .on_b = s.v[0].b};
  }
  return expand(a, b, s);
}

}  // namespace tumble::physics
