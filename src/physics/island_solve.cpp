#include "physics/island_solve.hpp"

#include <algorithm>
#include <functional>

namespace tumble::physics {
namespace {

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

// The island's bodies, with the lists its solve fills emptied.
std::span<const std::uint32_t> start_island(std::uint32_t island, WorldContacts& contacts) {
  contacts.solver.clear();
  contacts.points.clear();
  contacts.patches.clear();
  contacts.positions.clear();
  contacts.local.resize(contacts.island_of.size());
  return members_of(island, contacts);
}

}  // namespace

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

}  // namespace tumble::physics
