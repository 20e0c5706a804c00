// `tumble render` with [output] formats = ["html"]: the replay page of the dropped cube, opened in
// headless Chromium with no network, loads three.js, plays, and at t = 2 s shows the cube where
// the MP4's frame at 2 s has it (same camera, same size); its overlays are the frames' own; two
// renders write the same bytes; and without three.js the render says what to run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "io/base64.hpp"
#include "io/png_io.hpp"
#include "support/chromium_page.hpp"
#include "support/command_test.hpp"
#include "support/scene_text.hpp"
#include "support/video_reader.hpp"

namespace tumble {
namespace {

namespace fs = std::filesystem;
using testing::Outcome;
using testing::PageRun;
using testing::read_file;
using testing::run_page;
using testing::step_result;

// The centre of the cube's pixels: those clearly red (its #d9592f-ish faces lit or not, not the
// grey floor, its grey shadow or the blue-grey sky), and how many there are.
struct Blob {
  double x = 0.0, y = 0.0;  // px from the top-left corner
  long pixels = 0;
};

Blob cube_in(const io::Image& image) {
  Blob blob;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.row(y) + 3 * x;
      if (p[0] > 110 && p[0] - std::max(p[1], p[2]) > 60) {
        blob.x += x;
        blob.y += y;
        ++blob.pixels;
      }
    }
  }
  if (blob.pixels > 0) {
    blob.x /= static_cast<double>(blob.pixels);
    blob.y /= static_cast<double>(blob.pixels);
  }
  return blob;
}

// The text of a JSON value the driver answered, for messages.
std::string text_of(const io::JsonValue* value) {
  return value ? value->text : "(none)";
}

class HtmlReplay : public testing::CommandTest {
 protected:
  void SetUp() override {
    CommandTest::SetUp();
    missing_ = testing::chromium_missing();
  }

  // Renders `scene` (named `name`) with `arguments` into `folder`; the page's path.
  std::string render(const std::string& scene, const std::string& arguments,
                     const std::string& folder, const std::string& name = "dropped_cube") {
    const Outcome run = tumble("render -q " + scene + " " + arguments + " -o " + path(folder));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return path(folder + "/" + name + "/" + name + ".html");
  }

  std::string missing_;
};

constexpr const char* kDroppedCube = TUMBLE_SOURCE_DIR "/scenes/dropped_cube.toml";

// The steps that load the page and make its 3D view exactly W×H CSS pixels: the window as wide,
// and as high as the view plus the controls under it.
std::string sized_steps(int width, int height) {
  return "{\"viewport\": [" + std::to_string(width) + ", " + std::to_string(height + 200) +
         "]}, {\"wait\": \"document.body.dataset.ready || document.body.dataset.error\"}, "
         "{\"viewport\": [" +
         std::to_string(width) + ", \"" + std::to_string(height) +
         " + document.getElementById('controls').offsetHeight\"]}";
}

TEST_F(HtmlReplay, TheDroppedCubeAtTwoSecondsIsWhereTheMp4HasIt) {
  const std::string page = render(kDroppedCube,
                                  "--width 640 --height 360 --format mp4,html "
                                  "--no-frames",
                                  "out");
  const std::string html = read_file(page);
  ASSERT_GT(html.size(), 500000u);  // three.js is in it
  // Nothing to fetch: no script, style or link by URL (three.js's own strings name the XHTML
  // namespace, which is no fetch; the run below counts what the page asked for).
  for (const char* fetch : {"src=\"http", "src='http", "href=\"http", "href='http", "url(http",
                            "<link", "<script src", "<script type=\"module\""}) {
    EXPECT_EQ(html.find(fetch), std::string::npos) << fetch;
  }
  if (!missing_.empty()) GTEST_SKIP() << missing_ << ": the page is checked in it";

  std::string steps = "[";
  steps += sized_steps(640, 360);
  steps +=
      ", {\"eval\": \"[tumbleReplay.time(), tumbleReplay.playing(), typeof "
      "TumbleThree.THREE.REVISION]\"}";
  steps += ", {\"screenshot\": \"" + path("page.png") + "\", \"clip\": \"#stage canvas\"}";
  steps +=
      ", {\"data_url\": \"tumbleReplay.snapshot()\", \"to\": \"" + path("snapshot.png") + "\"}]";
  const PageRun run = run_page("file://" + page + "#t=2&paused", steps);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(text_of(step_result(run, 1)), "\"true\"");  // data-ready, not data-error
  EXPECT_EQ(text_of(step_result(run, 3)), "[2,false,\"string\"]");
  // The page alone, from file://: nothing over the network, nothing else from disk.
  EXPECT_EQ(run.answer.find("requests")->text, "[\"file://" + page + "\"]");
  EXPECT_EQ(run.answer.find("errors")->text, "[]");

  const testing::DecodedVideo video =
      testing::read_video(path("out/dropped_cube/dropped_cube.mp4"));
  ASSERT_EQ(video.error, "");
  ASSERT_GT(video.pictures.size(), 120u);
  ASSERT_NEAR(video.pictures[120].time, 2.0, 1e-9);
  const Blob expected = cube_in(video.pictures[120].rgb);
  ASSERT_GT(expected.pixels, 2000);  // the cube is about 75 px a side at 640x360

  for (const char* picture : {"page.png", "snapshot.png"}) {
    const Result<io::Image> shot = io::read_png(path(picture));
    ASSERT_TRUE(shot) << shot.error();
    ASSERT_EQ(shot->width, 640) << picture;
    ASSERT_EQ(shot->height, 360) << picture;
    const Blob found = cube_in(*shot);
    const double offset = std::hypot(found.x - expected.x, found.y - expected.y);  // px
    std::printf(
        "%s: the cube's centre at (%.1f, %.1f) px, the MP4's at (%.1f, %.1f): %.2f px "
        "apart; %ld pixels against %ld\n",
        picture, found.x, found.y, expected.x, expected.y, offset, found.pixels, expected.pixels);
    EXPECT_LT(offset, 10.0) << picture;
    // The same cube: its area within a quarter of the video's (the video draws a dark frame on
    // its edges, the page does not).
    EXPECT_NEAR(static_cast<double>(found.pixels) / static_cast<double>(expected.pixels), 1.0, 0.25)
        << picture;
  }
}

TEST_F(HtmlReplay, ThePagePlaysTheAnimation) {
  if (!missing_.empty()) GTEST_SKIP() << missing_ << ": the page is run in it";
  const std::string page =
      render(kDroppedCube, "--width 320 --height 180 --format html --no-frames", "out");
  const std::string cube = "tumbleReplay.scene.getObjectByName('cube')";
  const PageRun run = run_page(
      "file://" + page + "#paused",
      "[{\"wait\": \"document.body.dataset.ready || document.body.dataset.error\"}, "
      "{\"eval\": \"[tumbleReplay.time(), " +
          cube +
          ".position.y]\"}, "
          // Ten animation frames of playing: whatever they last, the clock and the cube move on.
          "{\"eval\": \"tumbleReplay.play(), new Promise((done) => { let n = 0; const next = () "
          "=> ++n < 10 ? requestAnimationFrame(next) : done([tumbleReplay.time() > 0, " +
          cube + ".position.y < 3, tumbleReplay.playing()]); requestAnimationFrame(next); })\"}]");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(text_of(step_result(run, 0)), "\"true\"");
  EXPECT_EQ(text_of(step_result(run, 1)), "[0,3]");  // paused at the start: 3 m up
  EXPECT_EQ(text_of(step_result(run, 2)), "[true,true,true]");
  EXPECT_EQ(run.answer.find("errors")->text, "[]");
}

// The overlays drawn in the scene come from the frames: at a frame's time the velocity arrow
// starts at the cube's centre (the glTF's node, as the page animates it) and points along its
// velocity, the trail ends at the tracked corner, and each axis is its length long.
TEST_F(HtmlReplay, TheOverlaysAreTheFramesOwn) {
  if (!missing_.empty()) GTEST_SKIP() << missing_ << ": the page is run in it";
  write("slide.toml", R"(name = "slide"
duration = 1.0
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 1.0
velocity = [1.0, 0.5, 0.0]
angular_velocity = [0.0, 1.0, 0.0]
[camera]
position = [4.0, 3.0, 6.0]
look_at = [0.0, 0.0, 0.0]
[ground]
height = -1.0
[render]
width = 320
height = 180
fps = 20
[[overlays]]
kind = "vector"
body = "cube"
quantity = "velocity"
scale = 0.5
label = "v"
[[overlays]]
kind = "trail"
body = "cube"
point = [0.5, 0.5, 0.5]
[[overlays]]
kind = "axes"
body = "cube"
length = 1.5
)");
  const std::string page = render(path("slide.toml"), "--format html --no-frames", "out", "slide");
  const std::string probe =
      "(() => { const arrows = []; let trail = null; tumbleReplay.scene.traverse((o) => { "
      "if (o.type === 'ArrowHelper') arrows.push(o); if (o.isLine && o.geometry.attributes.color) "
      "trail = o; }); const cube = tumbleReplay.scene.getObjectByName('cube'); "
      "const d = (a, b) => Math.round(1e4 * a.distanceTo(b)) / 1e4; "
      "const THREE = TumbleThree.THREE; const v = new THREE.Vector3(0, 1, 0).applyQuaternion("
      "arrows[0].quaternion); const corner = new THREE.Vector3(0.5, 0.5, 0.5).applyMatrix4("
      "cube.matrixWorld); const p = trail.geometry.attributes.position; const end = new "
      "THREE.Vector3().fromBufferAttribute(p, p.count - 1); "
      "const label = document.querySelector('#labels span'); const canvas = "
      "document.querySelector('#stage canvas'); const length = arrows[0].line.scale.y + "
      "arrows[0].cone.scale.y; const tip = arrows[0].position.clone().addScaledVector(v, "
      "length).project(tumbleReplay.camera); const x = canvas.offsetLeft + (tip.x + 1) / 2 * "
      "canvas.clientWidth; const y = canvas.offsetTop + (1 - tip.y) / 2 * canvas.clientHeight; "
      "return [arrows.length, d(arrows[0].position, cube.position), "
      "Math.round(1e4 * v.dot(new THREE.Vector3(1, 0.5, 0).normalize())) / 1e4, "
      "Math.round(1e4 * arrows[1].line.scale.y + 1e4 * arrows[1].cone.scale.y) / 1e4, "
      "d(end, corner), label.textContent, Math.round(Math.hypot(parseFloat(label.style.left) - "
      "x, parseFloat(label.style.top) - y))]; })()";
  const PageRun run =
      run_page("file://" + page + "#t=0.5&paused",
               "[{\"wait\": \"document.body.dataset.ready || document.body.dataset.error\"}, "
               "{\"eval\": \"" +
                   probe + "\"}]");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(text_of(step_result(run, 0)), "\"true\"");
  // 4 arrows (the velocity, the three axes); the velocity's from the centre along (1, 0.5, 0)
  // (no gravity: it keeps it); the x axis 1.5 m long (shaft and head); the trail at the corner;
  // the velocity's label at its tip on the picture (0 px from it).
  EXPECT_EQ(text_of(step_result(run, 1)), "[4,0,1,1.5,0,\"v\",0]");
  EXPECT_EQ(run.answer.find("errors")->text, "[]");
}

// The same bytes from two renders, and the glTF in the page is the .glb a render writes.
TEST_F(HtmlReplay, TwoRendersWriteTheSamePageHoldingTheGlb) {
  const std::string first =
      render(kDroppedCube, "--width 160 --height 90 --format html,gltf --no-frames", "a");
  const std::string second =
      render(kDroppedCube, "--width 160 --height 90 --format html --no-frames", "b");
  const std::string page = read_file(first);
  ASSERT_GT(page.size(), 500000u);
  EXPECT_TRUE(page == read_file(second)) << "the two renders' pages differ";
  const std::string glb = read_file(dir_ / "a/dropped_cube/dropped_cube.glb");
  ASSERT_EQ(glb.substr(0, 4), "glTF");
  const std::vector<std::uint8_t> bytes(glb.begin(), glb.end());
  EXPECT_NE(page.find("id=\"tumble-replay-glb\">" + io::base64(bytes) + "</script>"),
            std::string::npos);
}

// Like the glTF: named in the summary and in report.json's "html" (not among its videos),
// written under --no-video, kept by a later render that does not write it, and refused by
// --chunk, which cuts the frames apart.
TEST_F(HtmlReplay, ThePageIsReportedKeptByALaterRenderAndRefusedInChunks) {
  const std::string small = write("small.toml", testing::spin_scene(64, 36)).string();
  const Outcome both =
      tumble("render " + small + " --format mp4,html --no-frames -o " + path("out"));
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_NE(both.err.find(path("out/spin") +
                          "/: spin.mp4, spin.html, poster.png, contact_sheet.png, report.json\n"),
            std::string::npos)
      << both.err;
  const std::string page = read_file(dir_ / "out/spin/spin.html");
  ASSERT_GT(page.size(), 500000u);
  const auto report = io::parse_json(read_file(dir_ / "out/spin/report.json"));
  ASSERT_TRUE(report) << report.error();
  EXPECT_EQ(report->find("html")->string, path("out/spin/spin.html"));
  EXPECT_EQ(report->find("gltf")->kind, io::JsonValue::Kind::null);
  EXPECT_EQ(report->find("settings")->find("formats")->text, "[\"mp4\", \"html\"]");

  const Outcome mp4 = tumble("render " + small + " --format mp4 --no-frames -o " + path("out"));
  ASSERT_EQ(mp4.exit_code, 0) << mp4.err;
  EXPECT_NE(mp4.err.find("kept of the earlier render of this scene in " + path("out/spin") +
                         "/: spin.html\n"),
            std::string::npos)
      << mp4.err;
  EXPECT_TRUE(read_file(dir_ / "out/spin/spin.html") == page);

  fs::remove_all(dir_ / "out");
  const Outcome alone =
      tumble("render -q " + small + " --format html --no-video --no-frames -o " + path("out"));
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_TRUE(read_file(dir_ / "out/spin/spin.html") == page);  // the same bytes again
  EXPECT_FALSE(fs::exists(dir_ / "out/spin/spin.mp4"));

  const Outcome chunk =
      tumble("render " + small + " --chunk 1/2 --format mp4,html -o " + path("chunks"));
  EXPECT_EQ(chunk.exit_code, 2);
  EXPECT_NE(chunk.err.find("--chunk: html is not written in parts"), std::string::npos)
      << chunk.err;
  EXPECT_NE(chunk.err.find("render the html replay whole, or of a frame range with --frames"),
            std::string::npos)
      << chunk.err;
  EXPECT_FALSE(fs::exists(dir_ / "chunks"));
  const std::string html_scene =
      write("html.toml", testing::spin_scene(64, 36) + "[output]\nformats = [\"mp4\", \"html\"]\n")
          .string();
  const Outcome plan = tumble("plan " + html_scene + " --chunks 2");
  EXPECT_EQ(plan.exit_code, 2);
  EXPECT_EQ(plan.out, "");
  EXPECT_NE(plan.err.find("tumble: plan: " + html_scene + ": html is not written in parts"),
            std::string::npos)
      << plan.err;
}

// tumble diff --report of two renders with replays shows both, each loaded and ready in its
// frame of the report, with nothing fetched but the three pages.
TEST_F(HtmlReplay, TheDiffReportShowsBothRendersReplays) {
  render(kDroppedCube, "--width 160 --height 90 --format mp4,html", "a");
  render(kDroppedCube, "--width 160 --height 90 --format mp4,html", "b");
  const Outcome diff = tumble("diff --report " + path("report") + " " + path("a/dropped_cube") +
                              " " + path("b/dropped_cube"));
  EXPECT_EQ(diff.exit_code, 0) << diff.err;
  EXPECT_TRUE(read_file(dir_ / "report/replay-a.html") ==
              read_file(dir_ / "a/dropped_cube/dropped_cube.html"));
  if (!missing_.empty()) GTEST_SKIP() << missing_ << ": the report is loaded in it";
  const std::string ready = "document.body && document.body.dataset.ready";
  const PageRun run = run_page(
      "file://" + path("report/index.html"),
      "[{\"frame\": 0, \"wait\": \"" + ready + "\"}, {\"frame\": 1, \"wait\": \"" + ready + "\"}]");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(text_of(step_result(run, 0)), "\"true\"");
  EXPECT_EQ(text_of(step_result(run, 1)), "\"true\"");
  EXPECT_EQ(run.answer.find("requests")->text, "[\"file://" + path("report/index.html") +
                                                   "\",\"file://" + path("report/replay-a.html") +
                                                   "\",\"file://" + path("report/replay-b.html") +
                                                   "\"]");
  EXPECT_EQ(run.answer.find("errors")->text, "[]");
}

TEST_F(HtmlReplay, WithoutThreeJsTheRenderSaysWhatToRunAndWritesNothing) {
  fs::create_directories(dir_ / "web");
  write("web/replay.html", "<!-- tumble: data -->");
  const Outcome run =
      tumble("render -q " + std::string(kDroppedCube) + " --format mp4,html -o " + path("out"),
             "TUMBLE_WEB_DIR=" + path("web") + " exec ");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "tumble: the html replay needs three.js, and " + path("web") +
                         "/dist/three.bundle.js is missing: run scripts/install-deps (or `npm ci "
                         "&& npm run bundle` in " +
                         path("web") + ")\n");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
}  // namespace tumble
