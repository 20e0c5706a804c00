#include "app/scene_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/scene_builder.hpp"

namespace tumble::app {

Framing frame_scene(const scene::Scene& scene, std::int64_t frame_count) {
  // Bounds of every body, at every frame, as spheres around their centres.
  physics::Vec3 low = physics::Vec3::Constant(std::numeric_limits<double>::infinity());
  physics::Vec3 high = -low;
  double largest_radius = 0.0;
  double lowest_point = std::numeric_limits<double>::infinity();
  sim::Simulation simulation = scene::build_simulation(scene);
  for (std::int64_t k = 0; k < std::max<std::int64_t>(frame_count, 1); ++k) {
    const auto states = simulation.states_at(static_cast<double>(k) / scene.fps);
    for (std::size_t i = 0; i < states.size(); ++i) {
      const double radius = 0.5 * scene.bodies[i].size.norm();
      low = low.cwiseMin(states[i].position());
      high = high.cwiseMax(states[i].position());
      largest_radius = std::max(largest_radius, radius);
      lowest_point = std::min(lowest_point, states[i].position().y() - radius);
    }
  }

  Framing out;
  const physics::Vec3 center = 0.5 * (low + high);
  const double radius = 0.5 * (high - low).norm() + largest_radius;
  out.camera.look_at = scene.camera.look_at.value_or(center);
  out.camera.up = scene.camera.up;
  out.camera.fov_degrees = scene.camera.fov_degrees;
  if (scene.camera.position) {
    out.camera.position = *scene.camera.position;
  } else {
    // Far enough that the bounding sphere spans 65% of the frame's height (R / d = sin of the
    // angle it subtends), seen from above and to the side so that three faces of a cube show.
    const double half_fov = 0.5 * scene.camera.fov_degrees * M_PI / 180.0;
    const double distance = radius / (0.65 * std::sin(half_fov));
    out.camera.position =
        out.camera.look_at + distance * physics::Vec3(0.55, 0.42, 0.72).normalized();
  }
  out.ground_height = scene.ground_height.value_or(lowest_point - 0.25 * largest_radius);
  out.follow_offset = out.camera.position - out.camera.look_at;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].name == scene.camera.follow) out.follow_index = static_cast<int>(i);
  }
  return out;
}

render::FrameView frame_view(const scene::Scene& scene, const Framing& framing,
                             const std::vector<physics::BodyState>& states) {
  render::FrameView view;
  view.camera = framing.camera;
  if (framing.follow_index >= 0) {
    view.camera.look_at = states[static_cast<std::size_t>(framing.follow_index)].position();
    view.camera.position = view.camera.look_at + framing.follow_offset;
  }
  view.boxes.reserve(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    view.boxes.push_back(render::Box{.position = states[i].position(),
                                     .orientation = states[i].orientation(),
                                     .size = scene.bodies[i].size,
                                     .color = scene.bodies[i].color});
  }
  return view;
}

}  // namespace tumble::app
