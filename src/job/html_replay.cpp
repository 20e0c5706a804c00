#include "job/html_replay.hpp"

#include "io/atomic_file.hpp"
#include "io/glb_writer.hpp"
#include "io/replay_page.hpp"
#include "job/gltf_scene.hpp"
#include "job/replay_data.hpp"

namespace tumble::job {

Result<void> write_html_replay(const std::string& path, const ReplayAssets& assets,
                               const scene::Scene& scene, const view::Framing& framing,
                               const std::vector<view::FrameMotion>& motion,
                               std::int64_t first_frame) {
  const Result<std::vector<std::uint8_t>> glb =
      io::glb_bytes(gltf_scene(scene, framing, motion, std::string("tumble ") + TUMBLE_VERSION));
  if (!glb) return Error{path + ": " + glb.error()};
  const std::string data = replay_data_json(scene, framing, motion, first_frame);
  const Result<std::string> page = io::replay_page({.markup = assets.markup,
                                                    .three_js = assets.three_js,
                                                    .replay_js = assets.replay_js,
                                                    .data_json = data,
                                                    .glb = *glb});
  if (!page) return Error{path + ": " + page.error() + " (in " + assets.directory + ")"};
  return io::write_file_atomically(path, *page);
}

}  // namespace tumble::job
