// From a scene's [[overlays]] and a frame's body states to the renderer's plain items: texts
// with their live values formatted, arrows, trails and axes. Only a scene with overlays gets
// here (SimulatedFrames), so one without runs the code it ran before overlays existed.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "physics/rigid_body.hpp"
#include "render/font.hpp"
#include "render/frame.hpp"
#include "scene/scene.hpp"
#include "view/joint_view.hpp"
#include "view/overlay_values.hpp"
#include "view/plot_view.hpp"

namespace tumble::view {

// Whether the scene's overlays draw text (texts, arrow labels): then the renderer needs a font.
bool overlays_need_font(const scene::Scene& scene);
// Whether they draw lines or arrows: then the renderer builds their shaders.
bool overlays_need_lines(const scene::Scene& scene);

// The fontconfig family the scene's text is drawn in: [render] font, else render's default.
std::string overlay_font(const scene::Scene& scene);

// One warning for each character of the overlays' fixed text (the texts around their
// placeholders, the labels) that `font` lacks: it is drawn as a gap, never as the font's
// missing-glyph box. None when `font` is null (a render without text).
std::vector<std::string> missing_character_warnings(const scene::Scene& scene,
                                                    const render::Font* font);

class OverlayItems {
 public:
  explicit OverlayItems(const scene::Scene& scene);  // `scene` must outlive it

  // Frames before the first frame drawn whose states the trails and plots need: a render that
  // starts at frame A record()s frames A - frames_of_history() .. A - 1 first (not before 0), so
  // that a chunk of a video draws the same trail and plot as the whole video.
  std::int64_t frames_of_history() const;

  // Takes in the bodies' drawn states at time t (s) for the trails, and the values of the steps
  // around t (StepPair) and of the joints there for the plots. Times increase from call to call.
  void record(const std::vector<physics::BodyState>& states, const StepPair& steps, double t,
              std::span<const JointValue> joints = {});

  // Adds the overlays' items for frame `frame` at time t (s), whose drawn states were just
  // record()ed: drawn where `states` put the bodies, showing the values of the physics steps
  // around t (`steps`, overlay_values.hpp) and the joints' values there (joint_view.hpp).
  // `contacts` are every body's contact force (contact_forces) when needs_contacts().
  void add_to(const std::vector<physics::BodyState>& states, const StepPair& steps, double t,
              std::int64_t frame, render::FrameView& view, std::span<const JointValue> joints = {},
              std::span<const BodyContact> contacts = {}) const;

  // Whether an overlay shows a contact force: then add_to needs every body's.
  bool needs_contacts() const;

 private:
  struct TrailPoint {
    double time;             // s
    physics::Vec3 position;  // world frame (m)
  };
  const scene::Scene& scene_;
  std::vector<std::deque<TrailPoint>> trails_;  // per overlay; empty but for trails
  std::vector<std::deque<PlotSample>> plots_;   // per overlay; empty but for plots
};

}  // namespace tumble::view
