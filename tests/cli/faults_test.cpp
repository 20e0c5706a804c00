// Faults a user or a machine can cause, through the real executable: interruption, an unwritable
// output folder, a full disk, a body that blows up, limits, and the exit code of every command.
// Whatever happens, no output may be left looking complete and no earlier output half replaced.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/command_test.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::testing::Outcome;
using tumble::testing::read_file;

// Small frames, quick to render; `duration` seconds at 30 frames/s.
std::string spin_scene(double duration) {
  return "name = \"spin\"\nduration = " + std::to_string(duration) + R"(
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
angular_velocity = [0.0, 2.0, 1.0]
[render]
width = 160
height = 120
fps = 30
)";
}

class Faults : public tumble::testing::CommandTest {
 protected:
  // Every file below `root`, hidden ones too.
  int files_below(const fs::path& root) const {
    int count = 0;
    if (!fs::exists(root)) return 0;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      count += entry.is_regular_file() ? 1 : 0;
    }
    return count;
  }

  // Waits (up to a minute) until process `pid` is tumble and catches `signal` (its handler is
  // installed, as /proc/PID/status's SigCgt mask shows): a signal sent sooner would kill it
  // outright, and on a loaded machine tumble may take over a second to get there.
  static bool wait_until_catching(pid_t pid, int signal) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    const std::string status = "/proc/" + std::to_string(pid) + "/status";
    while (std::chrono::steady_clock::now() < deadline) {
      std::ifstream in(status);
      bool tumble = false;  // not the shell that is about to exec it
      for (std::string line; std::getline(in, line);) {
        if (line.rfind("Name:", 0) == 0) tumble = line.find("tumble") != std::string::npos;
        if (line.rfind("SigCgt:", 0) != 0) continue;
        const unsigned long long caught = std::stoull(line.substr(7), nullptr, 16);
        if (tumble && (caught >> (signal - 1) & 1)) return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  // Waits (up to a minute) until a render into `root` has written `frames` PNG frames.
  bool wait_for_frames(const fs::path& root, int frames) const {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (std::chrono::steady_clock::now() < deadline) {
      if (files_below(root) >= frames) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  // A complete earlier render of 15 frames in out/spin, to see that faults leave it as it was.
  void render_earlier_output() {
    const Outcome first = tumble("render " + write("short.toml", spin_scene(0.5)).string() +
                                 " -o " + path("out") + " -q");
    ASSERT_EQ(first.exit_code, 0) << first.err;
    earlier_video_ = read_file(dir_ / "out/spin/spin.mp4");
    ASSERT_FALSE(earlier_video_.empty());
  }
  void expect_earlier_output_untouched() {
    EXPECT_EQ(read_file(dir_ / "out/spin/spin.mp4"), earlier_video_);
    // Frames, the MP4, report.json, poster.png and contact_sheet.png.
    EXPECT_EQ(files_below(dir_ / "out"), 15 + 4);
    for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
      EXPECT_EQ(entry.path().filename(), "spin") << "left behind: " << entry.path();
    }
  }

  std::string earlier_video_;
};

TEST_F(Faults, SigintStopsARenderCleanlyAndLeavesNoVideo) {
  const pid_t render = start("render " + write("long.toml", spin_scene(600.0)).string() + " -o " +
                             path("out") + " -q");
  ASSERT_TRUE(wait_for_frames(dir_ / "out", 3)) << "the render never got going";
  ASSERT_EQ(::kill(render, SIGINT), 0);
  const Outcome run = wait(render);
  EXPECT_EQ(run.exit_code, 130) << run.err;
  EXPECT_NE(run.err.find("tumble: stopped by SIGINT after "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(" of 18000 frames"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out/spin/spin.mp4"));
  EXPECT_EQ(files_below(dir_ / "out"), 0) << "an interrupted render left files";
}

TEST_F(Faults, SigtermDuringARenderKeepsTheEarlierOutputWhole) {
  render_earlier_output();
  const pid_t render = start("render " + write("long.toml", spin_scene(600.0)).string() + " -o " +
                             path("out") + " -q");
  ASSERT_TRUE(wait_for_frames(dir_ / "out", 15 + 4 + 3)) << "the render never got going";
  ASSERT_EQ(::kill(render, SIGTERM), 0);
  const Outcome run = wait(render);
  EXPECT_EQ(run.exit_code, 143) << run.err;
  EXPECT_NE(run.err.find("stopped by SIGTERM"), std::string::npos) << run.err;
  expect_earlier_output_untouched();
}

// `timeout` sends its signal to tumble and then to the process group: the second one, at once,
// is the same request and must not cut the clean-up short.
TEST_F(Faults, ARepeatedSignalStillStopsCleanly) {
  const pid_t render = start("render " + write("long.toml", spin_scene(600.0)).string() + " -o " +
                             path("out") + " -q");
  ASSERT_TRUE(wait_for_frames(dir_ / "out", 3)) << "the render never got going";
  ASSERT_EQ(::kill(render, SIGTERM), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(render, SIGTERM);  // may find it gone already
  const Outcome run = wait(render);
  EXPECT_EQ(run.exit_code, 143) << run.err;
  EXPECT_NE(run.err.find("tumble: stopped by SIGTERM after "), std::string::npos) << run.err;
  EXPECT_EQ(files_below(dir_ / "out"), 0) << "an interrupted render left files";
}

// A write blocked on a FIFO nobody reads fails with EINTR when the signal comes: a stop (130),
// not a write failure (2).
TEST_F(Faults, SigintStopsASimulationBlockedOnAFullPipe) {
  const std::string fifo = path("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const pid_t simulate =
      start("simulate " + write("short.toml", spin_scene(20.0)).string() + " --out " + fifo);
  // Opened (without waiting for the writer), never read: the pipe fills.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  ASSERT_TRUE(wait_until_catching(simulate, SIGINT)) << "the simulation never got going";
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // time to fill the pipe
  ASSERT_EQ(::kill(simulate, SIGINT), 0);
  const Outcome run = wait(simulate);
  ::close(reader);
  EXPECT_EQ(run.exit_code, 130) << run.err;
  EXPECT_NE(run.err.find("tumble: stopped by SIGINT"), std::string::npos) << run.err;
}

TEST_F(Faults, SigintStopsASimulationWithoutWritingItsFile) {
  // 10^8 steps: far longer than the test waits.
  const fs::path scene = write("long.toml", R"(duration = 10000.0
[physics]
dt = 0.0001
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
)");
  const pid_t simulate =
      start("simulate " + scene.string() + " --every 1000000 --out " + path("states.csv"));
  ASSERT_TRUE(wait_until_catching(simulate, SIGINT)) << "the simulation never got going";
  ASSERT_EQ(::kill(simulate, SIGINT), 0);
  const Outcome run = wait(simulate);
  EXPECT_EQ(run.exit_code, 130) << run.err;
  EXPECT_NE(run.err.find("tumble: stopped by SIGINT at t = "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("states.csv was not written"), std::string::npos) << run.err;
  EXPECT_EQ(files_below(dir_), 1) << "only the scene file may be there";
}

// Root is not held back by a folder's permissions: take its power to override them away.
std::string without_root_override() {
  return ::geteuid() == 0 ? "setpriv --bounding-set=-dac_override,-dac_read_search " : "";
}

TEST_F(Faults, AnUnwritableOutputFolderIsAClearErrorBeforeAnyWork) {
  fs::create_directories(dir_ / "locked");
  fs::permissions(dir_ / "locked", fs::perms::owner_read | fs::perms::owner_exec);
  const std::string scene = write("short.toml", spin_scene(0.5)).string();
  const Outcome render =
      tumble("render " + scene + " -o " + path("locked/out"), "exec " + without_root_override());
  fs::permissions(dir_ / "locked", fs::perms::owner_all);
  EXPECT_EQ(render.exit_code, 2) << render.err;
  EXPECT_NE(
      render.err.find("cannot create output folder " + path("locked/out") + ": Permission denied"),
      std::string::npos)
      << render.err;
  EXPECT_EQ(files_below(dir_ / "locked"), 0);
}

TEST_F(Faults, AnOutputFolderThatIsAFileIsAClearError) {
  write("taken", "a file, not a folder");
  const Outcome run =
      tumble("render " + write("short.toml", spin_scene(0.5)).string() + " -o " + path("taken"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("cannot create output folder " + path("taken")), std::string::npos)
      << run.err;
  EXPECT_EQ(read_file(dir_ / "taken"), "a file, not a folder");
}

TEST_F(Faults, AFileSizeLimitFailsTheRenderAndKeepsTheEarlierOutput) {
  render_earlier_output();
  // 64 blocks of 512 bytes: a few of the longer render's frames fit, then writes fail as they
  // would on a full disk (tumble ignores SIGXFSZ and reports the error).
  const Outcome run = tumble(
      "render " + write("long.toml", spin_scene(10.0)).string() + " -o " + path("out") + " -q",
      "ulimit -f 64; exec ");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("File too large"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("render failed after "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(path("out/spin") + " was left as it was"), std::string::npos) << run.err;
  expect_earlier_output_untouched();
}

TEST_F(Faults, AFullDiskFailsTheRenderWithNothingLeftBehind) {
  // A 256 kB tmpfs, mounted in a user and mount namespace of the test's own.
  if (std::system("unshare --user --map-root-user --mount true 2>/dev/null") != 0) {
    GTEST_SKIP() << "this machine does not allow user namespaces for a small tmpfs";
  }
  fs::create_directories(dir_ / "small");
  const std::string scene = write("long.toml", spin_scene(10.0)).string();
  const std::string command =
      "unshare --user --map-root-user --mount sh -c 'mount -t tmpfs -o size=256k none " +
      path("small") + " && " + std::string(TUMBLE_EXECUTABLE) + " render " + scene + " -o " +
      path("small") + " -q; echo \"exit $?\"; ls -A " + path("small") + "' >" + path("log") +
      " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string log = read_file(dir_ / "log");
  EXPECT_NE(log.find("No space left on device"), std::string::npos) << log;
  EXPECT_NE(log.find("exit 2\n"), std::string::npos) << log;
  EXPECT_EQ(log.substr(log.find("exit 2\n") + 7), "") << "files left on the full disk: " << log;
}

TEST_F(Faults, ANewRenderReplacesTheWholeEarlierOutput) {
  render_earlier_output();
  // Fewer frames than before: none of the earlier render's later frames may stay beside them.
  const Outcome run = tumble("render " + write("short.toml", spin_scene(0.5)).string() + " -o " +
                             path("out") + " --frames 0:5 -q");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The frames, report.json, the MP4 and contact_sheet.png (poster.png shows a frame not rendered).
  EXPECT_EQ(files_below(dir_ / "out"), 5 + 3);
  EXPECT_TRUE(fs::exists(dir_ / "out/spin/frames/frame_00004.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out/spin/frames/frame_00005.png"));
}

TEST_F(Faults, AFolderThatIsNotATumbleRenderIsNeverReplaced) {
  write("notes.txt", "");
  fs::create_directories(dir_ / "out/spin");
  std::ofstream(dir_ / "out/spin/notes.txt") << "mine";
  const Outcome run =
      tumble("render " + write("short.toml", spin_scene(0.5)).string() + " -o " + path("out"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("exists and is not a tumble render"), std::string::npos) << run.err;
  EXPECT_EQ(read_file(dir_ / "out/spin/notes.txt"), "mine");
}

// "\u0000" once reached the file system as "", so that the hidden folder was the output root
// itself, and a failed render emptied it.
TEST_F(Faults, ASceneCannotTouchFilesBesideItsOwnFolder) {
  fs::create_directories(dir_ / "out/other_render");
  write("out/keep.txt", "mine");
  write("out/other_render/report.json", "{}");
  const Outcome run =
      tumble("render " +
             write("nul.toml", spin_scene(0.5) + "[output]\ndirectory = \"\\u0000\"\n").string() +
             " -o " + path("out"));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("output.directory: must be a relative folder"), std::string::npos)
      << run.err;
  EXPECT_EQ(read_file(dir_ / "out/keep.txt"), "mine");
  EXPECT_EQ(read_file(dir_ / "out/other_render/report.json"), "{}");
  EXPECT_EQ(files_below(dir_ / "out"), 2);
}

// The scene's folder is swapped as a whole, which a link cannot be: refused before the work.
TEST_F(Faults, ALinkAsTheScenesFolderIsRefusedBeforeAnyWork) {
  render_earlier_output();
  fs::rename(dir_ / "out/spin", dir_ / "real");
  fs::create_directory_symlink(dir_ / "real", dir_ / "out/spin");
  const Outcome run = tumble("render " + write("long.toml", spin_scene(10.0)).string() + " -o " +
                             path("out") + " -q");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find(path("out/spin") + " is a symbolic link"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "out/spin"));
  EXPECT_EQ(read_file(dir_ / "real/spin.mp4"), earlier_video_);
}

// A render only replaces a folder that holds nothing but a render's own files, and never writes
// into another render's folder: scene "a/b" inside scene "a" would be deleted by a new "a".
TEST_F(Faults, ARenderNeverReplacesOrEntersAnotherRendersFiles) {
  const auto scene_in = [&](const std::string& name, const std::string& directory) {
    return write(name + ".toml", spin_scene(0.5) + "[output]\ndirectory = \"" + directory + "\"\n")
        .string();
  };
  ASSERT_EQ(tumble("render " + scene_in("outer", "a") + " -o " + path("out") + " -q").exit_code, 0);
  const Outcome inner = tumble("render " + scene_in("inner", "a/b") + " -o " + path("out"));
  EXPECT_EQ(inner.exit_code, 2) << inner.err;
  EXPECT_NE(inner.err.find(path("out/a") + " is a render's folder"), std::string::npos)
      << inner.err;
  // Nor with -o pointing into it, at any depth, or through a link that leads there.
  fs::create_directory_symlink(dir_ / "out/a/frames", dir_ / "link");
  for (const std::string& root : {path("out/a"), path("out/a/frames"), path("link")}) {
    const Outcome below = tumble("render " + scene_in("outer", "a") + " -o " + root);
    EXPECT_EQ(below.exit_code, 2) << below.err;
    EXPECT_NE(below.err.find(path("out/a") + " is a render's folder"), std::string::npos)
        << below.err;
  }
  write("out/a/frames/notes.txt", "mine");
  const Outcome again = tumble("render " + scene_in("outer", "a") + " -o " + path("out"));
  EXPECT_EQ(again.exit_code, 2) << again.err;
  EXPECT_NE(
      again.err.find(path("out/a") + " holds frames/notes.txt, which a render does not write"),
      std::string::npos)
      << again.err;
  EXPECT_EQ(read_file(dir_ / "out/a/frames/notes.txt"), "mine");
}

// The folder is checked again just before the swap: a file put there during the render stays.
TEST_F(Faults, AFolderFilledDuringTheRenderIsNotReplaced) {
  const pid_t render = start("render " + write("long.toml", spin_scene(20.0)).string() + " -o " +
                             path("out") + " -q");
  ASSERT_TRUE(wait_for_frames(dir_ / "out", 3)) << "the render never got going";
  fs::create_directories(dir_ / "out/spin");
  write("out/spin/important.txt", "precious");
  const Outcome run = wait(render);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find(path("out/spin") + " exists and is not a tumble render"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(read_file(dir_ / "out/spin/important.txt"), "precious");
  EXPECT_EQ(files_below(dir_ / "out"), 1);
}

// The new render is in place; the old one, swapped out, cannot be deleted (its frames folder is
// read-only): the run says where it is instead of leaving it unmentioned.
TEST_F(Faults, AnOldRenderThatCannotBeDeletedIsReported) {
  render_earlier_output();
  fs::permissions(dir_ / "out/spin/frames", fs::perms::owner_read | fs::perms::owner_exec);
  const Outcome run = tumble(
      "render " + write("short.toml", spin_scene(0.5)).string() + " -o " + path("out") + " -q",
      "exec " + without_root_override());
  fs::permissions(dir_ / "out", fs::perms::owner_all);
  for (const auto& entry : fs::recursive_directory_iterator(dir_ / "out")) {
    if (entry.is_directory()) fs::permissions(entry.path(), fs::perms::owner_all);
  }
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("tumble: warning: the earlier output, moved aside to " +
                         path("out/.spin.partial-")),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("Permission denied); delete it by hand"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::exists(dir_ / "out/spin/report.json"));
}

// `bench pipeline` times its renders in a scratch folder of its own: a "pipeline" folder of the
// user's beside its report is left alone, and nothing else is left behind.
TEST_F(Faults, BenchPipelineLeavesTheUsersFilesAlone) {
  fs::create_directories(dir_ / "out/pipeline");
  write("out/pipeline/thesis.tex", "mine");
  const Outcome run =
      tumble("bench pipeline --frames 2 --width 64 --height 48 --msaa 1 --out " + path("out"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_file(dir_ / "out/pipeline/thesis.tex"), "mine");
  EXPECT_NE(read_file(dir_ / "out/pipeline.md").find("| pipelined |"), std::string::npos);
  EXPECT_EQ(files_below(dir_ / "out"), 2);
}

// With standard error closed, the MP4 would get descriptor 2, and the progress text would be
// written into the video: the same bytes as a render with standard error open.
TEST_F(Faults, AClosedStandardErrorDoesNotEndUpInTheVideo) {
  const std::string scene = write("short.toml", spin_scene(2.0)).string();
  const std::string closed =
      std::string(TUMBLE_EXECUTABLE) + " render " + scene + " -o " + path("closed") + " 2>&-";
  ASSERT_EQ(std::system(closed.c_str()), 0);
  ASSERT_EQ(tumble("render -q " + scene + " -o " + path("open")).exit_code, 0);
  const std::string video = read_file(dir_ / "open/spin/spin.mp4");
  EXPECT_FALSE(video.empty());
  EXPECT_TRUE(read_file(dir_ / "closed/spin/spin.mp4") == video) << "the videos differ";
}

// Writing through /dev/stdout (a stream, not a file to replace), and through a link to a file.
TEST_F(Faults, SimulateWritesThroughDevStdoutAndLinks) {
  const std::string scene = write("short.toml", spin_scene(0.5)).string();
  // Standard output is a file here (the fixture's): appended to through the stream, not replaced.
  write("log.txt", "earlier lines\n");
  const std::string append = std::string(TUMBLE_EXECUTABLE) + " simulate " + scene +
                             " --every 10 --out /dev/stdout >>" + path("log.txt");
  EXPECT_EQ(std::system(append.c_str()), 0);
  EXPECT_EQ(read_file(dir_ / "log.txt").rfind("earlier lines\nt,body,", 0), 0u)
      << read_file(dir_ / "log.txt");
  fs::create_directories(dir_ / "real");
  write("real/states.csv", "old");
  fs::create_symlink("real/states.csv", dir_ / "link.csv");
  const Outcome through_link = tumble("simulate " + scene + " --out " + path("link.csv"));
  EXPECT_EQ(through_link.exit_code, 0) << through_link.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.csv"));
  EXPECT_EQ(read_file(dir_ / "real/states.csv").rfind("t,body,", 0), 0u);
}

TEST_F(Faults, ABodyThatBlowsUpStopsTheRenderNamingItTheTimeAndTheStableStep) {
  // k dt = 100 / s × 0.05 s = 5, beyond explicit Euler's limit of 2: |v| grows 4× a step.
  const fs::path scene = write("stiff.toml", R"(duration = 2.0
[physics]
dt = 0.05
integrator = "euler"
[[bodies]]
name = "slab"
shape = "cube"
size = 1.0
mass = 1.0
velocity = [1.0, 0.0, 0.0]
[[bodies.forces]]
kind = "linear_damping"
coefficient = 100.0
[render]
width = 160
height = 120
)");
  for (const std::string& command : {"render " + scene.string() + " -o " + path("out") + " -q",
                                     "simulate " + scene.string() + " --out " + path("s.csv")}) {
    const Outcome run = tumble(command);
    EXPECT_EQ(run.exit_code, 2) << command << ": " << run.err;
    // |v| = 4^n passes 1e8 m/s at step 14 (4^14 = 2.7e8): t = 0.7 s.
    EXPECT_NE(run.err.find("tumble: body \"slab\" blew up at t = 0.7 s (step 14 of dt = 0.05 s): "
                           "its speed reached 2.68e+08 m/s"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("Likely cause: linear damping makes the momentum decay at k = c/m = "
                           "100 /s: k·dt = 5 is beyond euler's stability limit k·dt <= 2"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("use dt <= 0.016 s"), std::string::npos) << run.err;
  }
  EXPECT_EQ(files_below(dir_), 1) << "only the scene file may be there";
}

TEST_F(Faults, CommandLineSizesAreHeldToTheSameLimits) {
  const std::string scene = write("short.toml", spin_scene(0.5)).string();
  const Outcome big =
      tumble("render " + scene + " -o " + path("out") + " --width 8192 --height 8192");
  EXPECT_EQ(big.exit_code, 2) << big.err;
  EXPECT_NE(big.err.find("8192 × 8192 is 67108864 pixels, more than the limit of 35389440"),
            std::string::npos)
      << big.err;
  const Outcome huge = tumble("render " + scene + " -o " + path("out") + " --width 100000");
  EXPECT_EQ(huge.exit_code, 2) << huge.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(Faults, TooManyBodiesAreRefusedAtTheFirstOneTooMany) {
  std::string text = "duration = 1.0\nbodies = [\n";
  for (int i = 0; i < 1001; ++i) {
    text +=
        "  { name = \"b" + std::to_string(i) + "\", shape = \"cube\", size = 1.0, mass = 1.0 },\n";
  }
  const fs::path scene = write("crowd.toml", text + "]\n");
  const Outcome run = tumble("check " + scene.string());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  // Body 1000 (the 1001st) is on line 1003.
  EXPECT_NE(run.err.find("crowd.toml:1003:3: bodies: 1001 bodies, more than the limit of 1000"),
            std::string::npos)
      << run.err;
}

TEST_F(Faults, AnOversizedOrMissingSceneFileIsAClearError) {
  const fs::path big = dir_ / "big.toml";
  std::ofstream(big) << "duration = 1.0\n" << std::string(17 * 1024 * 1024, '#') << "\n";
  const Outcome too_big = tumble("check " + big.string());
  EXPECT_EQ(too_big.exit_code, 2);
  EXPECT_NE(too_big.err.find("big.toml: scene file is larger than the limit of 16 MB"),
            std::string::npos)
      << too_big.err;
  const Outcome folder = tumble("simulate " + dir_.string());
  EXPECT_EQ(folder.exit_code, 2);
  EXPECT_NE(folder.err.find("is a folder, not a scene file"), std::string::npos) << folder.err;
  const Outcome missing = tumble("render " + path("absent.toml") + " -o " + path("out"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("absent.toml: cannot open scene file: No such file or directory"),
            std::string::npos)
      << missing.err;
}

// 0 on success, 1 on a failed comparison, 2 on bad usage or input; never a signal.
TEST_F(Faults, EveryCommandExitsWithTwoOnBadUsage) {
  const std::string scene = write("short.toml", spin_scene(0.5)).string();
  for (const std::string& arguments :
       std::vector<std::string>{"",
                                std::string("frobnicate"),
                                std::string("render"),
                                "render " + scene + " --fps 0",
                                "render " + scene + " --frames 9:3",
                                "render " + scene + " --png-compression huge",
                                std::string("simulate"),
                                "simulate " + scene + " --every 0",
                                std::string("diff a.png"),
                                "diff " + path("a.png") + " " + path("b.png"),
                                std::string("diff x y --threshold 300"),
                                std::string("bench"),
                                std::string("bench pipeline --width 1"),
                                std::string("bench pipeline --width 65"),
                                std::string("bench accuracy --bogus"),
                                std::string("bench accuracy --out ''"),
                                "render " + scene + " --frames 99999999999999999999:3",
                                "render " + scene + " --frames 1:",
                                "render " + scene + " -o ''",
                                "simulate " + scene + " --out ''",
                                "diff " + path("a.png") + " " + path("a.png") + " --out ''",
                                std::string("check"),
                                std::string("check a.toml b.toml")}) {
    const Outcome run = tumble(arguments);
    EXPECT_EQ(run.exit_code, 2) << "tumble " << arguments << ": " << run.err;
    EXPECT_FALSE(run.err.empty()) << "tumble " << arguments << " said nothing";
  }
  EXPECT_FALSE(fs::exists(dir_ / "output"));
}

}  // namespace
