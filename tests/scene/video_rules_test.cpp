// The video rules and the frame count, in their one home: the loader, `tumble render` and
// `tumble bench pipeline` all ask broken_video_rule and frame_count.
#include "scene/video_rules.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "scene/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tumble::scene {
namespace {

using testing::parse_valid;

constexpr const char* kCube = R"(duration = 0.5
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
[render]
width = 160
height = 120
fps = 30
)";

TEST(VideoRules, FrameCountIsDurationTimesFpsToTheNearestFrame) {
  Scene scene = parse_valid(kCube);
  EXPECT_EQ(frame_count(scene), 15);
  scene.duration = 0.51;  // 15.3 frames
  EXPECT_EQ(frame_count(scene), 15);
  scene.duration = 0.4833;  // 14.499 frames
  EXPECT_EQ(frame_count(scene), 14);
  scene.fps = 60;
  scene.duration = 1.0 / 120.0;  // half a frame: the first
  EXPECT_EQ(frame_count(scene), 1);
}

TEST(VideoRules, ALoadedSceneKeepsThemAndAChangedOneNamesTheKeyItBroke) {
  const Scene scene = parse_valid(kCube);
  EXPECT_FALSE(broken_video_rule(scene));

  Scene odd = scene;
  odd.render.height = 121;
  ASSERT_TRUE(broken_video_rule(odd));
  EXPECT_EQ(broken_video_rule(odd)->keys, std::vector<std::string>{"render.height"});
  EXPECT_NE(broken_video_rule(odd)->problem.find("must be even"), std::string::npos);
  odd.output.video = false;  // frames alone may be odd
  EXPECT_FALSE(broken_video_rule(odd));

  Scene no_frame = scene;
  no_frame.fps = 1;
  no_frame.duration = 0.4;
  ASSERT_TRUE(broken_video_rule(no_frame));
  EXPECT_EQ(broken_video_rule(no_frame)->keys, std::vector<std::string>{"render.fps"});
  EXPECT_EQ(broken_video_rule(no_frame)->fallback, "duration");

  Scene huge = scene;
  huge.render.width = 8192;
  huge.render.height = 8192;
  ASSERT_TRUE(broken_video_rule(huge));
  EXPECT_NE(broken_video_rule(huge)->problem.find("8192 × 8192 is 67108864 pixels"),
            std::string::npos);

  Scene nothing = scene;
  nothing.output.frames = false;
  nothing.output.video = false;
  ASSERT_TRUE(broken_video_rule(nothing));
  EXPECT_EQ(broken_video_rule(nothing)->keys, std::vector<std::string>{"output.video"});
}

// In a file the rule is blamed on the first of its keys the file has, else its fallback.
TEST(VideoRules, TheLoaderBlamesTheFirstKeyTheFileHas) {
  const Result<Scene> without_fps = parse_scene(
      "duration = 0.001\n[[bodies]]\nshape = \"cube\"\n"
      "size = 1.0\nmass = 1.0\n[physics]\ndt = 0.001\n",
      "test.toml");
  ASSERT_TRUE(!without_fps.ok());
  EXPECT_NE(without_fps.error().find(": duration: duration × fps gives no frame"),
            std::string::npos)
      << without_fps.error();
}

TEST(VideoRules, EachFormatBringsItsOwnSizeRule) {
  Scene scene = parse_valid(kCube);
  scene.render.width = 161;
  scene.output.formats = {common::VideoFormat::gif};  // palette indices: any size
  EXPECT_FALSE(broken_video_rule(scene));
  scene.output.formats = {common::VideoFormat::gif, common::VideoFormat::webm};
  ASSERT_TRUE(broken_video_rule(scene));
  EXPECT_NE(broken_video_rule(scene)->problem.find("must be even for VP9"), std::string::npos);
  scene.output.formats = {common::VideoFormat::mp4};
  EXPECT_NE(broken_video_rule(scene)->problem.find("must be even for H.264"), std::string::npos);
}

TEST(VideoRules, ATransparentBackgroundNeedsEveryVideoToCarryAlpha) {
  Scene scene = parse_valid(kCube);
  scene.render.transparent = true;
  ASSERT_TRUE(broken_video_rule(scene));  // the default MP4 has no alpha
  EXPECT_EQ(broken_video_rule(scene)->keys,
            (std::vector<std::string>{"output.formats", "render.background"}));
  scene.output.formats = {common::VideoFormat::webm};
  EXPECT_FALSE(broken_video_rule(scene));
  scene.output.formats = {common::VideoFormat::webm, common::VideoFormat::gif};
  EXPECT_TRUE(broken_video_rule(scene));
  scene.output.video = false;  // RGBA PNG frames only
  EXPECT_FALSE(broken_video_rule(scene));
}

TEST(VideoRules, PosterFrameIsTheMiddleOrTheNearestToPosterTime) {
  Scene scene = parse_valid(kCube);  // 15 frames at 30 fps
  EXPECT_EQ(poster_frame(scene), 7);
  scene.output.poster_time = 0.2;  // 6 frames in
  EXPECT_EQ(poster_frame(scene), 6);
  scene.output.poster_time = 0.21;  // 6.3 frames: the nearest is 6
  EXPECT_EQ(poster_frame(scene), 6);
  scene.output.poster_time = 0.5;  // the end of the scene, past the last frame's 14/30 s
  EXPECT_EQ(poster_frame(scene), 14);
  EXPECT_FALSE(broken_video_rule(scene));
  scene.output.poster_time = 0.6;
  ASSERT_TRUE(broken_video_rule(scene));
  EXPECT_EQ(broken_video_rule(scene)->keys, std::vector<std::string>{"output.poster_time"});
}

}  // namespace
}  // namespace tumble::scene
