#include "sim/contact_advice.hpp"

#include <cstdio>
#include <variant>

namespace tumble::sim {

std::vector<std::string> check_contact(const physics::BodyModel& model,
                                       const std::vector<physics::Plane>& planes,
                                       const physics::ContactSettings& settings, double dt) {
  std::vector<std::string> out;
  if (settings.method != physics::ContactMethod::impulse) return out;
  physics::Vec3 gravity = physics::Vec3::Zero();  // m/s²
  for (const physics::ForceLaw& law : model.forces) {
    if (const auto* g = std::get_if<physics::Gravity>(&law)) gravity += g->acceleration;
  }
  const double step_speed = gravity.norm() * dt;  // m/s gained in one step of free fall
  const double wanted = kThresholdOverStepSpeed * step_speed;
  if (settings.restitution_threshold >= wanted) return out;
  for (const physics::Plane& plane : planes) {
    if (physics::combine(model.material, plane.material).restitution <= 0.0) continue;
    char text[320];
    std::snprintf(text, sizeof text,
                  "restitution_threshold = %.3g m/s is below %.2g × the %.3g m/s that gravity adds "
                  "in one step (|g| dt), so resting on a plane it bounces off (restitution > 0) it "
                  "will bounce on every step and chatter; use restitution_threshold >= %.3g m/s "
                  "or a smaller dt",
                  settings.restitution_threshold, kThresholdOverStepSpeed, step_speed, wanted);
    out.push_back(text);
    break;
  }
  return out;
}

}  // namespace tumble::sim
