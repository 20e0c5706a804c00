// examples/parallel/render.sh run as a user runs it (GNU Parallel with 2 jobs, this build's
// tumble), its joined render checked against a whole render of the same scene.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "examples/chunked_render.hpp"
#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;
using tumble::testing::shell_quoted;

class ParallelExample : public tumble::testing::CommandTest {
 protected:
  // render.sh SCENE CHUNKS OUTPUT with 2 jobs at once and `tumble` as the executable, run from the
  // test's folder.
  Outcome render_sh(const std::string& scene, int chunks, const std::string& output,
                    const std::string& tumble = TUMBLE_EXECUTABLE) {
    const std::string prefix = "cd " + shell_quoted(dir_.string()) +
                               " && JOBS=2 TUMBLE=" + shell_quoted(tumble) + " exec ";
    return wait(
        start(shell_quoted(scene) + " " + std::to_string(chunks) + " " + shell_quoted(output),
              prefix, shell_quoted(TUMBLE_SOURCE_DIR "/examples/parallel/render.sh")));
  }
};

TEST_F(ParallelExample, JoinsThreeChunksIntoTheWholeRender) {
  // Spaces in both paths: every word must reach tumble as it was given.
  const std::string scene = write("tiny scene.toml", tumble::testing::kTinyScene).string();
  const Outcome run = render_sh(scene, 3, path("farm out"));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  ASSERT_EQ(tumble("render -q " + shell_quoted(scene) + " -o " + path("whole")).exit_code, 0);

  tumble::testing::expect_joined_equals_whole(dir_ / "farm out/tiny", dir_ / "whole/tiny");
  // The chunk folders are gone: OUTPUT holds the render folder alone.
  EXPECT_EQ(tumble::testing::names_in(dir_ / "farm out"), std::vector<std::string>{"tiny"});
}

TEST_F(ParallelExample, AFailedChunkStopsTheRenderAndLeavesNothing) {
  const std::string scene = write("tiny.toml", tumble::testing::kTinyScene).string();
  // tumble for every call but chunk 2's render, which fails as a crashed machine would.
  const fs::path failing = write("failing-tumble",
                                 "#!/bin/sh\ncase \"$*\" in *'--chunk 2/3'*) "
                                 "echo 'chunk 2 failed' >&2; exit 3;; esac\nexec " +
                                     shell_quoted(TUMBLE_EXECUTABLE) + " \"$@\"\n");
  fs::permissions(failing, fs::perms::owner_all);

  const Outcome run = render_sh(scene, 3, path("out"), failing.string());
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("chunk 2 failed"), std::string::npos) << run.err;
  // OUTPUT did not exist before: the script made it and removes it again, chunk folders and all.
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(ParallelExample, ABadSceneStopsBeforeAnyFolderWithTumblesMessage) {
  std::string text = tumble::testing::kTinyScene;
  text.replace(text.find("duration"), 8, "durration");
  const std::string scene = write("misspelt.toml", text).string();
  const Outcome run = render_sh(scene, 3, path("out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("misspelt.toml:2:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("did you mean \"duration\""), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
