// What the html replay shows besides the glTF (web/replay.js reads it): the picture's size,
// colours and light, the ground, the camera of each frame, and the overlays each frame draws in
// the scene (the arrows of vectors and axes, the trails), all from the frames a render drew
// (view::FrameMotion), so that the page shows what the video shows. Texts and plots, drawn on the
// picture rather than in the scene, are left to the video.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "view/scene_view.hpp"

namespace tumble::job {

// One JSON object (numbers to 7 significant digits, the precision of the glTF's floats):
//   name, fps, first_frame, frames: frame first_frame + k is motion[k], at (first_frame + k) / fps
//   width, height, background (sRGB), transparent, shadows, light {direction, color, ambient}
//   ground: null, or {height, color, grid_spacing, half_extent} (render::view_extent's square)
//   camera {position, look_at, up, fov_degrees}: the first frame's
//   camera_path: null for a camera that stays, else {position, look_at, up, fov_degrees}, each
//     one value per frame (the vectors' x, y, z in turn)
//   arrows: [{color (sRGB and opacity), label, from, to}], each point one per frame
//   trails: [{color, length (s), points}], each trail's point one per frame
// `motion` is not empty, its frames consecutive from `first_frame`, each with the same arrows and
// trails.
std::string replay_data_json(const scene::Scene& scene, const view::Framing& framing,
                             const std::vector<view::FrameMotion>& motion,
                             std::int64_t first_frame);

}  // namespace tumble::job
