// End-to-end tests of `tumble diff` on folders of frames, renders and videos, and of its JSON,
// JUnit and HTML outputs, run as a separate process the way CI runs it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "io/image.hpp"
#include "io/png_io.hpp"
#include "io/video_encoder.hpp"
#include "support/chromium_page.hpp"
#include "support/command_test.hpp"
#include "support/result_text.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::io::Image;
using tumble::testing::Outcome;
using tumble::testing::read_file;

// Frame k of a small moving picture: a bright square on a gradient, k pixels to the right.
Image moving_square(int k, int width = 64, int height = 48) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.row(y) + 3 * x;
      const bool square = x >= 10 + k && x < 26 + k && y >= 12 && y < 28;
      p[0] = static_cast<std::uint8_t>(square ? 230 : 30 + x);
      p[1] = static_cast<std::uint8_t>(square ? 200 : 40 + y);
      p[2] = static_cast<std::uint8_t>(square ? 60 : 90);
    }
  }
  return image;
}

std::string frame_name(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", k);
  return name;
}

// A slowly turning cube, turned `degrees` more about y at the start: 10 frames of 640x360.
std::string cube_scene(double degrees) {
  const double half = degrees * 3.14159265358979323846 / 360.0;
  char text[512];
  std::snprintf(text, sizeof text, R"(name = "cube"
duration = 0.25
[physics]
dt = 0.01
[[bodies]]
shape = "cube"
size = 1.0
mass = 1.0
orientation = [%.17g, 0.0, %.17g, 0.0]
angular_velocity = [0.3, 0.5, 0.0]
[render]
width = 640
height = 360
fps = 40
)",
                std::cos(half), std::sin(half));
  return text;
}

class DiffSequences : public tumble::testing::CommandTest {
 protected:
  // Frames 0 to count-1 of moving_square, from `shift_from` on with the square `shift` pixels
  // further right.
  void write_frames(const std::string& folder, int count, int shift_from = -1, int shift = 1) {
    fs::create_directories(dir_ / folder);
    for (int k = 0; k < count; ++k) {
      const Image frame = moving_square(k >= shift_from && shift_from >= 0 ? k + shift : k);
      ASSERT_EQ(::tumble::testing::error_text(
                    tumble::io::write_png(path(folder + "/" + frame_name(k)), frame)),
                "");
    }
  }

  void write_video(const std::string& name, int count) {
    tumble::io::VideoSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.fps = 30;
    std::string error;
    auto encoder = ::tumble::testing::value_or_empty(
        tumble::io::VideoEncoder::open(path(name), settings), error);
    ASSERT_TRUE(encoder) << error;
    for (int k = 0; k < count; ++k)
      ASSERT_EQ(::tumble::testing::error_text(encoder->add_frame(moving_square(k))), "");
    ASSERT_EQ(::tumble::testing::error_text(encoder->finish()), "");
  }

  void render(const std::string& root, double degrees) {
    const std::string scene = write("cube" + root + ".toml", cube_scene(degrees)).string();
    const Outcome run = tumble("render -q " + scene + " -o " + path(root));
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
};

TEST_F(DiffSequences, IdenticalFoldersMatch) {
  write_frames("a", 5);
  write_frames("b", 5);
  const Outcome run = tumble("diff " + path("a") + " " + path("b"));
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_EQ(run.out, "match: 0 of 5 frames differ (max, threshold 0 (channel levels 0-255))\n");
}

TEST_F(DiffSequences, AFrameMissingFromAFolderIsAMismatchThatSaysSo) {
  write_frames("a", 5);
  write_frames("b", 5);
  fs::remove(dir_ / "b" / frame_name(3));
  const Outcome run = tumble("diff " + path("a") + " " + path("b"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.out,
            "frame_00003.png: mismatch: missing from B\n"
            "mismatch: 1 of 5 frames differ; A has 5 frames, B has 4 (max, threshold 0 (channel "
            "levels 0-255))\n");
  // A range that leaves the missing frame out matches: only its frames are counted.
  EXPECT_EQ(tumble("diff --frames 0:3 " + path("a") + " " + path("b")).exit_code, 0);
  EXPECT_EQ(tumble("diff --frames 3:5 " + path("a") + " " + path("b")).exit_code, 1);
}

TEST_F(DiffSequences, OnlyTheChangedFramesAreReported) {
  write_frames("a", 6);
  write_frames("b", 6, 4);  // frames 4 and 5 have the square a pixel further right
  const Outcome run = tumble("diff " + path("a") + " " + path("b"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  // The square's left and right columns change: 2 columns of 16 pixels out of 64 x 48.
  EXPECT_NE(run.out.find("frame_00004.png: mismatch: 32 of 3072 pixels differ (1.04%)"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("frame_00005.png: mismatch: 32 of 3072"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("frame_00003.png"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("mismatch: 2 of 6 frames differ"), std::string::npos) << run.out;
  // --frames 0:4 leaves the changed frames out.
  EXPECT_EQ(tumble("diff --frames 0:4 " + path("a") + " " + path("b")).exit_code, 0);
  EXPECT_EQ(tumble("diff --frames 4:5 " + path("a") + " " + path("b")).exit_code, 1);
  // --max-pixels and --max-percent allow them.
  EXPECT_EQ(tumble("diff --max-pixels 32 " + path("a") + " " + path("b")).exit_code, 0);
  EXPECT_EQ(tumble("diff --max-pixels 31 " + path("a") + " " + path("b")).exit_code, 1);
  EXPECT_EQ(tumble("diff --max-percent 1.05 " + path("a") + " " + path("b")).exit_code, 0);
  EXPECT_EQ(tumble("diff --max-percent 1.0 " + path("a") + " " + path("b")).exit_code, 1);
}

TEST_F(DiffSequences, VideosOfDifferentLengthsAreAMismatchThatSaysSo) {
  write_video("ten.mp4", 10);
  write_video("eight.mp4", 8);
  const Outcome run =
      tumble("diff --metric perceptual " + path("ten.mp4") + " " + path("eight.mp4"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.out.find("frame 8: mismatch: missing from B\nframe 9: mismatch: missing from B\n"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("mismatch: 2 of 10 frames differ; A has 10 frames, B has 8"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(tumble("diff " + path("ten.mp4") + " " + path("ten.mp4")).exit_code, 0);
}

TEST_F(DiffSequences, AVideoMatchesTheFolderItWasEncodedFromPerceptuallyButNotExactly) {
  render("r", 0.0);
  const std::string video = path("r/cube/cube.mp4");
  const std::string folder = path("r/cube");  // a render's folder: its frames/ are compared
  // The PNGs brought to 4:2:0 as the video holds them, and what H.264's quantiser leaves not
  // counted: nothing is left at the default threshold, and no allowance is needed.
  const Outcome perceptual =
      tumble("diff --metric perceptual --json " + path("v.json") + " " + video + " " + folder);
  EXPECT_EQ(perceptual.exit_code, 0) << perceptual.out << perceptual.err;
  EXPECT_NE(perceptual.out.find("match: 0 of 10 frames differ"), std::string::npos)
      << perceptual.out;
  // The output says what was done to the PNGs, and so does the JSON.
  EXPECT_NE(perceptual.out.find("\nnote: B's frames converted to yuv420p BT.709 limited range and "
                                "back for comparison with video A; differences within A's H.264 "
                                "quantisation not counted (coarsest QP "),
            std::string::npos)
      << perceptual.out;
  const std::string json = read_file(dir_ / "v.json");
  EXPECT_NE(json.find("\"adaptation\": \"B's frames converted to yuv420p BT.709"),
            std::string::npos)
      << json;
  // Frames with pixels over the threshold say how many the quantisation explained.
  EXPECT_NE(json.find("\"quantised_pixels\": "), std::string::npos) << json;
  EXPECT_EQ(json.find("\"quantised_pixels\": null"), std::string::npos) << json;
  // The same the other way round.
  EXPECT_EQ(tumble("diff --metric perceptual " + folder + " " + video).exit_code, 0);
  // max compares levels as they are: the codec's changes all count.
  const Outcome exact = tumble("diff --metric max --threshold 0 " + video + " " + folder);
  EXPECT_EQ(exact.exit_code, 1) << exact.out << exact.err;
  EXPECT_NE(exact.out.find("mismatch: 10 of 10 frames differ"), std::string::npos) << exact.out;
  EXPECT_NE(exact.out.find("\nnote: B's frames converted to yuv420p BT.709 limited range and back "
                           "for comparison with video A\n"),
            std::string::npos)
      << exact.out;
}

TEST_F(DiffSequences, ACubeTurnedOneDegreeMoreFailsAtTheDefaultPerceptualThreshold) {
  render("straight", 0.0);
  render("turned", 1.0);
  render("again", 0.0);
  EXPECT_EQ(tumble("diff --metric perceptual " + path("straight/cube") + " " + path("again/cube"))
                .exit_code,
            0);
  const std::string turned = path("straight/cube") + " " + path("turned/cube");
  const Outcome run = tumble("diff --metric perceptual " + turned);
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_NE(run.out.find("mismatch: 10 of 10 frames differ"), std::string::npos) << run.out;
  // Against the video of the turned cube, what H.264 may have changed does not hide the turn.
  const Outcome video = tumble("diff --metric perceptual " + path("straight/cube") + " " +
                               path("turned/cube/cube.mp4"));
  EXPECT_EQ(video.exit_code, 1) << video.out << video.err;
  EXPECT_NE(video.out.find("mismatch: 10 of 10 frames differ"), std::string::npos) << video.out;
}

TEST_F(DiffSequences, JsonHoldsEveryFigureOfEveryFrame) {
  write_frames("a", 3);
  write_frames("b", 3, 2, 4);  // a shift by one pixel would pass as anti-aliasing
  const Outcome run = tumble("diff --metric perceptual --json " + path("d.json") + " " + path("a") +
                             " " + path("b"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  const std::string json = read_file(dir_ / "d.json");
  EXPECT_NE(json.find("\"metric\": \"perceptual\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"ignore_antialiasing\": true"), std::string::npos) << json;
  EXPECT_NE(json.find("\"adaptation\": null"), std::string::npos) << json;  // two folders
  EXPECT_NE(json.find("{\"index\": 0, \"name\": \"frame_00000.png\", \"match\": true, "
                      "\"problem\": null, \"figures\": {\"pixels\": 3072, \"differing_pixels\": 0, "
                      "\"antialiased_pixels\": 0, \"quantised_pixels\": null, "
                      "\"max_channel_difference\": 0, \"rms\": 0, "
                      "\"psnr_db\": null, \"ssim\": null}}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("{\"index\": 2, \"name\": \"frame_00002.png\", \"match\": false"),
            std::string::npos)
      << json;
}

// Parses the JUnit file with Python's XML parser and prints "tests failures name:failed ...".
std::string read_junit_back(const std::string& file) {
  const std::string script =
      "import sys, xml.etree.ElementTree as E\n"
      "root = E.parse(sys.argv[1]).getroot()\n"
      "suite = root.find('testsuite')\n"
      "cases = suite.findall('testcase')\n"
      "print(root.tag, suite.get('tests'), suite.get('failures'), len(cases), "
      "' '.join(c.get('name') + ':' + str(int(c.find('failure') is not None)) for c in cases))\n";
  const std::string command = "python3 -c \"$(cat <<'PY'\n" + script + "PY\n)\" '" + file + "'";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), &::pclose);
  std::string out;
  char buffer[256];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe.get())) out += buffer;
  return out;
}

TEST_F(DiffSequences, JunitHasOneTestCasePerFrameAndReadsBack) {
  if (std::system("command -v python3 >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "python3 is not installed (scripts/install-deps installs it): the JUnit file "
                    "is read back with its XML parser";
  }
  write_frames("a", 4);
  write_frames("b", 3, 2);
  const Outcome run =
      tumble("diff --junit " + path("junit.xml") + " " + path("a") + " " + path("b"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(read_junit_back(path("junit.xml")),
            "testsuites 5 3 5 frame_00000.png:0 frame_00001.png:0 frame_00002.png:1 "
            "frame_00003.png:1 frame count:1\n");
}

TEST_F(DiffSequences, TheHtmlReportShowsEveryImageInHeadlessChromium) {
  if (std::system("command -v chromium >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "chromium is not installed (apt-get install chromium; CI installs it): the "
                    "report is checked by loading it in headless Chromium";
  }
  write_frames("a", 4);
  write_frames("b", 4, 1, 4);
  const Outcome run = tumble("diff --metric perceptual --report " + path("report") + " " +
                             path("a") + " " + path("b"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  const std::string page = read_file(dir_ / "report" / "index.html");
  ASSERT_NE(page.find("</body>"), std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos);  // the report itself runs nothing
  EXPECT_EQ(page.find("http"), std::string::npos);     // and fetches nothing
  // A copy of the page beside it that counts, once loaded, the images that decoded.
  const std::string counter =
      "<script>addEventListener('load', () => { const all = [...document.images]; "
      "document.body.dataset.loaded = all.filter(i => i.complete && i.naturalWidth > 0).length + "
      "'/' + all.length; });</script>";
  const auto check = [&](const std::string& name, const std::string& extra) {
    std::string copy = page;
    copy.insert(copy.find("</body>"), extra + counter);
    write("report/" + name, copy);
    const std::string command =
        "chromium --headless --no-sandbox --disable-gpu "
        "--allow-file-access-from-files --dump-dom 'file://" +
        path("report/" + name) + "' 2>/dev/null";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), &::pclose);
    std::string dom;
    char buffer[4096];
    while (pipe && std::fgets(buffer, sizeof buffer, pipe.get())) dom += buffer;
    const std::size_t at = dom.find("data-loaded=\"");
    return at == std::string::npos ? std::string("no count in: ") + dom.substr(0, 200)
                                   : dom.substr(at + 13, dom.find('"', at + 13) - at - 13);
  };
  // Frames 1, 2 and 3 fail: three images each.
  EXPECT_EQ(check("check.html", ""), "9/9");
  // The check can fail: an image that is not there is not counted.
  EXPECT_EQ(check("broken.html", "<img src=\"absent.png\">"), "9/10");
}

// A stand-in for a render's html replay: a page that tells the page framing it that it ran.
std::string replay_page(const std::string& side) {
  return "<!DOCTYPE html>\n<html><body><p>replay of " + side + "</p><script>parent.postMessage('" +
         side + " ran', '*');</script></body></html>\n";
}

TEST_F(DiffSequences, TheReportShowsBothSidesReplaysWhenBothHaveOne) {
  write_frames("a", 3);
  write_frames("b", 3, 1);
  write("a/scene.html", replay_page("A"));
  write("b/scene.html", replay_page("B"));
  const Outcome run = tumble("diff --report " + path("report") + " " + path("a") + " " + path("b"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  // Copies, byte for byte, so that the report folder holds all it shows.
  EXPECT_EQ(read_file(dir_ / "report/replay-a.html"), replay_page("A"));
  EXPECT_EQ(read_file(dir_ / "report/replay-b.html"), replay_page("B"));
  const std::string page = read_file(dir_ / "report/index.html");
  EXPECT_NE(page.find("<h2>Replays</h2>"), std::string::npos);
  EXPECT_NE(page.find("<iframe src=\"replay-a.html\" title=\"expected (A): " + path("a")),
            std::string::npos);
  EXPECT_NE(page.find("<iframe src=\"replay-b.html\" title=\"actual (B): " + path("b")),
            std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos);  // the report itself still runs nothing

  const std::string missing = tumble::testing::chromium_missing();
  if (!missing.empty()) GTEST_SKIP() << missing << ": the frames are checked by loading the report";
  // A copy of the page that lists the replays that ran in its frames.
  std::string listening = page;
  listening.insert(listening.find("</body>"),
                   "<script>const ran = []; addEventListener('message', (e) => { ran.push(e.data); "
                   "document.body.dataset.ran = ran.sort().join(', '); });</script>");
  write("report/listening.html", listening);
  const tumble::testing::PageRun loaded = tumble::testing::run_page(
      "file://" + path("report/listening.html"),
      R"([{"wait": "document.body.dataset.ran && document.body.dataset.ran.includes(',') && document.body.dataset.ran"}])");
  ASSERT_EQ(loaded.exit_code, 0) << loaded.output;
  EXPECT_EQ(tumble::testing::step_result(loaded, 0)->string, "A ran, B ran");
  EXPECT_EQ(loaded.answer.find("errors")->text, "[]");
}

TEST_F(DiffSequences, TheReportHasNoReplaysUnlessBothSidesHaveOne) {
  write_frames("a", 2);
  write_frames("b", 2);
  write("a/scene.html", replay_page("A"));
  Outcome run = tumble("diff --report " + path("report") + " " + path("a") + " " + path("b"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_file(dir_ / "report/index.html").find("<h2>Replays"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "report/replay-a.html"));
  // Two pages in a folder: neither is known to be its replay.
  write("b/scene.html", replay_page("B"));
  write("b/other.html", replay_page("B"));
  run = tumble("diff --report " + path("report") + " " + path("a") + " " + path("b"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_file(dir_ / "report/index.html").find("<h2>Replays"), std::string::npos);
}

TEST_F(DiffSequences, ErrorsNameTheFileAndExitTwo) {
  write_frames("a", 3);
  fs::create_directories(dir_ / "empty");
  Outcome run = tumble("diff " + path("a") + " " + path("empty"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err,
            "tumble: " + path("empty") + ": folder holds no PNG frames (*.png, or frames/*.png)\n");
  write_frames("b", 3);
  write("b/" + frame_name(1), "not a png");
  run = tumble("diff " + path("a") + " " + path("b") + " --report " + path("report"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(path("b/" + frame_name(1)) + ": not a PNG file"), std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "report"));
  run = tumble("diff " + path("a") + " " + path("absent"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "tumble: " + path("absent") + ": no such file or folder\n");
  write("junk.mp4", "not a video");
  run = tumble("diff " + path("junk.mp4") + " " + path("a"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "tumble: " + path("junk.mp4") +
                         ": cannot read as a video: Invalid data found when processing input\n");
}

TEST_F(DiffSequences, OptionValuesOutsideTheMetricsRangeAreRefused) {
  write_frames("a", 1);
  const std::string inputs = path("a") + " " + path("a");
  Outcome run = tumble("diff --metric perceptual --threshold 1.5 " + inputs);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(
      run.err,
      "tumble: --threshold: expected a number from 0 to 1 for --metric perceptual, got 1.5\n");
  run = tumble("diff --metric ssim --max-pixels 3 " + inputs);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("apply to --metric max and perceptual, not ssim"), std::string::npos);
  run = tumble("diff --metric sharp " + inputs);
  EXPECT_EQ(run.exit_code, 2);
  run = tumble("diff --frames 3:1 " + inputs);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("expected A:B with 0 <= A < B, got 3:1"), std::string::npos) << run.err;
  run = tumble("diff --out " + path("x.png") + " " + inputs);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("use --report FOLDER"), std::string::npos) << run.err;
  run = tumble("diff --max-pixels 1 --max-percent 1 " + inputs);
  EXPECT_EQ(run.exit_code, 2);
}

}  // namespace
