// Penalty contact (the PenaltyContact law of forces.hpp): Fiedler, "Spring Physics" (2004):
// F = n k d − n b (n·v) at each penetrating point, here with the damping clamped so that the
// contact never pulls, and with Coulomb friction regularised around zero slip.
#include <cmath>

#include "physics/contact.hpp"
#include "physics/forces.hpp"
#include "physics/integrators.hpp"

namespace tumble::physics {

Wrench penalty_contact_wrench(const PenaltyContact& law, const BodyState& state) {
  Wrench total;
  for (const Plane& plane : law.planes) {
    // Most steps of most bodies touch nothing: one distance against the bounding sphere.
    if (separation(plane, state.position()) > law.half_size.norm()) continue;
    const double friction = combine(law.material, plane.material).friction;
    for (int feature = 0; feature < 8; ++feature) {
      const Vec3 point = body_point_to_world(state, corner(law.half_size, feature));
      const double depth = -separation(plane, point);  // m, positive inside
      if (depth <= 0.0) continue;
      const Vec3 velocity = point_velocity(state, point);
      const double normal_speed = plane.normal.dot(velocity);
      const double normal_force =
          std::max(0.0, law.stiffness * depth - law.damping * normal_speed);  // N, pushes only
      const Vec3 slip = velocity - normal_speed * plane.normal;               // m/s, in the plane
      const Vec3 force = normal_force * plane.normal -
                         (friction * normal_force /
                          std::sqrt(slip.squaredNorm() + law.slip_speed * law.slip_speed)) *
                             slip;
      const Wrench w = force_at_world_point(state, force, point);
      total.force += w.force;
      total.torque += w.torque;
    }
  }
  return total;
}

BodyModel with_penalty_contact(BodyModel model, std::vector<Plane> planes, double stiffness,
                               double damping) {
  model.forces.push_back(PenaltyContact{.planes = std::move(planes),
                                        .half_size = model.shape.half_size,
                                        .material = model.material,
                                        .stiffness = stiffness,
                                        .damping = damping});
  return model;
}

}  // namespace tumble::physics
