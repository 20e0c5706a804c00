#include "scene/stability_report.hpp"

#include <string>

#include "scene/scene_builder.hpp"
#include "sim/contact_advice.hpp"
#include "sim/stability.hpp"

namespace tumble::scene {
namespace {

std::vector<sim::StepWarning> body_warnings(const scene::Scene& scene,
                                            const scene::BodySpec& body) {
  return sim::check_step(scene::body_model(scene, body), scene::initial_state(body),
                         scene.physics.integrator, scene.physics.dt, scene.duration);
}

// `body "a"`, `bodies "a" and "b"`, or `bodies "a", "b", "c" and 4 more`.
std::string names_of(const scene::Scene& scene, const std::vector<std::size_t>& bodies) {
  constexpr std::size_t kNamed = 3;
  std::string out = bodies.size() == 1 ? "body " : "bodies ";
  for (std::size_t k = 0; k < bodies.size() && k < kNamed; ++k) {
    if (k > 0) out += k + 1 == bodies.size() ? " and " : ", ";
    out += "\"" + scene.bodies[bodies[k]].name + "\"";
  }
  if (bodies.size() > kNamed) out += " and " + std::to_string(bodies.size() - kNamed) + " more";
  return out;
}

}  // namespace

std::vector<std::string> stability_warnings(const scene::Scene& scene) {
  std::vector<std::string> lines;
  std::vector<physics::Plane> planes;
  for (const scene::PlaneSpec& spec : scene.planes) planes.push_back(scene::plane(spec));
  for (const scene::BodySpec& body : scene.bodies) {
    if (body.hull && body.hull->given_corners > body.hull->hull->vertices.size()) {
      lines.push_back("body \"" + body.name + "\": the hull of its points has " +
                      std::to_string(body.hull->given_corners) + " corners; tumble keeps " +
                      std::to_string(body.hull->hull->vertices.size()) +
                      " of them (picked farthest first), and it touches and is drawn as the "
                      "hull of those: features between them are cut off");
    }
    for (const sim::StepWarning& warning : body_warnings(scene, body)) {
      lines.push_back("body \"" + body.name + "\": " + warning.message);
    }
    for (const std::string& problem :
         sim::check_contact(scene::body_model(scene, body), planes, scene.physics.contact,
                            scene.physics.integrator, scene.physics.dt)) {
      lines.push_back("body \"" + body.name + "\": " + problem);
    }
  }
  std::vector<physics::BodyModel> models;
  std::vector<physics::BodyState> initial;
  for (const scene::BodySpec& body : scene.bodies) {
    models.push_back(scene::body_model(scene, body));
    initial.push_back(scene::initial_state(body));
  }
  const std::vector<std::size_t> weightless = sim::weightless_above_floor(models, initial, planes);
  if (!weightless.empty()) {
    lines.push_back(names_of(scene, weightless) +
                    ": no gravity acts, yet a floor (a plane facing up) lies below, which "
                    "nothing will ever bring " +
                    (weightless.size() == 1 ? "it" : "them") + " down to; if " +
                    (weightless.size() == 1 ? "it" : "they") +
                    " should fall, add [physics] gravity = [0, -9.81, 0]");
  }
  for (const sim::BodiesAdvice& advice :
       sim::check_contact_world(models, initial, planes, scene.physics.contact,
                                scene.physics.integrator, scene.physics.dt)) {
    lines.push_back(names_of(scene, advice.bodies) + ": " + advice.message);
  }
  return lines;
}

void print_stability_warnings(const scene::Scene& scene, std::FILE* out) {
  for (const std::string& line : stability_warnings(scene)) {
    std::fprintf(out, "tumble: warning: %s\n", line.c_str());
  }
}

std::string blow_up_message(const scene::Scene& scene, const sim::BlowUp& blow_up) {
  const scene::BodySpec& body = scene.bodies.at(blow_up.body);
  char when[96];
  std::snprintf(when, sizeof when, " at t = %.6g s (step %lld of dt = %.6g s): ", blow_up.time,
                static_cast<long long>(blow_up.step), scene.physics.dt);
  std::string message = "body \"" + body.name + "\" blew up" + when + blow_up.what + ".";
  const std::vector<sim::StepWarning> warnings = body_warnings(scene, body);
  if (warnings.empty()) {
    return message +
           " No stability limit tumble knows of is exceeded: check the sizes of its forces, "
           "or try a smaller dt (tumble check " +
           scene.source_path + " explains the step).";
  }
  message += " Likely cause:";
  for (const sim::StepWarning& warning : warnings) message += " " + warning.message;
  return message;
}

}  // namespace tumble::scene
