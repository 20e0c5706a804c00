#include "view/scene_view.hpp"

#include "view/joint_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/scene_builder.hpp"
#include "scene/stability_report.hpp"
#include "view/camera_path.hpp"
#include "view/plane_view.hpp"

namespace tumble::view {

Result<std::vector<physics::BodyState>> checked_states_at(sim::Simulation& simulation,
                                                          const scene::Scene& scene, double t,
                                                          const StopRequested& stop_requested) {
  if (stop_requested()) return Error{"interrupted"};
  std::vector<physics::BodyState> states = simulation.states_at(t);
  if (simulation.blow_up()) return Error{scene::blow_up_message(scene, *simulation.blow_up())};
  return states;
}

bool framing_needs_motion(const scene::Scene& scene) {
  const bool camera_given =
      !scene.camera.keys.empty() || (scene.camera.position && scene.camera.look_at);
  return !camera_given || (scene.planes.empty() && !scene.ground_height);
}

namespace {

// Where the bodies go over the whole run, as spheres around their centres.
struct MotionBounds {
  // Around every centre, and every spring anchor while it acts, at every frame (world frame, m).
  physics::Vec3 low = physics::Vec3::Constant(std::numeric_limits<double>::infinity());
  physics::Vec3 high = -low;
  double largest_radius = 0.0;                                    // of any body's sphere (m)
  double lowest_point = std::numeric_limits<double>::infinity();  // y any sphere reaches (m)
  std::int64_t steps = 0;                                         // physics steps taken
};

void take_in(const scene::Scene& scene, const std::vector<physics::BodyState>& states, double t,
             MotionBounds& bounds) {
  for (std::size_t i = 0; i < states.size(); ++i) {
    const double radius = 0.5 * scene.bodies[i].size.norm();
    bounds.low = bounds.low.cwiseMin(states[i].position());
    bounds.high = bounds.high.cwiseMax(states[i].position());
    bounds.largest_radius = std::max(bounds.largest_radius, radius);
    bounds.lowest_point = std::min(bounds.lowest_point, states[i].position().y() - radius);
    // Spring anchors are drawn too, where they are while they act: keep them in the picture.
    for (const physics::ForceLaw& law : scene.bodies[i].forces) {
      const auto* spring = std::get_if<physics::Spring>(&law);
      if (!spring || !physics::acts_at(*spring, t)) continue;
      const physics::Vec3 anchor = physics::anchor_motion(*spring, t).position;
      bounds.low = bounds.low.cwiseMin(anchor);
      bounds.high = bounds.high.cwiseMax(anchor);
    }
  }
}

// The framing pass: the scene's physics at every frame time, on a simulation of its own.
Result<MotionBounds> motion_bounds(const scene::Scene& scene, std::int64_t frame_count,
                                   const StopRequested& stop_requested) {
  MotionBounds bounds;
  sim::Simulation simulation = scene::build_simulation(scene);
  for (std::int64_t k = 0; k < std::max<std::int64_t>(frame_count, 1); ++k) {
    const double t = static_cast<double>(k) / scene.fps;  // s
    const auto states = checked_states_at(simulation, scene, t, stop_requested);
    if (!states) return Error{states.error()};
    take_in(scene, *states, t, bounds);
  }
  bounds.steps = simulation.step_count();
  return bounds;
}

// The camera the scene leaves to be chosen, framing `bounds`: looking at their centre unless
// look_at is given, and unless position is given, far enough that the bounding sphere spans 65%
// of the frame's height (R / d = sin of the angle it subtends), seen from above and to the side
// so that three faces of a cube show.
Result<render::Camera> chosen_camera(const scene::Scene& scene, const MotionBounds& bounds) {
  const physics::Vec3 center = 0.5 * (bounds.low + bounds.high);
  const double radius = 0.5 * (bounds.high - bounds.low).norm() + bounds.largest_radius;
  render::Camera camera{.look_at = scene.camera.look_at.value_or(center),
                        .up = scene.camera.up,
                        .fov_degrees = scene.camera.fov_degrees};
  if (scene.camera.position) {
    camera.position = *scene.camera.position;
    if ((camera.position - camera.look_at).norm() == 0.0) {
      return Error{scene.source_path +
                   ": [camera] position is the centre of the motion, where the camera looks "
                   "when look_at is not given: the view has no direction; give [camera] look_at"};
    }
  } else {
    const double half_fov = 0.5 * scene.camera.fov_degrees * M_PI / 180.0;
    const double distance = radius / (0.65 * std::sin(half_fov));
    camera.position = camera.look_at + distance * physics::Vec3(0.55, 0.42, 0.72).normalized();
  }
  return camera;
}

}  // namespace

Result<Framing> frame_scene(const scene::Scene& scene, std::int64_t frame_count,
                            const StopRequested& stop_requested) {
  Framing out;
  if (scene.planes.empty()) {
    out.ground = scene.render.ground;
  } else {
    DrawnPlanes planes = drawn_planes(scene);
    out.ground = planes.ground;
    out.quads = std::move(planes.quads);
    out.quad_names = std::move(planes.names);
  }
  if (framing_needs_motion(scene)) {
    Result<MotionBounds> bounds = motion_bounds(scene, frame_count, stop_requested);
    if (!bounds) return Error{bounds.error()};
    out.physics_steps = bounds->steps;
    if (scene.planes.empty()) {
      out.ground.height =
          scene.ground_height.value_or(bounds->lowest_point - 0.25 * bounds->largest_radius);
    } else {
      // Walls as far as two motion radii from it: a room around a small motion shows, a default
      // 20 m wall does not take over the picture.
      frame_walls(out.quads,
                  2.0 * (0.5 * (bounds->high - bounds->low).norm() + bounds->largest_radius),
                  bounds->low, bounds->high);
    }
    Result<render::Camera> camera = chosen_camera(scene, *bounds);
    if (!camera) return Error{camera.error()};
    out.camera = *camera;
  } else {
    if (scene.planes.empty()) out.ground.height = *scene.ground_height;
    out.camera = scene.camera.keys.empty() ? render::Camera{.position = *scene.camera.position,
                                                            .look_at = *scene.camera.look_at,
                                                            .up = scene.camera.up,
                                                            .fov_degrees = scene.camera.fov_degrees}
                                           : keyed_camera(scene.camera.keys, scene.camera.up, 0.0);
  }
  for (std::size_t i = 0; i < scene.bodies.size() && !scene.camera.follow.empty(); ++i) {
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

render::Solid solid_of(scene::Shape shape) {
  switch (shape) {
    case scene::Shape::sphere:
      return render::Solid::ball;
    case scene::Shape::capsule:
      return render::Solid::capsule;
    case scene::Shape::cylinder:
      return render::Solid::cylinder;
    case scene::Shape::hull:
      return render::Solid::hull;
    case scene::Shape::cube:
    case scene::Shape::box:
      break;
  }
  return render::Solid::box;
}

render::FrameView frame_view(const scene::Scene& scene, const Framing& framing,
                             const std::vector<physics::BodyState>& states, double t) {
  render::FrameView view;
  view.camera = camera_at(scene.camera, framing.camera, framing.follow_index, states, t);
  view.quads = framing.quads;
  view.boxes.reserve(states.size());
  std::uint32_t hulls = 0;  // before body i: its mesh's index (render_settings lists them so)
  for (std::size_t i = 0; i < states.size(); ++i) {
    view.boxes.push_back(render::Box{.position = states[i].position(),
                                     .orientation = states[i].orientation(),
                                     .size = scene.bodies[i].size,
                                     .color = scene.bodies[i].color,
                                     .solid = solid_of(scene.bodies[i].shape),
                                     .mesh = scene.bodies[i].hull ? hulls++ : 0});
    add_force_visuals(scene.bodies[i], states[i], t, view.boxes);
  }
  return view;
}

SimulatedFrames::SimulatedFrames(const scene::Scene& scene, const Framing& framing,
                                 StopRequested stop_requested)
    : scene_(scene),
      framing_(framing),
      stop_requested_(std::move(stop_requested)),
      simulation_(scene::build_simulation(scene)) {
  if (!scene.overlays.empty()) overlays_.emplace(scene);
}

std::vector<JointValue> SimulatedFrames::joint_values_at(double t) const {
  if (scene_.joints.empty()) return {};
  const std::int64_t n = simulation_.step_count();
  return joint_values(
      simulation_.joints(), simulation_.previous(), simulation_.current(), simulation_.alpha_at(t),
      simulation_.time_of_step(std::max<std::int64_t>(n - 1, 0)), simulation_.time_of_step(n));
}

Result<render::FrameView> SimulatedFrames::view(std::int64_t frame) {
  const double t = static_cast<double>(frame) / scene_.fps;  // s
  if (overlays_ && !started_) {
    // The trails' and plots' past, as a render from frame 0 would have recorded it.
    for (std::int64_t k = std::max<std::int64_t>(0, frame - overlays_->frames_of_history());
         k < frame; ++k) {
      const double past = static_cast<double>(k) / scene_.fps;  // s
      const auto states = checked_states_at(simulation_, scene_, past, stop_requested_);
      if (!states) return Error{states.error()};
      const StepPair steps{simulation_.previous(), simulation_.current(),
                           simulation_.alpha_at(past)};
      overlays_->record(*states, steps, past, joint_values_at(past));
    }
  }
  started_ = true;
  // Motion blur: the bodies at each picture's time, which spread over the shutter around t,
  // taken in time order with t's (the physics only goes forward).
  const common::MotionBlur& blur = scene_.render.motion_blur;
  std::vector<std::vector<render::Box>> blurred;
  int picture = 0;
  const auto add_pictures_until = [&](double end) -> Result<void> {
    for (; blur.on() && picture < blur.samples && blur.time(t, picture, scene_.fps) < end;
         ++picture) {
      const double at = std::clamp(blur.time(t, picture, scene_.fps), 0.0, scene_.duration);
      const auto states = checked_states_at(simulation_, scene_, at, stop_requested_);
      if (!states) return Error{states.error()};
      render::FrameView bodies = frame_view(scene_, framing_, *states, at);
      if (!scene_.joints.empty()) add_joints(scene_, simulation_.joints(), *states, bodies);
      blurred.push_back(std::move(bodies.boxes));
    }
    return {};
  };
  if (const Result<void> before = add_pictures_until(t); !before) return Error{before.error()};
  const Result<std::vector<physics::BodyState>> states =
      checked_states_at(simulation_, scene_, t, stop_requested_);
  if (!states) return Error{states.error()};
  render::FrameView view = frame_view(scene_, framing_, *states, t);
  if (recording_) {
    FrameMotion& motion = motion_.emplace_back(FrameMotion{.time = t,
                                                           .camera = view.camera,
                                                           .positions = {},
                                                           .orientations = {},
                                                           .arrows = {},
                                                           .trail_points = {}});
    for (const physics::BodyState& state : *states) {
      motion.positions.push_back(state.position());
      motion.orientations.push_back(state.orientation());
    }
  }
  if (!scene_.joints.empty()) add_joints(scene_, simulation_.joints(), *states, view);
  if (overlays_) {
    // The values shown: of the two steps around t, each interpolated as itself.
    const StepPair steps{simulation_.previous(), simulation_.current(), simulation_.alpha_at(t)};
    const std::vector<JointValue> joints = joint_values_at(t);
    overlays_->record(*states, steps, t, joints);
    std::vector<BodyContact> contacts;
    if (overlays_->needs_contacts()) contacts = contact_forces(simulation_);
    overlays_->add_to(*states, steps, t, frame, view, joints, contacts);
    if (recording_) {
      // Only the overlays draw arrows and lines, and each trail's line ends at the point just
      // recorded: the frame's own.
      motion_.back().arrows = view.arrows;
      for (const render::Polyline& line : view.lines) {
        motion_.back().trail_points.push_back(line.points.back());
      }
    }
  }
  if (blur.on()) {
    const Result<void> after = add_pictures_until(std::numeric_limits<double>::infinity());
    if (!after) return Error{after.error()};
    view.blurred_boxes = std::move(blurred);
  }
  return view;
}

render::FrameView motion_view(const scene::Scene& scene, const Framing& framing,
                              const FrameMotion& frame) {
  render::FrameView view;
  view.camera = frame.camera;
  view.quads = framing.quads;
  for (std::size_t i = 0; i < frame.positions.size(); ++i) {
    view.boxes.push_back(render::Box{.position = frame.positions[i],
                                     .orientation = frame.orientations[i],
                                     .size = scene.bodies[i].size,
                                     .color = scene.bodies[i].color,
                                     .solid = solid_of(scene.bodies[i].shape)});
  }
  return view;
}

Result<std::int64_t> SimulatedFrames::seek(std::int64_t frame) {
  const std::int64_t before = simulation_.step_count();
  // Not past the first state view(frame) needs: its trails' past comes first.
  const std::int64_t first_needed =
      overlays_ ? std::max<std::int64_t>(0, frame - overlays_->frames_of_history()) : frame;
  double t = static_cast<double>(first_needed) / scene_.fps;  // s, as view() computes it
  // A motion-blurred frame's first picture comes before its time.
  const common::MotionBlur& blur = scene_.render.motion_blur;
  if (blur.on()) {
    const double first_picture = blur.time(static_cast<double>(frame) / scene_.fps, 0, scene_.fps);
    t = std::min(t, std::max(0.0, first_picture));
  }
  const Result<std::vector<physics::BodyState>> states =
      checked_states_at(simulation_, scene_, t, stop_requested_);
  if (!states) return Error{states.error()};
  return simulation_.step_count() - before;
}

render::RenderSettings renderer_settings(const scene::Scene& scene, const Framing& framing) {
  render::RenderSettings settings{scene.render,
                                  overlays_need_font(scene) ? overlay_font(scene) : std::string(),
                                  overlays_need_lines(scene)};
  settings.ground = framing.ground;
  settings.round_solids =
      draws_joints(scene) ||
      std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const scene::BodySpec& b) {
        return solid_of(b.shape) != render::Solid::box && solid_of(b.shape) != render::Solid::hull;
      });
  // Each hull body's mesh, in body order (frame_view numbers them so).
  for (const scene::BodySpec& body : scene.bodies) {
    if (!body.hull) continue;
    const physics::ConvexHull& hull = *body.hull->hull;
    settings.hulls.push_back(
        {.corners = hull.vertices, .faces = hull.faces, .normals = hull.normals});
    settings.hull_sizes.push_back(body.size);
  }
  return settings;
}

}  // namespace tumble::view
