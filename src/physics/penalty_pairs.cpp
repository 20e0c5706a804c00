#include "physics/penalty_pairs.hpp"

#include <cmath>

#include "physics/pair_contact.hpp"

namespace tumble::physics {

void PenaltyPairs::add(std::span<const BodyState> states, double /*t*/,
                       std::span<Wrench> wrenches) const {
  for (const auto& [i, j] : pairs_) {
    const BodyState& a = states[i];
    const BodyState& b = states[j];
    const Mat3 rotation_a = a.rotation(), rotation_b = b.rotation();
    const PairManifold manifold = pair_manifold({a.position(), rotation_a, &models_[i].shape},
                                                {b.position(), rotation_b, &models_[j].shape}, 0.0);
    if (manifold.count == 0) continue;
    const double friction = combine(models_[i].material, models_[j].material).friction;
    const Vec3& normal = manifold.normal;
    for (int k = 0; k < manifold.count; ++k) {
      const PairPoint& contact = manifold.points[k];
      const double depth = -contact.separation;  // m, positive overlapping
      if (depth <= 0.0) continue;
      const Vec3 point = 0.5 * ((a.position() + rotation_a * contact.point_a) +
                                (b.position() + rotation_b * contact.point_b));
      const Vec3 velocity = point_velocity(b, point) - point_velocity(a, point);
      const double normal_speed = normal.dot(velocity);
      const double normal_force =
          std::max(0.0, springs_.stiffness * depth - springs_.damping * normal_speed);
      const Vec3 slip = velocity - normal_speed * normal;
      const Vec3 force =
          normal_force * normal -
          (friction * normal_force /
           std::sqrt(slip.squaredNorm() + springs_.slip_speed * springs_.slip_speed)) *
              slip;  // on B (N)
      const Wrench on_b = force_at_world_point(b, force, point);
      const Wrench on_a = force_at_world_point(a, -force, point);
      wrenches[i].force += on_a.force;
      wrenches[i].torque += on_a.torque;
      wrenches[j].force += on_b.force;
      wrenches[j].torque += on_b.torque;
    }
  }
}

void step_penalty_world(Integrator integrator, std::span<const BodyModel> models,
                        std::span<const BodyState> in, double t, double dt,
                        const ContactSettings& settings, PenaltyWorld& scratch,
                        std::span<BodyState> out, JointWorld* joints) {
  const std::size_t count = models.size();
  scratch.pairs.clear();
  if (settings.collide_bodies) {
    scratch.colliders.clear();
    scratch.bounds.clear();
    for (std::uint32_t i = 0; i < count; ++i) {
      if (!models[i].collides) continue;
      const BodyState& state = in[i];
      const double reach = (state.velocity().norm() +
                            state.angular_velocity().norm() * models[i].shape.half_size.norm()) *
                               dt +
                           kPenaltyReach;
      scratch.colliders.push_back(i);
      scratch.bounds.push_back(
          box_bounds(state.position(), state.rotation(), models[i].shape.half_size, reach));
    }
    overlapping_pairs(scratch.bounds, scratch.order, scratch.candidates);
    for (const auto& [first, second] : scratch.candidates) {
      const BodyPair pair(scratch.colliders[first], scratch.colliders[second]);
      if (joints && joints->keeps_apart(pair)) continue;
      scratch.pairs.push_back(pair);
    }
  }
  if (joints && !joints->joints.empty()) {
    // The joints' forces after the springs', from every stage's states (the springs' wrenches are
    // among the forces the joints' rows hold against), then their limits and the projection.
    const PenaltyPairs springs(
        models, {.stiffness = settings.stiffness, .damping = settings.damping}, scratch.pairs);
    const JointForces held(joints->joints, models, joints->whole);
    const struct Both final : Coupling {
      const Coupling& first;
      const Coupling& second;
      Both(const Coupling& a, const Coupling& b) : first(a), second(b) {}
      void add(std::span<const BodyState> states, double time,
               std::span<Wrench> wrenches) const override {
        first.add(states, time, wrenches);
        second.add(states, time, wrenches);
      }
    } both(springs, held);
    step_coupled(integrator, models, in, t, dt, both, out);
    hold_joint_members(integrator, dt, *joints, out);
    return;
  }
  if (scratch.pairs.empty()) {
    for (std::size_t i = 0; i < count; ++i) out[i] = step(integrator, models[i], in[i], t, dt);
    return;
  }
  const PenaltyPairs springs(models, {.stiffness = settings.stiffness, .damping = settings.damping},
                             scratch.pairs);
  step_coupled(integrator, models, in, t, dt, springs, out);
}

}  // namespace tumble::physics
