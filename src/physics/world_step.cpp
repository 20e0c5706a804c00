#include "physics/world_step.hpp"

#include <algorithm>
#include <limits>

namespace tumble::physics {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// The speculative reach of a pair within a step (m): how far the two boxes can close on each
// other, from their centres' motion and the swing of their corners, plus the touching distance.
double speculative_margin(const BodyState& a_start, const BodyState& a_end, const Vec3& a_half,
                          const BodyState& b_start, const BodyState& b_end, const Vec3& b_half,
                          double h /* s */) {
  const Vec3 closing =
      (a_end.position() - a_start.position()) - (b_end.position() - b_start.position());
  const double swing =
      h * (std::max(a_start.angular_velocity().norm(), a_end.angular_velocity().norm()) *
               a_half.norm() +
           std::max(b_start.angular_velocity().norm(), b_end.angular_velocity().norm()) *
               b_half.norm());
  return kTouchingDistance + closing.norm() + swing;
}

BoxPose pose_of(const BodyState& state, const Mat3& rotation, const Vec3& half_size) {
  return {.position = state.position(), .rotation = rotation, .half_size = half_size};
}

// World position of a body point (body frame, m).
Vec3 world_point(const BodyState& state, const Mat3& rotation, const Vec3& body_point) {
  return state.position() + rotation * body_point;
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
    if (planes.empty()) {
      contacts.advances[i] = {.end = step(integrator, models[i], in[i], t, dt), .remaining = dt};
    } else {
      contacts.advances[i] = advance_among_planes(integrator, models[i], in[i], t, dt, planes,
                                                  settings, contacts.planes[i]);
    }
  }
}

// Into contacts.found: the touching pairs of colliding bodies, with their manifolds at the start
// of the step and the last step's impulses of the same features.
void find_pairs(std::span<const BodyModel> models, std::span<const BodyState> in, double dt,
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
    const BodyState& a_end = contacts.advances[a].end;
    const BodyState& b_end = contacts.advances[b].end;
    const double margin = speculative_margin(in[a], a_end, models[a].half_size, in[b], b_end,
                                             models[b].half_size, dt);
    PairManifold manifold =
        box_box_manifold(pose_of(in[a], contacts.start_rotations[a], models[a].half_size),
                         pose_of(in[b], contacts.start_rotations[b], models[b].half_size), margin);
    if (manifold.count == 0) continue;
    const BodyPair bodies{a, b};
    while (previous < contacts.pairs.size() && contacts.pairs[previous].bodies < bodies) {
      ++previous;
    }
    if (previous < contacts.pairs.size() && contacts.pairs[previous].bodies == bodies) {
      const PairManifold& before = contacts.pairs[previous].manifold;
      for (int k = 0; k < manifold.count; ++k) {
        PairPoint& now = manifold.points[static_cast<std::size_t>(k)];
        for (int j = 0; j < before.count; ++j) {
          const PairPoint& then = before.points[static_cast<std::size_t>(j)];
          if (then.feature == now.feature) now.impulses = then.impulses;
        }
      }
    }
    contacts.found.push_back({bodies, manifold});
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
  const auto bucket = [islands](std::size_t count, auto island_of_item,
                                std::vector<std::uint32_t>& offsets,
                                std::vector<std::uint32_t>& items) {
    offsets.assign(static_cast<std::size_t>(islands) + 1, 0);
    for (std::uint32_t k = 0; k < count; ++k) {
      if (const std::uint32_t i = island_of_item(k); i != kNone) ++offsets[i + 1];
    }
    for (int i = 0; i < islands; ++i) offsets[i + 1] += offsets[i];
    items.resize(offsets.back());
    std::vector<std::uint32_t> next(offsets.begin(), offsets.end() - 1);
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

void solve_island(Integrator integrator, std::span<const BodyModel> models,
                  std::span<const BodyState> in, double dt, std::uint32_t island,
                  const std::vector<Plane>& planes, const ContactSettings& settings,
                  WorldContacts& contacts, std::span<BodyState> out) {
  const std::span<const std::uint32_t> members(
      contacts.members.data() + contacts.member_offsets[island],
      contacts.member_offsets[island + 1] - contacts.member_offsets[island]);
  contacts.island_bodies.clear();
  contacts.solver.clear();
  contacts.points.clear();
  contacts.patches.clear();
  contacts.positions.clear();
  contacts.local.resize(contacts.island_of.size());
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
    // No warm start of friction between bodies (contact_solver.hpp says why).
  }
  contacts.island_out.resize(members.size());
  resolve_island(contacts.island_bodies, contacts.solver, contacts.points, contacts.patches,
                 contacts.positions, settings, contacts.island_out);
  for (std::size_t k = 0; k < members.size(); ++k) {
    out[members[k]] = std::move(contacts.island_out[k]);
  }
}

}  // namespace

void step_world(Integrator integrator, std::span<const BodyModel> models,
                std::span<const BodyState> in, double t, double dt,
                const std::vector<Plane>& planes, const ContactSettings& settings,
                WorldContacts& contacts, std::span<BodyState> out) {
  advance_bodies(integrator, models, in, t, dt, planes, settings, contacts);
  contacts.found.clear();
  if (settings.collide_bodies) find_pairs(models, in, dt, contacts);
  const int islands = group_islands(in.size(), contacts);
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (contacts.island_of[i] == kNone) out[i] = std::move(contacts.advances[i].end);
  }
  for (int island = 0; island < islands; ++island) {
    solve_island(integrator, models, in, dt, static_cast<std::uint32_t>(island), planes, settings,
                 contacts, out);
  }
  contacts.pairs.swap(contacts.found);
}

}  // namespace tumble::physics
