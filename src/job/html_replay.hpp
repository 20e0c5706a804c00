// <scene>.html, what [output] formats = ["html"] writes: the render replayed in a browser, one
// page that needs nothing at view time (no network, no file beside it). It holds the render's
// glTF (job/gltf_scene.hpp, as <scene>.glb would hold it) as base64, the data of the overlays and
// camera (job/replay_data.hpp) and three.js with the player (job/replay_assets.hpp), put together
// by io::replay_page. The same render gives the same bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "job/replay_assets.hpp"
#include "scene/scene.hpp"
#include "view/scene_view.hpp"

namespace tumble::job {

// Writes the page of the frames `motion` recorded (frame first_frame on) to `path` atomically;
// the error names the path, or what of the assets cannot make a page.
Result<void> write_html_replay(const std::string& path, const ReplayAssets& assets,
                               const scene::Scene& scene, const view::Framing& framing,
                               const std::vector<view::FrameMotion>& motion,
                               std::int64_t first_frame);

}  // namespace tumble::job
