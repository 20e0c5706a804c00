// From a scene and body states to what the renderer draws: the glue between physics and render.
#pragma once

#include <vector>

#include "physics/rigid_body.hpp"
#include "render/frame.hpp"
#include "scene/scene.hpp"

#include <functional>
#include <stdexcept>

#include "sim/simulation.hpp"

namespace tumble::app {

// Where the camera and ground go when the scene leaves them out: chosen from the whole motion.
struct Framing {
  render::Camera camera;  // position and look_at as written, or framing every body at all times
  // [ground] as written. Without planes its height is as written, or just below the lowest point
  // any body reaches; with planes it is the floor plane (app/plane_view.hpp).
  render::Ground ground;
  std::vector<render::Quad> quads;  // the planes other than the floor, the same every frame
  render::Vec3 follow_offset;       // camera position - look_at, kept when following a body
  int follow_index = -1;            // the followed body, or -1
};

// Thrown when a render must stop before its last frame; what() says why.
struct RenderStopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Asked before each frame: true stops the render (RenderStopped "interrupted").
using StopRequested = std::function<bool()>;

// Every body's state at time t (s), from Simulation::states_at. Throws RenderStopped when
// `stop_requested` says so, or when a body blew up (naming it, the time and the likely cause).
std::vector<physics::BodyState> checked_states_at(sim::Simulation& simulation,
                                                  const scene::Scene& scene, double t,
                                                  const StopRequested& stop_requested);

// Runs the scene's physics over all frame times (cheap next to rendering) to frame it. Throws
// RenderStopped as checked_states_at does.
Framing frame_scene(const scene::Scene& scene, std::int64_t frame_count,
                    const StopRequested& stop_requested);

// The frame for the body states at time t (s): the bodies, the springs and pushes acting, and
// the planes' quads.
render::FrameView frame_view(const scene::Scene& scene, const Framing& framing,
                             const std::vector<physics::BodyState>& states, double t);

}  // namespace tumble::app
