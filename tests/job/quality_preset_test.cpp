// --quality: each preset gives exactly its size and frame rate through make_render_job (the one
// place overrides are applied and checked), and an explicit --width, --height or --fps wins.
#include "job/quality_preset.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "job/render_job.hpp"
#include "scene/scene_loader.hpp"

namespace tumble::job {
namespace {

scene::Scene cube() {
  const Result<scene::Scene> loaded = scene::parse_scene(
      "duration = 1.0\n[[bodies]]\nshape = \"cube\"\nsize = 1.0\nmass = 1.0\n", "cube.toml");
  return *loaded;
}

struct Expected {
  const char* name;
  int width, height, fps;
};

TEST(QualityPreset, EachPresetGivesExactlyItsSizeAndRate) {
  const Expected expected[] = {{"low", 854, 480, 15},
                               {"medium", 1280, 720, 30},
                               {"high", 1920, 1080, 60},
                               {"production", 2560, 1440, 60},
                               {"4k", 3840, 2160, 60}};
  for (const Expected& e : expected) {
    RenderOptions options;
    options.quality = e.name;
    const Result<RenderJob> job = make_render_job(cube(), options);
    ASSERT_TRUE(job) << e.name << ": " << job.error();
    EXPECT_EQ(job->scene.render.width, e.width) << e.name;
    EXPECT_EQ(job->scene.render.height, e.height) << e.name;
    EXPECT_EQ(job->scene.fps, e.fps) << e.name;
    EXPECT_EQ(job->frame_count, e.fps) << e.name;  // 1 s
  }
}

TEST(QualityPreset, ExplicitWidthHeightAndFpsWin) {
  RenderOptions options;
  options.quality = "4k";
  options.width = 640;
  options.fps = 24;
  const Result<RenderJob> job = make_render_job(cube(), options);
  ASSERT_TRUE(job) << job.error();
  EXPECT_EQ(job->scene.render.width, 640);
  EXPECT_EQ(job->scene.render.height, 2160);
  EXPECT_EQ(job->scene.fps, 24);
}

TEST(QualityPreset, AnUnknownNameIsAnErrorListingTheNames) {
  RenderOptions options;
  options.quality = "ultra";
  const Result<RenderJob> job = make_render_job(cube(), options);
  ASSERT_FALSE(job);
  EXPECT_EQ(job.error(), "--quality: unknown preset \"ultra\" (low, medium, high, production, 4k)");
}

}  // namespace
}  // namespace tumble::job
