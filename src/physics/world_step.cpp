#include "physics/world_step.hpp"

#include <algorithm>
#include <limits>

namespace tumble::physics {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// How far a box can move towards anything in a step of h (s): its centre's travel (the free
// step's, or its speed times h, whichever is more: an impact with a plane within the step can
// bring the end back near the start) plus its corners' swing (its fastest turn times its half
// diagonal).
double reach(const BodyState& start, const BodyState& end, const Vec3& half_size, double h) {
  const double travel = std::max((end.position() - start.position()).norm(),
                                 h * std::max(start.velocity().norm(), end.velocity().norm()));
  const double swing = h *
                       std::max(start.angular_velocity().norm(), end.angular_velocity().norm()) *
                       half_size.norm();
  return travel + swing;
}

// World position of a body point (body frame, m).
Vec3 world_point(const BodyState& state, const Mat3& rotation, const Vec3& body_point) {
  return state.position() + rotation * body_point;
}

BoxPose pose_of(const BodyState& state, const Mat3& rotation, const Vec3& half_size) {
  return {.position = state.position(), .rotation = rotation, .half_size = half_size};
}

std::uint32_t find_root(std::vector<std::uint32_t>& root, std::uint32_t i) {
  while (root[i] != i) {
    root[i] = root[root[i]];  // path halving
    i = root[i];
  }
  return i;
}

// The free steps, each with its impacts on planes.
void advance_bodies(Integrator integrator, std::span<const BodyModel> models,
                    std::span<const BodyState> in, double t, double dt,
                    const std::vector<Plane>& planes, const ContactSettings& settings,
                    WorldContacts& contacts) {
  contacts.advances.resize(in.size());
  contacts.planes.resize(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (contacts.asleep[i]) {
      // Unmoved, and still in its island: its manifolds keep the impulses it fell asleep with.
      contacts.advances[i] = {
          .end = in[i], .rotation = in[i].rotation(), .remaining = dt, .touching = true};
    } else if (planes.empty()) {
      contacts.advances[i] = {.end = step(integrator, models[i], in[i], t, dt), .remaining = dt};
    } else {
      contacts.advances[i] = advance_among_planes(integrator, models[i], in[i], t, dt, planes,
                                                  settings, contacts.planes[i]);
    }
  }
}

// Notes in pair.stamp where its bodies stand as its manifold is found with `margin` (m).
void stamp(const BodyState& a, const Mat3& a_rotation, const BodyState& b, double margin,
           PairContact& pair) {
  PairStamp& out = pair.stamp;
  out.valid = true;
  out.offset = a_rotation.transpose() * (b.position() - a.position());
  out.turn = a.orientation().conjugate() * b.orientation();
  out.normal = a_rotation.transpose() * pair.manifold.normal;
  out.margin = margin;
  for (int k = 0; k < pair.manifold.count; ++k) {
    out.separation[static_cast<std::size_t>(k)] =
        pair.manifold.points[static_cast<std::size_t>(k)].separation;
  }
}

// Whether the pair `before` keeps its manifold at the bodies' poses now, needing `margin` (m);
// if so, `pair` gets it, with its normal turned with A and its separations measured now.
bool reuse(const PairContact& before, const BodyState& a, const Mat3& a_rotation,
           const BodyState& b, const Mat3& b_rotation, const Vec3& b_half_size, double margin,
           PairContact& pair) {
  const PairStamp& then = before.stamp;
  if (!then.valid) return false;
  const Vec3 moved = a_rotation.transpose() * (b.position() - a.position()) - then.offset;
  const Quat turned = then.turn.conjugate() * (a.orientation().conjugate() * b.orientation());
  const double angle = 2.0 * std::asin(std::min(1.0, turned.vec().norm()));  // rad
  const double distance = moved.norm() + angle * b_half_size.norm();
  if (!(distance + margin <= then.margin && distance < kReuseDistance)) return false;
  pair.manifold = before.manifold;
  pair.stamp = then;
  const Vec3 n = a_rotation * then.normal;
  pair.manifold.normal = n;
  for (int k = 0; k < pair.manifold.count; ++k) {
    PairPoint& point = pair.manifold.points[static_cast<std::size_t>(k)];
    // The two anchors were one point when the manifold was found.
    const Vec3 apart =
        world_point(b, b_rotation, point.point_b) - world_point(a, a_rotation, point.point_a);
    point.separation = then.separation[static_cast<std::size_t>(k)] + n.dot(apart);
  }
  return true;
}

// Into contacts.found: the touching pairs of colliding bodies, with their manifolds at the start
// of the step and the last step's impulses of the same features.
void find_pairs(std::span<const BodyModel> models, std::span<const BodyState> in,
                WorldContacts& contacts) {
  contacts.found.clear();
  contacts.colliders.clear();
  for (std::uint32_t i = 0; i < in.size(); ++i) {
    if (models[i].collides) contacts.colliders.push_back(i);
  }
  if (contacts.colliders.size() < 2) return;
  contacts.start_rotations.resize(in.size());
  contacts.bounds.clear();
  for (const std::uint32_t i : contacts.colliders) {
    contacts.start_rotations[i] = in[i].rotation();
    const PlaneAdvance& advance = contacts.advances[i];
    const Mat3 end_rotation = advance.touching ? advance.rotation : advance.end.rotation();
    contacts.bounds.push_back(merged(
        box_bounds(in[i].position(), contacts.start_rotations[i], models[i].half_size,
                   kTouchingDistance),
        box_bounds(advance.end.position(), end_rotation, models[i].half_size, kTouchingDistance)));
  }
  overlapping_pairs(contacts.bounds, contacts.order, contacts.candidates);
  std::size_t previous = 0;  // contacts.pairs is sorted as the candidates are: merge, not search
  for (const BodyPair& candidate : contacts.candidates) {
    const std::uint32_t a = contacts.colliders[candidate.first];
    const std::uint32_t b = contacts.colliders[candidate.second];
    const BodyPair bodies{a, b};
    while (previous < contacts.pairs.size() && contacts.pairs[previous].bodies < bodies) {
      ++previous;
    }
    const PairContact* before =
        previous < contacts.pairs.size() && contacts.pairs[previous].bodies == bodies
            ? &contacts.pairs[previous]
            : nullptr;
    // Speculative points as far as the two can close on each other in the step.
    const double margin = kTouchingDistance + contacts.reaches[a] + contacts.reaches[b];
    PairContact pair;
    pair.bodies = bodies;
    if (before && reuse(*before, in[a], contacts.start_rotations[a], in[b],
                        contacts.start_rotations[b], models[b].half_size, margin, pair)) {
      contacts.found.push_back(pair);
      continue;
    }
    pair.manifold = box_box_manifold(
        pose_of(in[a], contacts.start_rotations[a], models[a].half_size),
        pose_of(in[b], contacts.start_rotations[b], models[b].half_size), margin + kReuseDistance);
    if (pair.manifold.count == 0) continue;
    stamp(in[a], contacts.start_rotations[a], in[b], margin + kReuseDistance, pair);
    if (before) {
      pair.manifold.friction = before->manifold.friction;
      for (int k = 0; k < pair.manifold.count; ++k) {
        PairPoint& now = pair.manifold.points[static_cast<std::size_t>(k)];
        for (int j = 0; j < before->manifold.count; ++j) {
          const PairPoint& then = before->manifold.points[static_cast<std::size_t>(j)];
          if (then.feature == now.feature) now.impulses = then.impulses;
        }
      }
    }
    contacts.found.push_back(pair);
  }
}

// Into contacts.island_of: each body's island (kNone for a body touching nothing), numbered in
// the order of their lowest bodies, so the solve's order depends on body order alone.
int group_islands(std::size_t body_count, WorldContacts& contacts) {
  contacts.root.resize(body_count);
  for (std::uint32_t i = 0; i < body_count; ++i) contacts.root[i] = i;
  for (const PairContact& pair : contacts.found) {
    const std::uint32_t a = find_root(contacts.root, pair.bodies.first);
    const std::uint32_t b = find_root(contacts.root, pair.bodies.second);
    if (a != b) contacts.root[std::max(a, b)] = std::min(a, b);
  }
  contacts.island_of.assign(body_count, kNone);
  std::vector<std::uint32_t>& number_of_root = contacts.local;  // reused as scratch here
  number_of_root.assign(body_count, kNone);
  int islands = 0;
  std::vector<char>& paired = contacts.paired;
  paired.assign(body_count, 0);
  for (const PairContact& pair : contacts.found) {
    paired[pair.bodies.first] = paired[pair.bodies.second] = 1;
  }
  for (std::uint32_t i = 0; i < body_count; ++i) {
    if (!contacts.advances[i].touching && !paired[i]) continue;
    const std::uint32_t r = find_root(contacts.root, i);
    if (number_of_root[r] == kNone) number_of_root[r] = static_cast<std::uint32_t>(islands++);
    contacts.island_of[i] = number_of_root[r];
  }
  // Bodies and pairs by island, each in its own order (a counting sort, which is stable).
  std::vector<std::uint32_t>& next = contacts.next_slot;
  const auto bucket = [islands, &next](std::size_t count, auto island_of_item,
                                       std::vector<std::uint32_t>& offsets,
                                       std::vector<std::uint32_t>& items) {
    offsets.assign(static_cast<std::size_t>(islands) + 1, 0);
    for (std::uint32_t k = 0; k < count; ++k) {
      if (const std::uint32_t i = island_of_item(k); i != kNone) ++offsets[i + 1];
    }
    for (int i = 0; i < islands; ++i) offsets[i + 1] += offsets[i];
    items.resize(offsets.back());
    next.assign(offsets.begin(), offsets.end() - 1);
    for (std::uint32_t k = 0; k < count; ++k) {
      if (const std::uint32_t i = island_of_item(k); i != kNone) items[next[i]++] = k;
    }
  };
  bucket(
      body_count, [&](std::uint32_t k) { return contacts.island_of[k]; }, contacts.member_offsets,
      contacts.members);
  bucket(
      contacts.found.size(),
      [&](std::uint32_t k) { return contacts.island_of[contacts.found[k].bodies.first]; },
      contacts.pair_offsets, contacts.pair_order);
  return islands;
}

// A pair whose two bodies can close on each other by more than this in a step (m) has its
// manifold found again before each sub-step: points fixed in the bodies at the start of the step
// stand for the contact only while the bodies stay near where they were (a box falling at 4 m/s
// past another's edge meets its face, which the edge's point knew nothing of: the pile of `tumble
// bench contact` sank 30 cm so while pouring). Box2D's speculative distance is 2 cm.
constexpr double kRefindReach = 0.02;

// An empty point slot: no row (its pushes are zero), a separation far apart, in no patch.
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

// Writes the pair's points (its rows' slots) and patch from its manifold, with the bodies at
// (a_position, a_rotation) and (b_position, b_rotation): the rows' arms, and the positions' base,
// so that each point's separation is the manifold's at these poses.
void write_pair_rows(const PairRows& rows, std::span<const BodyModel> models,
                     const Mat3& a_rotation, const Mat3& b_rotation, const BodyState& a_state,
                     const BodyState& b_state, WorldContacts& contacts) {
  PairContact& pair = contacts.found[rows.pair];
  const auto [a, b] = pair.bodies;
  // The solver pushes its first body along the normal, which points from A to B: B first.
  const std::uint32_t first = contacts.local[b], second = contacts.local[a];
  const Vec3& n = pair.manifold.normal;
  const Material material = combine(models[a].material, models[b].material);
  Vec3 arms_b[kMaxManifoldPoints], arms_a[kMaxManifoldPoints];
  const auto count = static_cast<std::uint32_t>(pair.manifold.count);
  for (std::uint32_t k = 0; k < rows.slots; ++k) {
    ContactConstraint& c = contacts.points[rows.first + k];
    PositionPoint& position = contacts.positions[rows.first + k];
    if (k >= count) {
      clear_slot(first, second, c, position);
      continue;
    }
    PairPoint& point = pair.manifold.points[k];
    arms_b[k] = b_rotation * point.point_b;
    arms_a[k] = a_rotation * point.point_a;
    c = make_constraint(first, contacts.solver[first], arms_b[k], second, contacts.solver[second],
                        arms_a[k], n, material);
    c.source = &point.impulses;
    // The separation is the manifold's plus the anchors' relative motion along n: the two anchors
    // were one point here (to rounding, subtracted here).
    const Vec3 offset = (b_state.position() + arms_b[k]) - (a_state.position() + arms_a[k]);
    position = {.a = first,
                .b = second,
                .anchor_a = point.point_b,
                .anchor_b = point.point_a,
                .normal = n,
                .base = point.separation - n.dot(offset)};
  }
  const PatchShape shape_b = patch_shape({arms_b, count}, n);
  const PatchShape shape_a = patch_shape({arms_a, count}, n);
  contacts.patches[rows.patch] = make_patch(
      first, contacts.solver[first], shape_b.centre_arm, second, &contacts.solver[second],
      shape_a.centre_arm, n, material.friction, shape_b.twist_arm, rows.first, count);
  contacts.patches[rows.patch].source = &pair.manifold.friction;
}

// Finds a fast pair's manifold again at the bodies' poses now, within the part `left` of the
// step still to come, and rewrites its rows, keeping the sub-step impulses of the features it
// still has (and of its friction, turned to the new tangents).
void refind_pair(const PairRows& rows, std::span<const BodyModel> models, double left,
                 WorldContacts& contacts) {
  PairContact& pair = contacts.found[rows.pair];
  const auto [a, b] = pair.bodies;
  const BodyState& a_state = contacts.substep_bodies[contacts.local[a]].state;
  const BodyState& b_state = contacts.substep_bodies[contacts.local[b]].state;
  const Mat3 a_rotation = a_state.rotation(), b_rotation = b_state.rotation();
  PairManifold found = box_box_manifold(pose_of(a_state, a_rotation, models[a].half_size),
                                        pose_of(b_state, b_rotation, models[b].half_size),
                                        kTouchingDistance + left * rows.reach);
  // A point found again keeps its impulse, and what the bounce needs: the speed it approached at
  // before it pushed, and whether it pushed. A new one takes the pair's fastest approach and its
  // largest push: the features found after an impact differ from the speculative ones before it.
  double pair_approach = 0.0, pair_largest = 0.0;
  for (int j = 0; j < pair.manifold.count; ++j) {
    const ContactConstraint& c = contacts.points[rows.first + static_cast<std::uint32_t>(j)];
    pair_approach = std::min(pair_approach, c.approach_speed);
    pair_largest = std::max(pair_largest, c.largest_impulse);
  }
  double impulse[kMaxManifoldPoints] = {}, largest[kMaxManifoldPoints],
         approach[kMaxManifoldPoints];
  std::fill(std::begin(largest), std::end(largest), pair_largest);
  std::fill(std::begin(approach), std::end(approach), pair_approach);
  for (int k = 0; k < found.count; ++k) {
    PairPoint& now = found.points[static_cast<std::size_t>(k)];
    for (int j = 0; j < pair.manifold.count; ++j) {
      if (pair.manifold.points[static_cast<std::size_t>(j)].feature != now.feature) continue;
      now.impulses = pair.manifold.points[static_cast<std::size_t>(j)].impulses;
      impulse[k] = contacts.points[rows.first + static_cast<std::uint32_t>(j)].normal_impulse;
      largest[k] = contacts.points[rows.first + static_cast<std::uint32_t>(j)].largest_impulse;
      approach[k] = contacts.points[rows.first + static_cast<std::uint32_t>(j)].approach_speed;
    }
  }
  const FrictionPatch& before = contacts.patches[rows.patch];
  const Vec3 tangent_impulse = before.tangent_impulse[0] * before.tangent[0].linear +
                               before.tangent_impulse[1] * before.tangent[1].linear;
  const double twist_impulse = before.twist_impulse;
  found.friction = pair.manifold.friction;
  pair.manifold = found;
  pair.stamp.valid = false;  // found at a sub-step's poses: not the start's
  write_pair_rows(rows, models, a_rotation, b_rotation, a_state, b_state, contacts);
  for (std::uint32_t k = 0; k < rows.slots; ++k) {
    contacts.points[rows.first + k].normal_impulse = impulse[k];
    contacts.points[rows.first + k].largest_impulse = largest[k];
    double& speed = contacts.points[rows.first + k].approach_speed;
    speed = std::min(speed, approach[k]);
  }
  FrictionPatch& patch = contacts.patches[rows.patch];
  for (int k = 0; k < 2; ++k)
    patch.tangent_impulse[k] = tangent_impulse.dot(patch.tangent[k].linear);
  patch.twist_impulse = twist_impulse;
}

// Writes the body's slots against one plane from its corners within `margin` (m) of it at
// (state, rotation): the rows, positions and patch, pointing at the body's manifold for that
// plane, which becomes the one found here. A corner found before keeps its impulses (of the last
// step, and its sub-step impulse, approach speed and largest push), and the patch its friction.
void write_plane_rows(const PlaneRows& rows, const BodyModel& model, const BodyState& state,
                      const Mat3& rotation, double margin, const std::vector<Plane>& planes,
                      WorldContacts& contacts) {
  const Plane& plane = planes[rows.plane];
  const std::uint32_t local = contacts.local[rows.body];
  Manifold& manifold = contacts.planes[rows.body].manifolds[rows.plane];
  Manifold found =
      box_plane_manifold(corner_separations(rotation, state.position(), model.half_size, plane),
                         model.half_size, margin);
  found.friction = manifold.friction;
  const Material material = combine(model.material, plane.material);
  double impulse[kMaxManifoldPoints] = {}, largest[kMaxManifoldPoints] = {},
         approach[kMaxManifoldPoints] = {};
  for (int k = 0; k < found.count; ++k) {
    ContactPoint& now = found.points[static_cast<std::size_t>(k)];
    for (int j = 0; j < manifold.count; ++j) {
      if (manifold.points[static_cast<std::size_t>(j)].feature != now.feature) continue;
      now.impulses = manifold.points[static_cast<std::size_t>(j)].impulses;
      const ContactConstraint& then = contacts.points[rows.first + static_cast<std::uint32_t>(j)];
      impulse[k] = then.normal_impulse;
      largest[k] = then.largest_impulse;
      approach[k] = then.approach_speed;
    }
  }
  const FrictionPatch& before = contacts.patches[rows.patch];
  const bool had_patch = before.count > 0;
  const Vec3 tangent_impulse = had_patch
                                   ? Vec3(before.tangent_impulse[0] * before.tangent[0].linear +
                                          before.tangent_impulse[1] * before.tangent[1].linear)
                                   : Vec3::Zero();
  const double twist_impulse = had_patch ? before.twist_impulse : 0.0;
  manifold = found;
  Vec3 arms[kMaxManifoldPoints];
  const SolverBody& solver = contacts.solver[local];
  for (std::uint32_t k = 0; k < kMaxManifoldPoints; ++k) {
    ContactConstraint& c = contacts.points[rows.first + k];
    PositionPoint& position = contacts.positions[rows.first + k];
    if (k >= static_cast<std::uint32_t>(found.count)) {
      clear_slot(local, kStatic, c, position);
      continue;
    }
    ContactPoint& point = manifold.points[k];
    arms[k] = rotation * point.body_point;
    c = make_constraint(local, solver, arms[k], plane.normal, material);
    c.source = &point.impulses;
    c.normal_impulse = impulse[k];
    c.largest_impulse = largest[k];
    c.approach_speed = std::min(c.approach_speed, approach[k]);
    position = {
        .a = local, .anchor_a = point.body_point, .normal = plane.normal, .base = -plane.offset};
  }
  const auto count = static_cast<std::uint32_t>(found.count);
  const PatchShape shape = patch_shape({arms, count}, plane.normal);
  FrictionPatch& patch = contacts.patches[rows.patch];
  patch = make_patch(local, solver, shape.centre_arm, kStatic, nullptr, Vec3::Zero(), plane.normal,
                     material.friction, shape.twist_arm, rows.first, count);
  patch.source = &manifold.friction;
  for (int k = 0; k < 2; ++k)
    patch.tangent_impulse[k] = tangent_impulse.dot(patch.tangent[k].linear);
  patch.twist_impulse = twist_impulse;
}

// The members of an island.
std::span<const std::uint32_t> members_of(std::uint32_t island, const WorldContacts& contacts) {
  return {contacts.members.data() + contacts.member_offsets[island],
          contacts.member_offsets[island + 1] - contacts.member_offsets[island]};
}

// The island's bodies, with the lists its solve fills emptied.
std::span<const std::uint32_t> start_island(std::uint32_t island, WorldContacts& contacts) {
  contacts.solver.clear();
  contacts.points.clear();
  contacts.patches.clear();
  contacts.positions.clear();
  contacts.local.resize(contacts.island_of.size());
  return members_of(island, contacts);
}

// A small island (a tower, a pyramid, a few boxes knocking): every body's free step, then one
// solve over all its points to convergence within its pass budget, the poses moved by the
// impulses, and a projection (physics/contact_island.hpp).
void solve_converged(Integrator integrator, std::span<const BodyModel> models,
                     std::span<const BodyState> in, double dt, std::uint32_t island,
                     const std::vector<Plane>& planes, const ContactSettings& settings,
                     WorldContacts& contacts, std::span<BodyState> out) {
  const std::span<const std::uint32_t> members = start_island(island, contacts);
  contacts.island_bodies.clear();
  for (const std::uint32_t i : members) {
    const PlaneAdvance& advance = contacts.advances[i];
    const Mat3 rotation = advance.touching ? advance.rotation : advance.end.rotation();
    contacts.local[i] = static_cast<std::uint32_t>(contacts.island_bodies.size());
    contacts.island_bodies.push_back(
        {.model = &models[i],
         .end = advance.end,
         .rotation = rotation,
         .weight = impulse_position_weight(integrator, advance.remaining)});
    contacts.solver.push_back(SolverBody::from(advance.end, models[i].constants, rotation));
  }
  for (const std::uint32_t i : members) {
    if (!contacts.advances[i].touching) continue;
    const std::uint32_t local = contacts.local[i];
    add_plane_points(models[i], local, contacts.island_bodies[local].rotation,
                     contacts.solver[local], planes, contacts.planes[i], contacts.points,
                     contacts.patches, contacts.positions);
  }
  for (std::uint32_t k = contacts.pair_offsets[island]; k < contacts.pair_offsets[island + 1];
       ++k) {
    PairContact& pair = contacts.found[contacts.pair_order[k]];
    const auto [a, b] = pair.bodies;
    // The solver pushes its first body along the normal, which points from A to B: B first.
    const std::uint32_t first = contacts.local[b], second = contacts.local[a];
    const IslandBody& body_b = contacts.island_bodies[first];
    const IslandBody& body_a = contacts.island_bodies[second];
    // Friction between bodies is not warm-started here (contact_solver.hpp says why): nothing
    // stale is left for a sub-stepped solve to start from.
    pair.manifold.friction = {};
    const Vec3& n = pair.manifold.normal;
    const Material material = combine(models[a].material, models[b].material);
    const Mat3& a_start = contacts.start_rotations[a];
    const Mat3& b_start = contacts.start_rotations[b];
    const auto first_point = static_cast<std::uint32_t>(contacts.points.size());
    Vec3 arms_b[kMaxManifoldPoints], arms_a[kMaxManifoldPoints];
    for (int k = 0; k < pair.manifold.count; ++k) {
      PairPoint& point = pair.manifold.points[static_cast<std::size_t>(k)];
      arms_b[k] = body_b.rotation * point.point_b;
      arms_a[k] = body_a.rotation * point.point_a;
      contacts.points.push_back(make_constraint(first, contacts.solver[first], arms_b[k], second,
                                                contacts.solver[second], arms_a[k], n, material));
      contacts.points.back().source = &point.impulses;
      contacts.points.back().speculative_speed = std::max(point.separation, 0.0) / dt;
      // The projection's separation is the start's plus the anchors' relative motion along n:
      // the two anchors were one point at the start (to rounding, subtracted here).
      const Vec3 start_offset =
          world_point(in[b], b_start, point.point_b) - world_point(in[a], a_start, point.point_a);
      contacts.positions.push_back({.a = first,
                                    .b = second,
                                    .anchor_a = point.point_b,
                                    .anchor_b = point.point_a,
                                    .normal = n,
                                    .base = point.separation - n.dot(start_offset)});
    }
    const auto count = static_cast<std::size_t>(pair.manifold.count);
    const PatchShape shape_b = patch_shape({arms_b, count}, n);
    const PatchShape shape_a = patch_shape({arms_a, count}, n);
    contacts.patches.push_back(make_patch(first, contacts.solver[first], shape_b.centre_arm, second,
                                          &contacts.solver[second], shape_a.centre_arm, n,
                                          material.friction, shape_b.twist_arm, first_point,
                                          static_cast<std::uint32_t>(count)));
  }
  contacts.island_out.resize(members.size());
  resolve_island(contacts.island_bodies, contacts.solver, contacts.points, contacts.patches,
                 contacts.positions, settings, contacts.poses, contacts.island_out);
  for (std::size_t k = 0; k < members.size(); ++k) {
    out[members[k]] = std::move(contacts.island_out[k]);
  }
}

// A large island (a pile): the sub-stepped solve from the start of the step
// (physics/substep_island.hpp), with every point found at the start pose.
void solve_substepped(Integrator integrator, std::span<const BodyModel> models,
                      std::span<const BodyState> in, double t, double dt, std::uint32_t island,
                      const std::vector<Plane>& planes, const ContactSettings& settings,
                      WorldContacts& contacts, std::span<BodyState> out) {
  const std::span<const std::uint32_t> members = start_island(island, contacts);
  contacts.substep_bodies.clear();
  for (const std::uint32_t i : members) {
    contacts.local[i] = static_cast<std::uint32_t>(contacts.substep_bodies.size());
    contacts.substep_bodies.push_back({.model = &models[i], .state = in[i]});
    contacts.solver.push_back(
        SolverBody::from(in[i], models[i].constants, contacts.start_rotations[i]));
  }
  // The fastest closing: of a pair, or of a body on the planes.
  double fastest = 0.0;
  for (std::uint32_t k = contacts.pair_offsets[island]; k < contacts.pair_offsets[island + 1];
       ++k) {
    const auto [a, b] = contacts.found[contacts.pair_order[k]].bodies;
    fastest = std::max(fastest, contacts.reaches[a] + contacts.reaches[b]);
  }
  for (const std::uint32_t i : members) fastest = std::max(fastest, contacts.reaches[i]);
  const int substeps = substeps_for(fastest);
  // In a fast island a body's corners near a plane are found again before each sub-step, as fast
  // pairs' points are: an impact within the step turns a box onto corners its start knew nothing
  // of (on the pile, bottom boxes hit from above went 3.9 cm into the floor so).
  const bool fast = substeps > kSubsteps;
  contacts.plane_rows.clear();
  if (!planes.empty()) {
    for (const std::uint32_t i : members) {
      const double margin = kTouchingDistance + contacts.reaches[i];
      const std::uint32_t local = contacts.local[i];
      if (!fast) {
        add_speculative_plane_points(models[i], local, in[i], contacts.start_rotations[i], margin,
                                     contacts.solver[local], planes, contacts.planes[i],
                                     contacts.points, contacts.patches, contacts.positions);
        continue;
      }
      contacts.planes[i].manifolds.resize(planes.size());
      const double near = models[i].half_size.norm() + margin + kRefindReach;
      for (std::uint32_t p = 0; p < planes.size(); ++p) {
        if (separation(planes[p], in[i].position()) > near) {
          contacts.planes[i].manifolds[p].count = 0;
          continue;
        }
        const PlaneRows rows{.body = i,
                             .plane = p,
                             .first = static_cast<std::uint32_t>(contacts.points.size()),
                             .patch = static_cast<std::uint32_t>(contacts.patches.size())};
        contacts.points.resize(contacts.points.size() + kMaxManifoldPoints);
        contacts.positions.resize(contacts.positions.size() + kMaxManifoldPoints);
        contacts.patches.emplace_back();
        write_plane_rows(rows, models[i], in[i], contacts.start_rotations[i], margin, planes,
                         contacts);
        contacts.plane_rows.push_back(rows);
      }
    }
  }
  contacts.rows.clear();
  for (std::uint32_t k = contacts.pair_offsets[island]; k < contacts.pair_offsets[island + 1];
       ++k) {
    const std::uint32_t p = contacts.pair_order[k];
    const auto [a, b] = contacts.found[p].bodies;
    PairRows rows{.pair = p,
                  .first = static_cast<std::uint32_t>(contacts.points.size()),
                  .patch = static_cast<std::uint32_t>(contacts.patches.size()),
                  .reach = contacts.reaches[a] + contacts.reaches[b]};
    rows.slots = rows.reach > kRefindReach
                     ? kMaxManifoldPoints
                     : static_cast<std::uint32_t>(contacts.found[p].manifold.count);
    contacts.points.resize(contacts.points.size() + rows.slots);
    contacts.positions.resize(contacts.positions.size() + rows.slots);
    contacts.patches.emplace_back();
    write_pair_rows(rows, models, contacts.start_rotations[a], contacts.start_rotations[b], in[a],
                    in[b], contacts);
    if (rows.reach > kRefindReach) contacts.rows.push_back(rows);
  }
  const auto refind = [&](int substep) {
    const double left = static_cast<double>(substeps - substep) / substeps;
    for (const PairRows& rows : contacts.rows) refind_pair(rows, models, left, contacts);
    for (const PlaneRows& rows : contacts.plane_rows) {
      const BodyState& now = contacts.substep_bodies[contacts.local[rows.body]].state;
      const BodyModel& model = models[rows.body];
      // As far as it can go in what is left of the step, at its speeds now or the start's, and
      // as far again as the projection may push it (a box wedged under another is pushed down).
      const double going =
          dt * (now.velocity().norm() + now.angular_velocity().norm() * model.half_size.norm());
      const double margin =
          kTouchingDistance + left * std::max(contacts.reaches[rows.body], going) + kRefindReach;
      write_plane_rows(rows, model, now, now.rotation(), margin, planes, contacts);
    }
  };
  substep_island(integrator, contacts.substep_bodies, contacts.solver, contacts.points,
                 contacts.positions, contacts.patches, t, dt, substeps, settings, contacts.substep,
                 contacts.rows.empty() ? std::function<void(int)>{} : refind);
  for (std::size_t k = 0; k < members.size(); ++k) {
    out[members[k]] = std::move(contacts.substep_bodies[k].state);
  }
}

// Whether the island suits solve_converged: small, and slow. Small: its pass budget
// (contact_island.hpp) still gives it kConvergedPasses. A pyramid of 55 cubes (400 points, 100
// passes) stands within 3 mm for 30 s so (0.33 mm with kept manifolds), and a tower of ten cubes
// within 3 mm for 60 s (1.3 mm), where the sub-steps let the tower rock 14 cm; but with 30 passes
// the pyramid moved 1.1 cm, and a pile of 1000 boxes solved so went 39 cm into itself, where the
// sub-steps (as many as it closes fast) keep it within 0.84 cm while the boxes land and 1.6 mm
// once it settles (contact_bench). Slow: no pair can close by more
// than kRefindReach in the step, for only the sub-steps find fast pairs' points again. Its points
// are counted as its pairs' and four for each body touching a plane.
constexpr int kConvergedPasses = 100;
bool converges(std::uint32_t island, const WorldContacts& contacts) {
  std::size_t points = 0;
  for (std::uint32_t k = contacts.pair_offsets[island]; k < contacts.pair_offsets[island + 1];
       ++k) {
    const PairContact& pair = contacts.found[contacts.pair_order[k]];
    const auto [a, b] = pair.bodies;
    if (contacts.reaches[a] + contacts.reaches[b] > kRefindReach) return false;
    points += static_cast<std::size_t>(pair.manifold.count);
  }
  for (std::uint32_t k = contacts.member_offsets[island]; k < contacts.member_offsets[island + 1];
       ++k) {
    if (contacts.advances[contacts.members[k]].touching) points += kMaxManifoldPoints;
  }
  return solver_passes(points) >= kConvergedPasses;
}

// Whether nothing but the body's state and the planes decides its laws: no law that switches
// on or off or moves in time, which a sleeping body would miss.
bool can_sleep(const BodyModel& model) {
  constexpr double kForever = std::numeric_limits<double>::infinity();
  return std::none_of(model.forces.begin(), model.forces.end(), [](const ForceLaw& law) {
    if (const auto* push = std::get_if<ForceAtPoint>(&law)) {
      return push->start != -kForever || push->end != kForever;
    }
    if (const auto* spring = std::get_if<Spring>(&law)) {
      return spring->start != -kForever || spring->end != kForever ||
             spring->anchor_keys.size() > 1;
    }
    return false;
  });
}

bool island_asleep(std::uint32_t island, const WorldContacts& contacts) {
  const auto members = members_of(island, contacts);
  return std::all_of(members.begin(), members.end(),
                     [&](std::uint32_t i) { return contacts.asleep[i] != 0; });
}

// Wakes the sleeping bodies of every island that has a body awake in it, each with its free step
// and its reach now; returns whether any woke.
bool wake_touched(Integrator integrator, std::span<const BodyModel> models,
                  std::span<const BodyState> in, double t, double dt,
                  const std::vector<Plane>& planes, const ContactSettings& settings, int islands,
                  WorldContacts& contacts) {
  bool woke = false;
  for (std::uint32_t island = 0; island < static_cast<std::uint32_t>(islands); ++island) {
    const auto members = members_of(island, contacts);
    const bool some_awake = std::any_of(members.begin(), members.end(),
                                        [&](std::uint32_t i) { return !contacts.asleep[i]; });
    if (!some_awake || island_asleep(island, contacts)) continue;
    for (const std::uint32_t i : members) {
      if (!contacts.asleep[i]) continue;
      contacts.asleep[i] = 0;
      contacts.still_for[i] = 0.0;
      contacts.advances[i] = advance_among_planes(integrator, models[i], in[i], t, dt, planes,
                                                  settings, contacts.planes[i]);
      contacts.reaches[i] = reach(in[i], contacts.advances[i].end, models[i].half_size, dt);
      woke = true;
    }
  }
  return woke;
}

// How fast the body's fastest point can move (m/s): a bound, |v| + |ω| × its half diagonal.
double point_speed_bound(const BodyState& state, const Vec3& half_size) {
  return state.velocity().norm() + state.angular_velocity().norm() * half_size.norm();
}

// Adds dt (s) to the body's time still if it ended the step still, else restarts it; returns
// whether it has been still for kTimeToSleep and may sleep.
bool still_long_enough(const BodyModel& model, const BodyState& end, double dt, double& still_for) {
  const bool still = point_speed_bound(end, model.half_size) < kSleepSpeed;
  still_for = still ? still_for + dt : 0.0;
  return still_for >= kTimeToSleep && can_sleep(model);
}

// Puts the body to sleep at rest where it stands.
void fall_asleep(const BodyModel& model, std::size_t i, WorldContacts& contacts,
                 std::span<BodyState> out) {
  PrimaryState rest = out[i].primary();
  rest.momentum.setZero();
  rest.angular_momentum.setZero();
  out[i] = BodyState(rest, model.constants);
  contacts.asleep[i] = 1;
}

// After the islands' solves: each awake body's time still, and an island whose bodies have all
// been still for kTimeToSleep (and may sleep) put to sleep at rest where it stands.
void settle(std::span<const BodyModel> models, double dt, int islands, WorldContacts& contacts,
            std::span<BodyState> out) {
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (contacts.island_of[i] == kNone) contacts.still_for[i] = 0.0;
  }
  for (std::uint32_t island = 0; island < static_cast<std::uint32_t>(islands); ++island) {
    if (island_asleep(island, contacts)) continue;
    const auto members = members_of(island, contacts);
    bool sleeps = true;
    for (const std::uint32_t i : members) {
      sleeps = still_long_enough(models[i], out[i], dt, contacts.still_for[i]) && sleeps;
    }
    if (!sleeps) continue;
    for (const std::uint32_t i : members) fall_asleep(models[i], i, contacts, out);
  }
}

// step_world for a world in which no two bodies can touch: each body's step among the planes
// (step_with_planes), and its sleep, exactly as its island of one would have them.
void step_bodies_alone(Integrator integrator, std::span<const BodyModel> models,
                       std::span<const BodyState> in, double t, double dt,
                       const std::vector<Plane>& planes, const ContactSettings& settings,
                       WorldContacts& contacts, std::span<BodyState> out) {
  contacts.planes.resize(in.size());
  contacts.pairs.clear();
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (contacts.asleep[i]) {  // nothing can wake it: only another body could
      out[i] = in[i];
      continue;
    }
    bool touching = false;
    if (planes.empty()) {
      out[i] = step(integrator, models[i], in[i], t, dt);
    } else {
      PlaneAdvance advance = advance_among_planes(integrator, models[i], in[i], t, dt, planes,
                                                  settings, contacts.planes[i]);
      touching = advance.touching;
      out[i] = touching ? rest_on_planes(integrator, models[i], advance, planes, settings,
                                         contacts.planes[i])
                        : std::move(advance.end);
    }
    if (!settings.sleep) continue;
    if (!touching) {
      contacts.still_for[i] = 0.0;
    } else if (still_long_enough(models[i], out[i], dt, contacts.still_for[i])) {
      fall_asleep(models[i], i, contacts, out);
    }
  }
}

}  // namespace

bool pairs_possible(std::span<const BodyModel> models, const ContactSettings& settings) {
  if (!settings.collide_bodies) return false;
  return std::count_if(models.begin(), models.end(),
                       [](const BodyModel& model) { return model.collides; }) >= 2;
}

void step_world(Integrator integrator, std::span<const BodyModel> models,
                std::span<const BodyState> in, double t, double dt,
                const std::vector<Plane>& planes, const ContactSettings& settings,
                WorldContacts& contacts, std::span<BodyState> out) {
  contacts.asleep.resize(in.size(), 0);
  contacts.still_for.resize(in.size(), 0.0);
  if (!pairs_possible(models, settings)) {
    step_bodies_alone(integrator, models, in, t, dt, planes, settings, contacts, out);
    return;
  }
  advance_bodies(integrator, models, in, t, dt, planes, settings, contacts);
  contacts.reaches.resize(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    contacts.reaches[i] = reach(in[i], contacts.advances[i].end, models[i].half_size, dt);
  }
  int islands = 0;
  do {  // again while bodies woke: what they touch now may be asleep too
    contacts.found.clear();
    if (settings.collide_bodies) find_pairs(models, in, contacts);
    islands = group_islands(in.size(), contacts);
  } while (settings.sleep &&
           wake_touched(integrator, models, in, t, dt, planes, settings, islands, contacts));
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (contacts.island_of[i] == kNone) out[i] = std::move(contacts.advances[i].end);
  }
  for (int island = 0; island < islands; ++island) {
    const auto k = static_cast<std::uint32_t>(island);
    if (island_asleep(k, contacts)) {
      for (const std::uint32_t i : members_of(k, contacts)) out[i] = in[i];
    } else if (contacts.pair_offsets[k] == contacts.pair_offsets[k + 1]) {
      // One body touching planes alone: its impacts were at their times; it rests as it would
      // with no other body in the world.
      const std::uint32_t i = contacts.members[contacts.member_offsets[k]];
      out[i] = rest_on_planes(integrator, models[i], contacts.advances[i], planes, settings,
                              contacts.planes[i]);
    } else if (converges(k, contacts)) {
      solve_converged(integrator, models, in, dt, k, planes, settings, contacts, out);
    } else {
      solve_substepped(integrator, models, in, t, dt, k, planes, settings, contacts, out);
    }
  }
  if (settings.sleep) settle(models, dt, islands, contacts, out);
  contacts.pairs.swap(contacts.found);
}

}  // namespace tumble::physics
