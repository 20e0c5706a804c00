#include "physics/contact_rows.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "physics/patch_friction.hpp"

namespace tumble::physics {
namespace {

// The direction `along` (unit, world) at a point `arm_a` (m, world) from a's centre, and at
// `arm_b` from b's when there is a b (null against a static shape); turning_direction
// (contact_solver.hpp) is the same without the linear part.
// (Computed in locals and stored once: reading back a half-written member stalls on the store.)
ImpulseDirection impulse_direction(const Vec3& along, const SolverBody& a, const Vec3& arm_a,
                                   const SolverBody* b, const Vec3& arm_b) {
  const Vec3 moment_a = arm_a.cross(along);
  const Vec3 turn_a = a.turn(moment_a);
  double inverse = a.inverse_mass + moment_a.dot(turn_a);
  Vec3 moment_b = Vec3::Zero(), turn_b = Vec3::Zero();
  if (b) {
    moment_b = arm_b.cross(along);
    turn_b = b->turn(moment_b);
    inverse += b->inverse_mass + moment_b.dot(turn_b);
  }
  return {.linear = along,
          .moment_a = moment_a,
          .turn_a = turn_a,
          .moment_b = moment_b,
          .turn_b = turn_b,
          .mass = inverse > 0.0 ? 1.0 / inverse : 0.0};
}

// A manifold's point as rows see it, whatever made the manifold: its arm from both bodies'
// centres and its anchor in both bodies (b's zero against a static shape).
struct RowPoint {
  Vec3 arm_a, arm_b;         // m, world
  Vec3 anchor_a, anchor_b;   // body frames (m)
  double base;               // PositionPoint::base (m)
  double impulse;            // the accumulated normal impulse it starts from (N s)
  double speculative_speed;  // m/s
};

// The rows' view of a plane manifold: body a against the static plane.
struct PlaneView {
  const PlaneManifoldRows& in;
  std::uint32_t a() const { return in.body; }
  static std::uint32_t b() { return kStatic; }
  const Vec3& normal() const { return in.plane.normal; }
  RowPoint point(std::uint32_t k) const {
    const ContactPoint& point = in.manifold.points[k];
    if (in.rounding > 0.0) {
      // The point is the core's (a sphere's centre, a capsule's end): it touches the radius below.
      return {.arm_a = in.rotation * point.body_point - in.rounding * in.plane.normal,
              .arm_b = Vec3::Zero(),
              .anchor_a = point.body_point,
              .anchor_b = Vec3::Zero(),
              .base = -in.plane.offset - in.rounding,
              .impulse = point.impulses.normal,
              .speculative_speed = 0.0};
    }
    return {.arm_a = in.rotation * point.body_point,
            .arm_b = Vec3::Zero(),
            .anchor_a = point.body_point,
            .anchor_b = Vec3::Zero(),
            .base = -in.plane.offset,
            .impulse = point.impulses.normal,
            .speculative_speed = 0.0};
  }
};

// The rows' view of a pair manifold: B is pushed along the normal (from A to B), so B is the
// rows' a. Against a static body (its index kStatic) the moving one is the rows' a, pushed away
// from the static one (along −normal when B is static), and the static one's anchor, which never
// moves, is folded into the base: s = base + n·(a's point) − n·(b's point) holds either way.
struct PairView {
  const PairManifoldRows& in;
  bool b_static;  // the rows' a is A
  Vec3 n;         // along which the rows' a is pushed

  explicit PairView(const PairManifoldRows& rows)
      : in(rows),
        b_static(rows.b == kStatic),
        n(rows.b == kStatic ? Vec3(-rows.manifold.normal) : rows.manifold.normal) {}
  std::uint32_t a() const { return b_static ? in.a : in.b; }
  std::uint32_t b() const { return b_static ? kStatic : in.a; }
  const Vec3& normal() const { return n; }
  RowPoint point(std::uint32_t k) const {
    const PairPoint& point = in.manifold.points[k];
    const Vec3& normal = in.manifold.normal;
    const Side a = side(in.a_base, in.a_rotation, point.point_a, in.a_shape, point.separation,
                        normal, (point.on_axis & 1) != 0);
    const Side b = side(in.b_base, in.b_rotation, point.point_b, in.b_shape, point.separation,
                        -normal, (point.on_axis & 2) != 0);
    const double speculative_speed =
        in.speculative_step > 0.0 ? std::max(point.separation, 0.0) / in.speculative_step : 0.0;
    if (b_static) {
      return {.arm_a = a.arm,
              .arm_b = Vec3::Zero(),
              .anchor_a = a.anchor,
              .anchor_b = Vec3::Zero(),
              .base = point.separation - n.dot(a.measured),
              .impulse = point.impulses.normal,
              .speculative_speed = speculative_speed};
    }
    const bool a_static = in.a == kStatic;
    // The two anchors were one point at the base poses (to rounding, subtracted here).
    return {.arm_a = b.arm,
            .arm_b = a_static ? Vec3::Zero() : a.arm,
            .anchor_a = b.anchor,
            .anchor_b = a_static ? Vec3::Zero() : a.anchor,
            .base = point.separation - n.dot(b.measured - a.measured) -
                    (a_static ? n.dot(a.measured) : 0.0),
            .impulse = point.impulses.normal,
            .speculative_speed = speculative_speed};
  }

 private:
  // One body's part of a point: its arm (world) for the rows, its anchor (body frame) for the
  // projection, and that anchor's world position at the base pose. A round body's anchor is the
  // point of its core under the contact and its arm the one the manifold gave, whichever way it
  // has turned since. The contact `point` stands the radius and half the `separation` off the core
  // along the body's `outward` normal (world).
  struct Side {
    Vec3 arm, anchor, measured;
  };
  static Side side(const PoseRef& base, const Mat3& rotation, const Vec3& point, const Shape& shape,
                   double separation, const Vec3& outward, bool on_axis) {
    switch (shape.kind) {
      case ShapeKind::cylinder:
        if (on_axis) {
          // On its side: anchored on the axis under the contact, as a capsule's point.
          const Vec3 over =
              (shape.radius + 0.5 * separation) * (base.rotation.transpose() * outward);
          const Vec3 core(
              0.0, std::clamp((point - over).y(), -shape.half_length, shape.half_length), 0.0);
          return {
              .arm = base.rotation * point, .anchor = core, .measured = world_point(base, core)};
        }
        [[fallthrough]];
      case ShapeKind::box:
      case ShapeKind::hull:
        return {.arm = rotation * point, .anchor = point, .measured = world_point(base, point)};
      case ShapeKind::sphere:
        return {.arm = base.rotation * point, .anchor = Vec3::Zero(), .measured = base.position};
      case ShapeKind::capsule: {
        const Vec3 over = (shape.radius + 0.5 * separation) * (base.rotation.transpose() * outward);
        const Vec3 core = nearest_core_point(shape, point - over);
        return {.arm = base.rotation * point, .anchor = core, .measured = world_point(base, core)};
      }
    }
    return {};
  }
};

// `value` into list[i], which is either in the list or just past its end (appended).
template <class T>
[[gnu::always_inline]] inline void put(std::vector<T>& list, std::uint32_t i, const T& value) {
  if (i == list.size()) {
    list.push_back(value);
  } else {
    list[i] = value;
  }
}

// An empty slot: no row (its pushes are zero), a separation far apart, in no patch.
void clear_slot(std::uint32_t a, std::uint32_t b, std::uint32_t i, ContactRows& rows) {
  const Vec3 zero = Vec3::Zero();
  put(rows.points, i,
      ContactConstraint{.a = a,
                        .b = b,
                        .normal = {.linear = zero,
                                   .moment_a = zero,
                                   .turn_a = zero,
                                   .moment_b = zero,
                                   .turn_b = zero,
                                   .mass = 0.0}});
  put(rows.positions, i,
      PositionPoint{.a = a, .b = b, .base = std::numeric_limits<double>::infinity()});
}

// A patch whose points keep their features and their spread about their centre within this
// fraction keeps its twist arm: rigid motion keeps the spread to round-off (a resting box, a
// settled pile), while a patch that changes (a box sliding off another) has its arm anew, the
// remembered one at most 0.05 % off (the arm scales as the spread's square root).
constexpr double kSpreadKept = 1e-3;

// The patch shape of the manifold's points (their arms about their centre, from body A): the
// manifold's memo when it still holds, else the twist arm computed anew.
template <class ManifoldType>
PatchMemo remembered(const ManifoldType& manifold, std::span<const Vec3> arms, const Vec3& centre,
                     const Vec3& normal) {
  // The features in increasing order (a manifold lists its points deepest first, an order that
  // round-off can change); each takes at most 14 bits, so four, shifted past the count, fit.
  std::array<std::uint64_t, kMaxManifoldPoints> features{};
  double spread = 0.0;  // m²
  for (std::size_t k = 0; k < arms.size(); ++k) {
    features[k] = static_cast<std::uint64_t>(manifold.points[k].feature) + 1;
    spread += (arms[k] - centre).squaredNorm();
  }
  std::sort(features.begin(), features.begin() + static_cast<std::ptrdiff_t>(arms.size()));
  std::uint64_t points = arms.size();
  for (std::size_t k = 0; k < arms.size(); ++k) points |= features[k] << (4 + 15 * k);
  const PatchMemo& before = manifold.patch;
  if (before.points == points && std::abs(spread - before.spread) <= kSpreadKept * before.spread) {
    return before;
  }
  return {.points = points, .spread = spread, .twist_arm = patch_twist_arm(arms, normal, centre)};
}

// Writes the manifold's normal rows, position points and friction patch into `at`.
template <class View>
void write(const View& view, const RowSlots& at, ContactRows& rows) {
  const auto& in = view.in;
  const std::uint32_t a = view.a(), b = view.b();
  const Vec3& normal = view.normal();
  const auto count = static_cast<std::uint32_t>(in.manifold.count);
  const SolverBody& body_a = rows.bodies[a];
  const SolverBody* body_b = b == kStatic ? nullptr : &rows.bodies[b];
  Vec3 arms_a[kMaxManifoldPoints], arms_b[kMaxManifoldPoints];
  for (std::uint32_t k = 0; k < at.slots; ++k) {
    if (k >= count) {
      clear_slot(a, b, at.first + k, rows);
      continue;
    }
    const RowPoint point = view.point(k);
    arms_a[k] = point.arm_a;
    arms_b[k] = point.arm_b;
    // The direction into a local first: built in place, it had the whole constraint zeroed
    // before the call (a `rep stos` of 23 words, a fifth of building a constraint).
    const ImpulseDirection along =
        impulse_direction(normal, body_a, point.arm_a, body_b, point.arm_b);
    put(rows.points, at.first + k,
        ContactConstraint{.a = a,
                          .b = b,
                          .normal = along,
                          .restitution = in.material.restitution,
                          .approach_speed = relative_speed(along, body_a, body_b),
                          .speculative_speed = point.speculative_speed,
                          .normal_impulse = point.impulse});
    put(rows.positions, at.first + k,
        PositionPoint{.a = a,
                      .b = b,
                      .anchor_a = point.anchor_a,
                      .anchor_b = point.anchor_b,
                      .normal = normal,
                      .base = point.base});
  }
  // The twist arm once, from a's arms: the patch has one shape, whichever body it is seen from.
  const Vec3 centre_a = mean_arm({arms_a, count});
  const PatchMemo shape = remembered(in.manifold, {arms_a, count}, centre_a, normal);
  const Vec3 centre_b = body_b ? mean_arm({arms_b, count}) : Vec3::Zero();
  Vec3 tangents[2];
  tangent_basis(normal, tangents);
  FrictionPatch patch{
      .a = a,
      .b = b,
      .tangent = {impulse_direction(tangents[0], body_a, centre_a, body_b, centre_b),
                  impulse_direction(tangents[1], body_a, centre_a, body_b, centre_b)},
      .twist = turning_direction(normal, body_a, body_b),
      .friction = in.material.friction,
      .shape = shape,
      .first = at.first,
      .count = count,
      .rolling_arm = in.material.rolling_resistance,
      .source = in.source,
      .keeps_friction = in.keeps_friction};
  if (in.keeps_friction) {
    const PatchImpulses& friction = in.manifold.friction;
    for (int k = 0; k < 2; ++k) {
      patch.tangent_impulse[k] = friction.tangent.dot(patch.tangent[k].linear);
    }
    patch.twist_impulse = friction.twist;
  }
  put(rows.patches, at.patch, patch);
}

// The slots of a manifold appended to the rows.
RowSlots appended(std::uint32_t count, const ContactRows& rows) {
  return {.first = static_cast<std::uint32_t>(rows.points.size()),
          .slots = count,
          .patch = static_cast<std::uint32_t>(rows.patches.size())};
}

template <class Manifold>
void store(const ContactRows& rows, const FrictionPatch& patch, Manifold& manifold) {
  for (std::uint32_t k = 0; k < patch.count; ++k) {
    manifold.points[k].impulses.normal = rows.points[patch.first + k].normal_impulse;
  }
  if (patch.keeps_friction) manifold.friction = patch_impulses(patch);
  manifold.patch = patch.shape;
}

}  // namespace

RowSlots add_slots(ContactRows& rows, std::uint32_t slots) {
  const RowSlots at = appended(slots, rows);
  rows.points.resize(rows.points.size() + slots);
  rows.positions.resize(rows.positions.size() + slots);
  rows.patches.emplace_back();
  return at;
}

void append_rows(const PlaneManifoldRows& manifold, ContactRows& rows) {
  write(PlaneView{manifold}, appended(static_cast<std::uint32_t>(manifold.manifold.count), rows),
        rows);
}
void write_rows(const PlaneManifoldRows& manifold, const RowSlots& at, ContactRows& rows) {
  write(PlaneView{manifold}, at, rows);
}
void append_rows(const PairManifoldRows& manifold, ContactRows& rows) {
  write(PairView(manifold), appended(static_cast<std::uint32_t>(manifold.manifold.count), rows),
        rows);
}
void write_rows(const PairManifoldRows& manifold, const RowSlots& at, ContactRows& rows) {
  write(PairView(manifold), at, rows);
}

PatchImpulses patch_impulses(const FrictionPatch& patch) {
  return {.tangent = patch.tangent_impulse[0] * patch.tangent[0].linear +
                     patch.tangent_impulse[1] * patch.tangent[1].linear,
          .twist = patch.twist_impulse};
}

void restore(const CarriedImpulses& carried, const RowSlots& at, ContactRows& rows) {
  FrictionPatch& patch = rows.patches[at.patch];
  for (std::uint32_t k = 0; k < patch.count; ++k) {
    ContactConstraint& c = rows.points[at.first + k];
    c.normal_impulse = carried.impulse[k];
  }
  for (int k = 0; k < 2; ++k) {
    patch.tangent_impulse[k] = carried.friction.tangent.dot(patch.tangent[k].linear);
  }
  patch.twist_impulse = carried.friction.twist;
}

void store_impulses(const ContactRows& rows, std::span<std::vector<Manifold>> plane_manifolds,
                    std::span<PairContact> pairs) {
  for (const FrictionPatch& patch : rows.patches) {
    const ManifoldRef& source = patch.source;
    if (source.plane == kPairManifold) {
      store(rows, patch, pairs[source.owner].manifold);
    } else {
      store(rows, patch, plane_manifolds[source.owner][source.plane]);
    }
  }
}

}  // namespace tumble::physics
