#include "physics/contact_rows.hpp"

#include <algorithm>
#include <limits>

namespace tumble::physics {
namespace {

// A manifold's points as rows see them, whatever made the manifold: each point's arm from both
// bodies' centres and its anchor in both bodies, with b absent against a static shape.
struct RowPoint {
  Vec3 arm_a, arm_b;         // m, world
  Vec3 anchor_a, anchor_b;   // body frames (m)
  double base;               // PositionPoint::base (m)
  double impulse;            // the accumulated normal impulse it starts from (N s)
  double speculative_speed;  // m/s
};

struct ManifoldInRows {
  std::uint32_t a, b;  // solver bodies; b kStatic against a static shape
  const Vec3& normal;  // unit, world, from b towards a
  const Material& material;
  std::uint32_t count;
  RowPoint points[kMaxManifoldPoints];
  ManifoldRef source;
  const PatchImpulses* friction;  // where keeps_friction, else null
};

// An empty slot: no row (its pushes are zero), a separation far apart, in no patch.
void clear_slot(std::uint32_t a, std::uint32_t b, ContactConstraint& point,
                PositionPoint& position) {
  const Vec3 zero = Vec3::Zero();
  point = ContactConstraint{.a = a,
                            .b = b,
                            .normal = {.linear = zero,
                                       .moment_a = zero,
                                       .turn_a = zero,
                                       .moment_b = zero,
                                       .turn_b = zero,
                                       .mass = 0.0}};
  position = {.a = a, .b = b, .base = std::numeric_limits<double>::infinity()};
}

// Writes the manifold's normal rows, position points and friction patch into `at`.
void write(const ManifoldInRows& m, const RowSlots& at, ContactRows& rows) {
  const SolverBody& body_a = rows.bodies[m.a];
  const SolverBody* body_b = m.b == kStatic ? nullptr : &rows.bodies[m.b];
  Vec3 arms_a[kMaxManifoldPoints], arms_b[kMaxManifoldPoints];
  for (std::uint32_t k = 0; k < at.slots; ++k) {
    ContactConstraint& c = rows.points[at.first + k];
    PositionPoint& position = rows.positions[at.first + k];
    if (k >= m.count) {
      clear_slot(m.a, m.b, c, position);
      continue;
    }
    const RowPoint& point = m.points[k];
    arms_a[k] = point.arm_a;
    arms_b[k] = point.arm_b;
    // The direction into a local first: built in place, it had the whole constraint zeroed
    // before the call (a `rep stos` of 23 words, a fifth of building a constraint).
    const ImpulseDirection along =
        impulse_direction(m.normal, body_a, point.arm_a, body_b, point.arm_b);
    c = {.a = m.a,
         .b = m.b,
         .normal = along,
         .restitution = m.material.restitution,
         .approach_speed = relative_speed(along, body_a, body_b),
         .speculative_speed = point.speculative_speed,
         .normal_impulse = point.impulse};
    position = {.a = m.a,
                .b = m.b,
                .anchor_a = point.anchor_a,
                .anchor_b = point.anchor_b,
                .normal = m.normal,
                .base = point.base};
  }
  const PatchShape shape_a = patch_shape({arms_a, m.count}, m.normal);
  const PatchShape shape_b = body_b ? patch_shape({arms_b, m.count}, m.normal) : PatchShape{};
  Vec3 tangents[2];
  tangent_basis(m.normal, tangents);
  FrictionPatch& patch = rows.patches[at.patch];
  patch = {.a = m.a,
           .b = m.b,
           .tangent = {impulse_direction(tangents[0], body_a, shape_a.centre_arm, body_b,
                                         shape_b.centre_arm),
                       impulse_direction(tangents[1], body_a, shape_a.centre_arm, body_b,
                                         shape_b.centre_arm)},
           .twist = twist_direction(m.normal, body_a, body_b),
           .friction = m.material.friction,
           .twist_arm = shape_a.twist_arm,
           .first = at.first,
           .count = m.count,
           .source = m.source,
           .keeps_friction = m.friction != nullptr};
  if (!m.friction) return;
  for (int k = 0; k < 2; ++k) {
    patch.tangent_impulse[k] = m.friction->tangent.dot(patch.tangent[k].linear);
  }
  patch.twist_impulse = m.friction->twist;
}

ManifoldInRows in_rows(const PlaneManifoldRows& in) {
  ManifoldInRows m{.a = in.body,
                   .b = kStatic,
                   .normal = in.plane.normal,
                   .material = in.material,
                   .count = static_cast<std::uint32_t>(in.manifold.count),
                   .points = {},
                   .source = in.source,
                   .friction = in.keeps_friction ? &in.manifold.friction : nullptr};
  for (std::uint32_t k = 0; k < m.count; ++k) {
    const ContactPoint& point = in.manifold.points[k];
    RowPoint& row = m.points[k];
    row.arm_a = in.rotation * point.body_point;
    row.arm_b = Vec3::Zero();
    row.anchor_a = point.body_point;
    row.anchor_b = Vec3::Zero();
    row.base = -in.plane.offset;
    row.impulse = point.impulses.normal;
    row.speculative_speed = 0.0;
  }
  return m;
}

ManifoldInRows in_rows(const PairManifoldRows& in) {
  const PairManifold& manifold = in.manifold;
  ManifoldInRows m{.a = in.b,
                   .b = in.a,
                   .normal = manifold.normal,
                   .material = in.material,
                   .count = static_cast<std::uint32_t>(manifold.count),
                   .points = {},
                   .source = in.source,
                   .friction = in.keeps_friction ? &manifold.friction : nullptr};
  const Vec3& n = manifold.normal;
  for (std::uint32_t k = 0; k < m.count; ++k) {
    const PairPoint& point = manifold.points[k];
    RowPoint& row = m.points[k];
    row.arm_a = in.b_rotation * point.point_b;
    row.arm_b = in.a_rotation * point.point_a;
    row.anchor_a = point.point_b;
    row.anchor_b = point.point_a;
    // The two anchors were one point at the base poses (to rounding, subtracted here).
    const Vec3 offset =
        world_point(in.b_base, point.point_b) - world_point(in.a_base, point.point_a);
    row.base = point.separation - n.dot(offset);
    row.impulse = point.impulses.normal;
    row.speculative_speed =
        in.speculative_step > 0.0 ? std::max(point.separation, 0.0) / in.speculative_step : 0.0;
  }
  return m;
}

template <class Rows>
void append(const Rows& manifold, ContactRows& rows) {
  write(in_rows(manifold), add_slots(rows, static_cast<std::uint32_t>(manifold.manifold.count)),
        rows);
}

template <class Manifold>
void store(const ContactRows& rows, const FrictionPatch& patch, Manifold& manifold) {
  for (std::uint32_t k = 0; k < patch.count; ++k) {
    manifold.points[k].impulses.normal = rows.points[patch.first + k].normal_impulse;
  }
  if (patch.keeps_friction) manifold.friction = patch_impulses(patch);
}

}  // namespace

RowSlots add_slots(ContactRows& rows, std::uint32_t slots) {
  const RowSlots at{.first = static_cast<std::uint32_t>(rows.points.size()),
                    .slots = slots,
                    .patch = static_cast<std::uint32_t>(rows.patches.size())};
  rows.points.resize(rows.points.size() + slots);
  rows.positions.resize(rows.positions.size() + slots);
  rows.patches.emplace_back();
  return at;
}

void append_rows(const PlaneManifoldRows& manifold, ContactRows& rows) {
  append(manifold, rows);
}
void write_rows(const PlaneManifoldRows& manifold, const RowSlots& at, ContactRows& rows) {
  write(in_rows(manifold), at, rows);
}
void append_rows(const PairManifoldRows& manifold, ContactRows& rows) {
  append(manifold, rows);
}
void write_rows(const PairManifoldRows& manifold, const RowSlots& at, ContactRows& rows) {
  write(in_rows(manifold), at, rows);
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
    c.largest_impulse = carried.largest[k];
    c.approach_speed = std::min(c.approach_speed, carried.approach[k]);
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
