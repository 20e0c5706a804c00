// From a scene and body states to what the renderer draws: the glue between physics and render.
#pragma once

#include <vector>

#include "physics/rigid_body.hpp"
#include "render/frame.hpp"
#include "scene/scene.hpp"

namespace tumble::app {

// Where the camera and ground go when the scene leaves them out: chosen from the whole motion.
struct Framing {
  render::Camera camera;  // position and look_at as written, or framing every body at all times
  double ground_height;   // as written, or just below the lowest point any body reaches (m)
  render::Vec3 follow_offset;  // camera position - look_at, kept when following a body
  int follow_index = -1;       // the followed body, or -1
};

// Runs the scene's physics over all frame times (cheap next to rendering) to frame it.
Framing frame_scene(const scene::Scene& scene, std::int64_t frame_count);

// The frame for the body states at time t (s): the bodies, plus springs and active pushes.
render::FrameView frame_view(const scene::Scene& scene, const Framing& framing,
                             const std::vector<physics::BodyState>& states, double t);

}  // namespace tumble::app
