// A render's motion as a glTF scene (io::GltfScene, which io::glb_bytes writes as a binary
// glTF 2.0): what [output] formats = ["gltf"] writes as <scene>.glb, and what a page that replays
// the motion in a browser embeds. Call it with the frames view::SimulatedFrames recorded
// (record_motion(), then motion() once the frames are drawn), so that each pose is the very state
// its frame was drawn from.
//
// What it holds, in tumble's world frame, which is glTF's (metres, +y up, right-handed, so
// nothing is swizzled):
// - every body as a node, named as the body, showing its mesh as the renderer draws it
//   (render/solid_mesh.hpp: the same box, ball, capsule, cylinder and hull meshes, at the body's
//   size) in a material of the body's colour (bodies of one shape, size and colour share a mesh);
// - every visible plane but the floor as the quad the renderer draws (its `size` about its
//   point), and the floor (or [ground]) as the square of ground the frames show before it fades,
//   union over the frames; planes are double-sided and matte; no ground on a transparent
//   background, which draws none;
// - the camera: a perspective camera node at the first frame's pose, with that frame's vertical
//   field of view (glTF cannot animate it: [[camera.keys]] that change fov_degrees keep the
//   first), the picture's aspect ratio and the renderer's near and far distances over the frames;
// - one animation, "motion": a LINEAR translation and rotation channel per body sampling its pose
//   at every frame's time t = k / fps (s, the scene's clock: a render of frames A:B starts at
//   A / fps), and the camera's too when it moves (keys, orbit, follow).
// Colours: tumble's are sRGB-encoded, glTF's baseColorFactor is linear light, so each colour is
// decoded (render::linear_from_srgb, IEC 61966-2-1). Left out: springs, pushes and joints as
// drawn, overlays and texts, the ground's grid, lights and shadows.
#pragma once

#include <string>
#include <vector>

#include "io/glb_writer.hpp"
#include "scene/scene.hpp"
#include "view/scene_view.hpp"

namespace tumble::job {

// The glTF of `scene` drawn with `framing` over the frames of `motion` (in frame order; their
// bodies in the scene's order). `generator` is asset.generator ("tumble 0.1.0").
io::GltfScene gltf_scene(const scene::Scene& scene, const view::Framing& framing,
                         const std::vector<view::FrameMotion>& motion,
                         const std::string& generator);

}  // namespace tumble::job
