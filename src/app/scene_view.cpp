#include "app/scene_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "app/plane_view.hpp"
#include "app/stability_report.hpp"
#include "scene/scene_builder.hpp"

namespace tumble::app {

std::vector<physics::BodyState> checked_states_at(sim::Simulation& simulation,
                                                  const scene::Scene& scene, double t,
                                                  const StopRequested& stop_requested) {
  if (stop_requested()) throw RenderStopped("interrupted");
  std::vector<physics::BodyState> states = simulation.states_at(t);
  if (simulation.blow_up()) throw RenderStopped(blow_up_message(scene, *simulation.blow_up()));
  return states;
}

Framing frame_scene(const scene::Scene& scene, std::int64_t frame_count,
                    const StopRequested& stop_requested) {
  // Bounds of every body, at every frame, as spheres around their centres.
  physics::Vec3 low = physics::Vec3::Constant(std::numeric_limits<double>::infinity());
  physics::Vec3 high = -low;
  double largest_radius = 0.0;
  double lowest_point = std::numeric_limits<double>::infinity();
  sim::Simulation simulation = scene::build_simulation(scene);
  for (std::int64_t k = 0; k < std::max<std::int64_t>(frame_count, 1); ++k) {
    const double t = static_cast<double>(k) / scene.fps;  // s
    const auto states = checked_states_at(simulation, scene, t, stop_requested);
    for (std::size_t i = 0; i < states.size(); ++i) {
      const double radius = 0.5 * scene.bodies[i].size.norm();
      low = low.cwiseMin(states[i].position());
      high = high.cwiseMax(states[i].position());
      largest_radius = std::max(largest_radius, radius);
      lowest_point = std::min(lowest_point, states[i].position().y() - radius);
      // Spring anchors are drawn too, where they are while they act: keep them in the picture.
      for (const physics::ForceLaw& law : scene.bodies[i].forces) {
        const auto* spring = std::get_if<physics::Spring>(&law);
        if (!spring || !physics::acts_at(*spring, t)) continue;
        const physics::Vec3 anchor = physics::anchor_motion(*spring, t).position;
        low = low.cwiseMin(anchor);
        high = high.cwiseMax(anchor);
      }
    }
  }

  Framing out;
  if (scene.planes.empty()) {
    out.ground = scene.render.ground;
    out.ground.height = scene.ground_height.value_or(lowest_point - 0.25 * largest_radius);
  } else {
    DrawnPlanes planes = drawn_planes(scene);
    out.ground = planes.ground;
    out.quads = std::move(planes.quads);
    // Walls as far as two motion radii from it: a room around a small motion shows, a default
    // 20 m wall does not take over the picture.
    frame_walls(out.quads, 2.0 * (0.5 * (high - low).norm() + largest_radius), low, high);
  }
  const physics::Vec3 center = 0.5 * (low + high);
  const double radius = 0.5 * (high - low).norm() + largest_radius;
  out.camera.look_at = scene.camera.look_at.value_or(center);
  out.camera.up = scene.camera.up;
  out.camera.fov_degrees = scene.camera.fov_degrees;
  if (scene.camera.position) {
    out.camera.position = *scene.camera.position;
    if ((out.camera.position - out.camera.look_at).norm() == 0.0) {
      throw RenderStopped(scene.source_path +
                          ": [camera] position is the centre of the motion, where the camera "
                          "looks when look_at is not given: the view has no direction; give "
                          "[camera] look_at");
    }
  } else {
    // Far enough that the bounding sphere spans 65% of the frame's height (R / d = sin of the
    // angle it subtends), seen from above and to the side so that three faces of a cube show.
    const double half_fov = 0.5 * scene.camera.fov_degrees * M_PI / 180.0;
    const double distance = radius / (0.65 * std::sin(half_fov));
    out.camera.position =
        out.camera.look_at + distance * physics::Vec3(0.55, 0.42, 0.72).normalized();
  }
  out.follow_offset = out.camera.position - out.camera.look_at;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].name == scene.camera.follow) out.follow_index = static_cast<int>(i);
  }
  return out;
}

namespace {

const render::Color kSpringColor(0.22, 0.23, 0.26);
const render::Color kPushColor(0.98, 0.80, 0.15);

// A thin box along the segment from `from` to `to`: how springs and pushes are drawn.
render::Box rod(const physics::Vec3& from, const physics::Vec3& to, double thickness,
                const render::Color& color) {
  const physics::Vec3 along = to - from;
  return render::Box{.position = 0.5 * (from + to),
                     .orientation = physics::Quat::FromTwoVectors(physics::Vec3::UnitZ(), along),
                     .size = physics::Vec3(thickness, thickness, std::max(along.norm(), thickness)),
                     .color = color};
}

// Springs (a rod and an anchor block, where the anchor is at t) and pushes (a rod ending at the
// pushed point), each while it acts, so that what moves a body can be seen. Sizes scale with the
// body.
void add_force_visuals(const scene::BodySpec& body, const physics::BodyState& state, double t,
                       std::vector<render::Box>& out) {
  const double scale = body.size.maxCoeff();
  for (const physics::ForceLaw& law : body.forces) {
    if (const auto* spring = std::get_if<physics::Spring>(&law)) {
      if (!physics::acts_at(*spring, t)) continue;
      const physics::Vec3 anchor = physics::anchor_motion(*spring, t).position;
      const physics::Vec3 end = physics::body_point_to_world(state, spring->attachment);
      out.push_back(rod(anchor, end, 0.04 * scale, kSpringColor));
      out.push_back(render::Box{.position = anchor,
                                .size = physics::Vec3::Constant(0.15 * scale),
                                .color = kSpringColor});
    } else if (const auto* push = std::get_if<physics::ForceAtPoint>(&law)) {
      const double magnitude = push->force.norm();
      if (!physics::acts_at(*push, t) || magnitude == 0.0) continue;
      const physics::Vec3 point = physics::body_point_to_world(state, push->point);
      const double length = std::clamp(0.4 * magnitude, 0.4, 1.5) * scale;
      out.push_back(rod(point - length * push->force / magnitude, point, 0.05 * scale, kPushColor));
    }
  }
}

}  // namespace

render::FrameView frame_view(const scene::Scene& scene, const Framing& framing,
                             const std::vector<physics::BodyState>& states, double t) {
  render::FrameView view;
  view.camera = framing.camera;
  if (framing.follow_index >= 0) {
    view.camera.look_at = states[static_cast<std::size_t>(framing.follow_index)].position();
    view.camera.position = view.camera.look_at + framing.follow_offset;
  }
  view.quads = framing.quads;
  view.boxes.reserve(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    view.boxes.push_back(render::Box{.position = states[i].position(),
                                     .orientation = states[i].orientation(),
                                     .size = scene.bodies[i].size,
                                     .color = scene.bodies[i].color});
    add_force_visuals(scene.bodies[i], states[i], t, view.boxes);
  }
  return view;
}

}  // namespace tumble::app
