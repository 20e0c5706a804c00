#include "physics/world_step.hpp"

#include <algorithm>
#include <limits>

#include "physics/island_solve.hpp"

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
