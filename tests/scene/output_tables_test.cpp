// [output] formats, gif_loop and poster_time, and [render] background = "transparent", as read
// from a scene file.
#include "scene/output_tables.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "scene/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tumble::scene {
namespace {

// A 1 s cube scene with `tables` appended, parsed; and its error.
Scene parsed(const std::string& tables) {
  return testing::parse_valid(testing::cube_scene(1.0) + tables);
}
std::string error_of(const std::string& tables) {
  return testing::error_of(testing::cube_scene(1.0) + tables);
}

TEST(OutputTables, DefaultsAreOneMp4LoopingGifAndOpaqueBackground) {
  const Scene scene = parsed("");
  EXPECT_EQ(scene.output.formats, std::vector<common::VideoFormat>{common::VideoFormat::mp4});
  EXPECT_TRUE(scene.output.gif_loop);
  EXPECT_FALSE(scene.output.poster_time);
  EXPECT_FALSE(scene.render.transparent);
}

TEST(OutputTables, FormatsAreReadInOrder) {
  const Scene scene = parsed(
      "[output]\nformats = [\"gif\", \"mp4\", \"webm\"]\ngif_loop = false\nposter_time = 0.25\n");
  EXPECT_EQ(scene.output.formats,
            (std::vector<common::VideoFormat>{common::VideoFormat::gif, common::VideoFormat::mp4,
                                              common::VideoFormat::webm}));
  EXPECT_FALSE(scene.output.gif_loop);
  EXPECT_EQ(scene.output.poster_time, 0.25);
}

TEST(OutputTables, BadFormatsAreErrorsAtTheirLine) {
  EXPECT_NE(error_of("[output]\nformats = [\"mp4\", \"avi\"]\n")
                .find("test.toml:7:19: output.formats: unknown format \"avi\""),
            std::string::npos)
      << error_of("[output]\nformats = [\"mp4\", \"avi\"]\n");
  EXPECT_NE(error_of("[output]\nformats = [\"gif\", \"gif\"]\n").find("lists \"gif\" twice"),
            std::string::npos);
  EXPECT_NE(error_of("[output]\nformats = []\n").find("names no format"), std::string::npos);
  EXPECT_NE(error_of("[output]\nformats = \"mp4\"\n").find("expected an array"), std::string::npos);
}

TEST(OutputTables, GltfIsAFormatBesideTheVideos) {
  const Scene both = parsed("[output]\nformats = [\"gltf\", \"mp4\"]\n");
  EXPECT_TRUE(both.output.gltf);
  EXPECT_EQ(both.output.formats, std::vector<common::VideoFormat>{common::VideoFormat::mp4});
  // Alone: no video, and no rule of the videos' (an odd size, a transparent background).
  const Scene alone = parsed(
      "[render]\nwidth = 161\nbackground = \"transparent\"\n[output]\nformats = [\"gltf\"]\n");
  EXPECT_TRUE(alone.output.gltf);
  EXPECT_TRUE(alone.output.formats.empty());
  EXPECT_FALSE(parsed("").output.gltf);
  // It is something to write when frames and video are off.
  EXPECT_FALSE(
      parsed("[output]\nformats = [\"gltf\"]\nframes = false\nvideo = false\n").output.frames);
  EXPECT_NE(error_of("[output]\nformats = [\"mp4\"]\nframes = false\nvideo = false\n")
                .find("nothing to write"),
            std::string::npos);
}

TEST(OutputTables, GltfListedTwiceOrMisspeltIsAnErrorAtItsLine) {
  const std::string twice = error_of("[output]\nformats = [\"gltf\", \"mp4\", \"gltf\"]\n");
  EXPECT_NE(twice.find("test.toml:7:27: output.formats: lists \"gltf\" twice"), std::string::npos)
      << twice;
  const std::string misspelt = error_of("[output]\nformats = [\"glb\"]\n");
  EXPECT_NE(misspelt.find("test.toml:7:12: output.formats: unknown format \"glb\" (\"mp4\", "
                          "\"webm\", \"gif\", \"gltf\" or \"html\")"),
            std::string::npos)
      << misspelt;
}

TEST(OutputTables, HtmlIsAFormatBesideTheVideosAndTheGltf) {
  const Scene all = parsed("[output]\nformats = [\"html\", \"mp4\", \"gltf\"]\n");
  EXPECT_TRUE(all.output.html);
  EXPECT_TRUE(all.output.gltf);
  EXPECT_EQ(all.output.formats, std::vector<common::VideoFormat>{common::VideoFormat::mp4});
  EXPECT_FALSE(parsed("").output.html);
  const Scene alone =
      parsed("[render]\nwidth = 161\n[output]\nformats = [\"html\"]\nframes = false\n");
  EXPECT_TRUE(alone.output.html);
  EXPECT_FALSE(alone.output.gltf);
  EXPECT_TRUE(alone.output.formats.empty());
  const std::string twice = error_of("[output]\nformats = [\"html\", \"html\"]\n");
  EXPECT_NE(twice.find("test.toml:7:20: output.formats: lists \"html\" twice"), std::string::npos)
      << twice;
}

TEST(OutputTables, TransparentIsABackgroundAndAColourStillIsOne) {
  const Scene clear =
      parsed("[render]\nbackground = \"transparent\"\n[output]\nformats = [\"webm\"]\n");
  EXPECT_TRUE(clear.render.transparent);
  const Scene coloured = parsed("[render]\nbackground = \"#ff0000\"\n");
  EXPECT_FALSE(coloured.render.transparent);
  EXPECT_EQ(coloured.render.background, common::Color(1, 0, 0));
  // With the default MP4, the loader blames the background (the file has no formats key).
  EXPECT_NE(error_of("[render]\nbackground = \"transparent\"\n")
                .find("test.toml:7:14: render.background: a transparent background needs a "
                      "format with alpha"),
            std::string::npos)
      << error_of("[render]\nbackground = \"transparent\"\n");
}

}  // namespace
}  // namespace tumble::scene
