// How far the renderer's picture of a frame reaches, worked out from the frame alone (no GL): the
// sphere of the boxes, the perspective's near and far distances and the ground's square. The
// renderer draws each frame with it; a glTF file (job/gltf_scene.hpp) gives its camera and ground
// the same reach, so that a viewer shows what the frames show.
#pragma once

#include "render/frame.hpp"

namespace tumble::render {

// From where the ground's colour starts to fade into the background, as a fraction of the
// square's half edge (ground.frag's u_fade_start): the ground is solid within it.
inline constexpr double kGroundFadeStart = 0.35;

struct ViewExtent {
  double radius = 1.0;           // of the sphere around the look-at point holding every box (m)
  double quad_reach = 0.0;       // of the quad corner farthest from the look-at point (m)
  double camera_distance = 0.0;  // from the camera to the point it looks at (m)
  double near = 0.01;            // the perspective's near and far distances from the camera (m)
  double far = 100.0;
  // The ground is a square in the plane y = its height, centred under the look-at point, this
  // far from its centre to each edge (m): big enough that its faded edge is never in view.
  double ground_half_extent = 30.0;
};

ViewExtent view_extent(const FrameView& view);

}  // namespace tumble::render
