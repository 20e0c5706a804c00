// From a scene and body states to what the renderer draws: the glue between physics and render.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "physics/rigid_body.hpp"
#include "pipeline/frame_pipeline.hpp"
#include "render/frame.hpp"
#include "scene/scene.hpp"
#include "sim/simulation.hpp"
#include "view/overlay_view.hpp"

namespace tumble::view {

// Where the camera and ground go: as the scene writes them, or chosen from the whole motion.
struct Framing {
  // Position and look_at as written (the first key's with [[camera.keys]]), or framing every body
  // at all times; each frame's camera starts from it (app/camera_path.hpp).
  render::Camera camera;
  // [ground] as written. Without planes its height is as written, or just below the lowest point
  // any body reaches; with planes it is the floor plane (app/plane_view.hpp).
  render::Ground ground;
  std::vector<render::Quad> quads;      // the planes other than the floor, the same every frame
  std::vector<std::string> quad_names;  // each quad's plane's name
  int follow_index = -1;                // the followed body, or -1
  std::int64_t physics_steps = 0;       // steps the framing pass took; 0 when it was not needed
};

// The renderer's settings for `scene` drawn as `framing` places its ground: a font and the lines'
// shaders only for a scene whose overlays draw them.
render::RenderSettings renderer_settings(const scene::Scene& scene, const Framing& framing);

// Asked before each frame: true stops the render ("interrupted").
using StopRequested = std::function<bool()>;

// Every body's state at time t (s), from Simulation::states_at; an error when `stop_requested`
// says so, or when a body blew up (naming it, the time and the likely cause).
Result<std::vector<physics::BodyState>> checked_states_at(sim::Simulation& simulation,
                                                          const scene::Scene& scene, double t,
                                                          const StopRequested& stop_requested);

// True when the scene leaves the camera's position or look_at, or (without planes) the ground's
// height, to be chosen from the whole motion: only then does frame_scene run the physics.
bool framing_needs_motion(const scene::Scene& scene);

// The camera and ground of every frame. When framing_needs_motion, runs the scene's physics over
// all `frame_count` frame times first (the framing pass), which fails as checked_states_at does,
// or when a camera given only its position is at the centre of the motion it would look at.
Result<Framing> frame_scene(const scene::Scene& scene, std::int64_t frame_count,
                            const StopRequested& stop_requested);

// How a body of the shape is drawn.
render::Solid solid_of(scene::Shape shape);

// The frame for the body states at time t (s): the bodies, the springs and pushes acting, and
// the planes' quads.
render::FrameView frame_view(const scene::Scene& scene, const Framing& framing,
                             const std::vector<physics::BodyState>& states, double t);

// What one frame shows of the motion, kept for a file that replays it (a glTF,
// job/gltf_scene.hpp): the frame's time, its camera and every body's pose, in body order.
struct FrameMotion {
  double time = 0.0;  // s
  render::Camera camera;
  std::vector<physics::Vec3> positions;     // each body's centre, world frame (m)
  std::vector<physics::Quat> orientations;  // each body's body-to-world rotation
  // The overlays drawn in the scene (an html replay draws them too): the arrows of the vectors
  // and axes as the frame draws them, and each trail's point at this frame, in the order of the
  // scene's [[overlays]].
  std::vector<render::Arrow> arrows;
  std::vector<render::Vec3> trail_points;  // world frame (m)
};

// The camera, the planes and the bodies' boxes of a recorded frame: what render::view_extent
// needs for the renderer's reach at that frame (a glTF's ground and the replay's).
render::FrameView motion_view(const scene::Scene& scene, const Framing& framing,
                              const FrameMotion& frame);

// The frame loop's source for a render: frame k shows the bodies at t = k / fps (s), their states
// interpolated between the two physics steps around t, on a simulation of its own, and the
// scene's overlays computed from those same states.
class SimulatedFrames final : public pipeline::FrameSource {
 public:
  // `scene` and `framing` must outlive it.
  SimulatedFrames(const scene::Scene& scene, const Framing& framing, StopRequested stop_requested);
  Result<render::FrameView> view(std::int64_t frame) override;
  // Runs the physics up to frame `frame`'s time, or with trails to the oldest frame of their
  // past, drawing nothing: where a chunk starts, so that it pays only for the steps before its
  // first frame. Returns the steps taken; view(frame) then takes at most the trails' past and
  // shows what a render from frame 0 shows.
  Result<std::int64_t> seek(std::int64_t frame);
  const sim::Simulation& simulation() const { return simulation_; }
  // From now on, keeps each frame's camera and body poses as view() makes the frame (motion(),
  // in frame order): the very states and camera the frame is drawn from. They stay in memory to
  // the end: 56 bytes a body a frame.
  void record_motion() { recording_ = true; }
  const std::vector<FrameMotion>& motion() const { return motion_; }

 private:
  // Every joint's values at time t (s), just reached by the simulation (joint_view.hpp).
  std::vector<JointValue> joint_values_at(double t) const;

  const scene::Scene& scene_;
  const Framing& framing_;
  StopRequested stop_requested_;
  sim::Simulation simulation_;
  std::optional<OverlayItems> overlays_;  // only for a scene with overlays
  bool started_ = false;                  // whether a frame was asked for yet
  bool recording_ = false;                // record_motion() was called
  std::vector<FrameMotion> motion_;       // of each frame since, when recording
};

}  // namespace tumble::view
