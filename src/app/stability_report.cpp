#include "app/stability_report.hpp"

#include "scene/scene_builder.hpp"
#include "sim/stability.hpp"

namespace tumble::app {

std::vector<std::string> stability_warnings(const scene::Scene& scene) {
  std::vector<std::string> lines;
  for (const scene::BodySpec& body : scene.bodies) {
    const physics::BodyModel model{.constants = scene::body_constants(body), .forces = body.forces};
    for (const sim::StepWarning& warning :
         sim::check_step(model, scene::initial_state(body), scene.physics.integrator,
                         scene.physics.dt, scene.duration)) {
      lines.push_back("body \"" + body.name + "\": " + warning.message);
    }
  }
  return lines;
}

void print_stability_warnings(const scene::Scene& scene, std::FILE* out) {
  for (const std::string& line : stability_warnings(scene)) {
    std::fprintf(out, "tumble: warning: %s\n", line.c_str());
  }
}

}  // namespace tumble::app
