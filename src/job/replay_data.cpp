#include "job/replay_data.hpp"

#include <cassert>
#include <cstdio>
#include <functional>
#include <variant>

#include "io/json_text.hpp"
#include "render/view_extent.hpp"

namespace tumble::job {
namespace {

// 7 significant digits: the page draws in float, as the glTF stores.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.7g", value);
  return text;
}

std::string vector(const Eigen::VectorXd& values) {
  std::string text = "[";
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    text += (i ? ", " : "") + number(values[i]);
  }
  return text + "]";
}

// One value per frame: `of(frame)`'s 3 components in turn.
std::string per_frame(const std::vector<view::FrameMotion>& motion,
                      const std::function<render::Vec3(const view::FrameMotion&)>& of) {
  std::string text = "[";
  for (std::size_t k = 0; k < motion.size(); ++k) {
    const render::Vec3 value = of(motion[k]);
    text +=
        (k ? ", " : "") + number(value.x()) + ", " + number(value.y()) + ", " + number(value.z());
  }
  return text + "]";
}

std::string camera_json(const render::Camera& camera) {
  return "{\"position\": " + vector(camera.position) + ", \"look_at\": " + vector(camera.look_at) +
         ", \"up\": " + vector(camera.up) + ", \"fov_degrees\": " + number(camera.fov_degrees) +
         "}";
}

bool camera_moves(const std::vector<view::FrameMotion>& motion) {
  const render::Camera& first = motion.front().camera;
  for (const view::FrameMotion& frame : motion) {
    const render::Camera& camera = frame.camera;
    if (camera.position != first.position || camera.look_at != first.look_at ||
        camera.up != first.up || camera.fov_degrees != first.fov_degrees) {
      return true;
    }
  }
  return false;
}

std::string camera_path_json(const std::vector<view::FrameMotion>& motion) {
  if (!camera_moves(motion)) return "null";
  std::string fov = "[";
  for (std::size_t k = 0; k < motion.size(); ++k) {
    fov += (k ? ", " : "") + number(motion[k].camera.fov_degrees);
  }
  return "{\"position\": " +
         per_frame(motion, [](const view::FrameMotion& m) { return m.camera.position; }) +
         ", \"look_at\": " +
         per_frame(motion, [](const view::FrameMotion& m) { return m.camera.look_at; }) +
         ", \"up\": " + per_frame(motion, [](const view::FrameMotion& m) { return m.camera.up; }) +
         ", \"fov_degrees\": " + fov + "]}";
}

std::string ground_json(const scene::Scene& scene, const view::Framing& framing,
                        const std::vector<view::FrameMotion>& motion) {
  const render::Ground& ground = framing.ground;
  if (!ground.enabled || scene.render.transparent) return "null";
  const render::ViewExtent extent =
      render::view_extent(view::motion_view(scene, framing, motion.front()));
  return "{\"height\": " + number(ground.height) + ", \"color\": " + vector(ground.color) +
         ", \"grid_spacing\": " + number(ground.grid_spacing) +
         ", \"half_extent\": " + number(extent.ground_half_extent) + "}";
}

std::string arrows_json(const std::vector<view::FrameMotion>& motion) {
  std::string text = "[";
  const std::size_t count = motion.front().arrows.size();
  for (std::size_t a = 0; a < count; ++a) {
    const render::Arrow& first = motion.front().arrows[a];
    text += std::string(a ? ",\n  " : "\n  ") + "{\"color\": " + vector(first.color) +
            ", \"label\": " + io::json_string(first.label) + ", \"from\": " +
            per_frame(motion, [a](const view::FrameMotion& m) { return m.arrows[a].from; }) +
            ", \"to\": " +
            per_frame(motion, [a](const view::FrameMotion& m) { return m.arrows[a].to; }) + "}";
  }
  return text + "]";
}

std::string trails_json(const scene::Scene& scene, const std::vector<view::FrameMotion>& motion) {
  std::string text = "[";
  std::size_t t = 0;  // the trail's index among the trails
  for (const scene::OverlaySpec& overlay : scene.overlays) {
    const auto* trail = std::get_if<scene::TrailOverlay>(&overlay);
    if (!trail) continue;
    text += std::string(t ? ",\n  " : "\n  ") + "{\"color\": " + vector(trail->color) +
            ", \"length\": " + number(trail->length) + ", \"points\": " +
            per_frame(motion, [t](const view::FrameMotion& m) { return m.trail_points[t]; }) + "}";
    ++t;
  }
  return text + "]";
}

}  // namespace

std::string replay_data_json(const scene::Scene& scene, const view::Framing& framing,
                             const std::vector<view::FrameMotion>& motion,
                             std::int64_t first_frame) {
  assert(!motion.empty());
  for ([[maybe_unused]] const view::FrameMotion& frame : motion) {
    assert(frame.arrows.size() == motion.front().arrows.size());
    assert(frame.trail_points.size() == motion.front().trail_points.size());
  }
  const common::RenderSettings& render = scene.render;
  return "{\"name\": " + io::json_string(scene.name) + ", \"fps\": " + std::to_string(scene.fps) +
         ", \"first_frame\": " + std::to_string(first_frame) +
         ", \"frames\": " + std::to_string(motion.size()) +
         ",\n \"width\": " + std::to_string(render.width) +
         ", \"height\": " + std::to_string(render.height) +
         ", \"background\": " + vector(render.background) +
         ", \"transparent\": " + (render.transparent ? "true" : "false") +
         ", \"shadows\": " + (render.shadows ? "true" : "false") +
         ",\n \"light\": {\"direction\": " + vector(render.light.direction) +
         ", \"color\": " + vector(render.light.color) +
         ", \"ambient\": " + number(render.light.ambient) +
         "},\n \"ground\": " + ground_json(scene, framing, motion) +
         ",\n \"camera\": " + camera_json(motion.front().camera) +
         ",\n \"camera_path\": " + camera_path_json(motion) +
         ",\n \"arrows\": " + arrows_json(motion) +
         ",\n \"trails\": " + trails_json(scene, motion) + "}\n";
}

}  // namespace tumble::job
