// The scene hash changes with the scene file's bytes and with every override that changes the
// pictures, and with nothing else.
#include "job/scene_hash.hpp"

#include <gtest/gtest.h>

#include "io/sha256.hpp"

namespace tumble::job {
namespace {

TEST(SceneHash, IsTheSha256OfTheFileAndTheValuesAsRendered) {
  scene::Scene scene;
  scene.render.width = 64;
  scene.render.height = 36;
  scene.fps = 30;
  scene.render.msaa = 0;
  scene.duration = 0.5;
  EXPECT_EQ(scene_hash("name = \"a\"\n", scene),
            io::sha256_hex("name = \"a\"\n\n# as rendered: width=64 height=36 fps=30 msaa=0 "
                           "duration=0.5\n"));
}

TEST(SceneHash, ChangesWithTheFileAndWithEachOverrideButNotTheOutputs) {
  const scene::Scene scene;
  const std::string base = scene_hash("duration = 1.0\n", scene);
  EXPECT_NE(scene_hash("duration = 2.0\n", scene), base);
  for (const auto& change : std::vector<void (*)(scene::Scene&)>{
           [](scene::Scene& s) { s.render.width += 2; },
           [](scene::Scene& s) { s.render.height += 2; }, [](scene::Scene& s) { s.fps += 1; },
           [](scene::Scene& s) { s.render.msaa = 4; },
           [](scene::Scene& s) { s.duration += 1.0; }}) {
    scene::Scene changed = scene;
    change(changed);
    EXPECT_NE(scene_hash("duration = 1.0\n", changed), base);
  }
  scene::Scene other_outputs = scene;
  other_outputs.output.video = false;
  other_outputs.output.crf = 30;
  other_outputs.render.backend = common::Backend::egl;
  EXPECT_EQ(scene_hash("duration = 1.0\n", other_outputs), base);
}

}  // namespace
}  // namespace tumble::job
