// A plot overlay: its ticks at round steps, its layout, and its curve on the frame where the
// values `tumble simulate` prints put it.
#include "view/plot_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>

#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "support/command_test.hpp"
#include "support/render_golden.hpp"
#include "view/scene_view.hpp"

namespace tumble::view {
namespace {

TEST(PlotView, TicksAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(tick_step(0.0, 4.0, 5), 1.0);
  EXPECT_DOUBLE_EQ(tick_step(0.0, 9.81, 4), 5.0);
  EXPECT_DOUBLE_EQ(tick_step(-0.3, 0.3, 4), 0.2);
  EXPECT_DOUBLE_EQ(tick_step(0.0, 0.0004, 4), 0.0001);
  EXPECT_DOUBLE_EQ(tick_step(0.0, 70.0, 4), 20.0);
}

// The value axis of samples from 0.3 to 19.6 spans 0 to 20 in steps of 5; the graph sits in the
// top-right corner's box, inside its margins; the time axis shows the last 4 s, or the first 4.
TEST(PlotView, TheLayoutSpansTheValuesAndTheWindow) {
  scene::PlotOverlay plot;
  plot.window = 4.0;
  plot.offset = Eigen::Vector2d(-24, 24);
  const std::vector<PlotSample> samples = {{.t = 0.5, .values = {0.3}},
                                           {.t = 1.0, .values = {19.6}}};
  const PlotLayout early = plot_layout(plot, samples, 1.0, 1280, 720);
  EXPECT_EQ(early.y_low, 0.0);
  EXPECT_EQ(early.y_high, 20.0);
  EXPECT_EQ(early.y_step, 5.0);
  EXPECT_EQ(early.t_low, 0.0);
  EXPECT_EQ(early.t_high, 4.0);
  EXPECT_EQ(early.corner, Eigen::Vector2d(1280 - 440 - 24, 24));
  EXPECT_GT(early.area_corner.x(), early.corner.x());
  EXPECT_LT(early.area_corner.x() + early.area_size.x(), early.corner.x() + early.size.x());
  EXPECT_EQ(early.at(0.0, 20.0), early.area_corner);
  const PlotLayout late = plot_layout(plot, samples, 10.0, 1280, 720);
  EXPECT_EQ(late.t_low, 6.0);
  EXPECT_EQ(late.t_high, 10.0);
  // No sample in the window: a flat unit around 0.
  EXPECT_EQ(late.y_low, -1.0);
  EXPECT_EQ(late.y_high, 1.0);
}

// With a fixed value axis of [0, 7] the ticks are the round values inside it, 0, 2, 4 and 6,
// none past its top; a value flat at 1e-13 about 0 gets an axis of [-1, 1], not one of 1e-13.
TEST(PlotView, TicksStayInsideAFixedAxisAndNoiseIsFlat) {
  scene::PlotOverlay plot;
  plot.values.resize(1);
  plot.labels = {"v"};
  plot.colors = {render::Rgba(0, 0, 1, 1)};
  plot.y_min = 0.0;
  plot.y_max = 7.0;
  const std::vector<PlotSample> samples = {{.t = 0.5, .values = {3.0}}};
  render::FrameView view;
  add_plot(plot, samples, 1.0, 1280, 720, view);
  std::vector<std::string> ticks;
  for (const render::Text& text : view.texts) {
    if (text.anchor == render::Anchor::kRight) ticks.push_back(text.text);
  }
  EXPECT_EQ(ticks, (std::vector<std::string>{"0", "2", "4", "6"}));
  const PlotLayout layout = plot_layout(plot, samples, 1.0, 1280, 720);
  for (const render::Stroke& stroke : view.strokes) {
    for (const Eigen::Vector2d& point : stroke.points) {
      EXPECT_GE(point.y(), layout.corner.y());
      EXPECT_LE(point.y(), layout.corner.y() + layout.size.y());
    }
  }
  scene::PlotOverlay free = plot;
  free.y_min.reset();
  free.y_max.reset();
  const std::vector<PlotSample> noise = {{.t = 0.1, .values = {1e-13}},
                                         {.t = 0.2, .values = {-2e-13}}};
  const PlotLayout flat = plot_layout(free, noise, 1.0, 1280, 720);
  EXPECT_EQ(flat.y_low, -1.0);
  EXPECT_EQ(flat.y_high, 1.0);
}

class PlotFrame : public testing::CommandTest {};

// A cube dropped on the floor bouncing for 4 s, its kinetic energy plotted in blue over the
// whole 4 s window at 1280×720: at each frame's time, in each column where the curve is not
// steep (the bounces are), the curve's pixels are centred within 1 px of where the value that
// `tumble simulate`'s states give (the energy at the steps around, lerped) maps to.
TEST_F(PlotFrame, TheCurveFollowsTheSimulatedValuesWithinAPixel) {
  const std::string text = R"(name = "bounce"
duration = 4.0
[physics]
dt = 0.005
gravity = [0, -9.81, 0]
[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
restitution = 0.6
[[bodies]]
name = "cube"
shape = "cube"
size = 1.0
mass = 1.0
position = [0, 3, 0]
angular_velocity = [0.5, 1.0, 0.0]
restitution = 0.6
[render]
fps = 30
width = 1280
height = 720
[camera]
position = [4, 3, 8]
look_at = [0, 1, 0]
[[overlays]]
kind = "plot"
values = ["{cube.kinetic_energy}"]
labels = ["E"]
unit = "J"
colors = ["#0000ff"]
window = 4.0
size = [640, 360]
)";
  const std::filesystem::path file = write("bounce.toml", text);
  const testing::Outcome run = tumble("simulate " + file.string() + " --out " + path("s.csv"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::vector<std::pair<double, double>> energy;  // (t, kinetic energy) a step
  std::ifstream csv(path("s.csv"));
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) {
    std::stringstream fields(line);
    std::string field;
    std::vector<double> row;
    while (std::getline(fields, field, ',')) row.push_back(std::strtod(field.c_str(), nullptr));
    ASSERT_EQ(row.size(), 22u);
    energy.emplace_back(row[0], row[21]);
  }
  constexpr std::int64_t kFrame = 119;
  std::vector<PlotSample> samples;
  for (std::int64_t k = 0; k <= kFrame; ++k) {
    const double t = static_cast<double>(k) / 30.0;
    std::size_t n = 0;
    while (n + 1 < energy.size() && energy[n + 1].first < t) ++n;
    const double alpha = (t - energy[n].first) / (energy[n + 1].first - energy[n].first);
    const double value = alpha <= 0.0
                             ? energy[n].second
                             : energy[n].second + alpha * (energy[n + 1].second - energy[n].second);
    samples.push_back({.t = t, .values = {value}});
  }
  const Result<scene::Scene> loaded = scene::load_scene_file(file.string());
  ASSERT_TRUE(loaded) << loaded.error();
  const auto& plot = std::get<scene::PlotOverlay>(loaded->overlays[0]);
  const double t = static_cast<double>(kFrame) / 30.0;
  const PlotLayout layout = plot_layout(plot, samples, t, 1280, 720);
  EXPECT_GT(layout.y_high, 20.0);  // m g h = 29 J at the first impact, less the rest

  const Result<Framing> framing = frame_scene(*loaded, 120, [] { return false; });
  ASSERT_TRUE(framing);
  SimulatedFrames source(*loaded, *framing, [] { return false; });
  const Result<render::FrameView> view = source.view(kFrame);
  ASSERT_TRUE(view) << view.error();
  const io::Image image = testing::draw(renderer_settings(*loaded, *framing), *view);
  ASSERT_EQ(image.width, 1280);

  int checked = 0;
  for (std::size_t k = 1; k + 1 < samples.size(); ++k) {
    const Eigen::Vector2d here = layout.at(samples[k].t, samples[k].values[0]);
    const double before = layout.at(samples[k - 1].t, samples[k - 1].values[0]).y();
    const double after = layout.at(samples[k + 1].t, samples[k + 1].values[0]).y();
    const double spacing = here.x() - layout.at(samples[k - 1].t, 0.0).x();
    if (std::abs(here.y() - before) > 0.5 * spacing || std::abs(here.y() - after) > 0.5 * spacing) {
      continue;  // steep here: the column holds a run of the curve
    }
    const int column = static_cast<int>(std::floor(here.x()));
    double weight = 0.0, sum = 0.0;
    for (int row = static_cast<int>(layout.area_corner.y());
         row < static_cast<int>(layout.area_corner.y() + layout.area_size.y()) + 2; ++row) {
      const std::uint8_t* p = image.row(row) + 3 * column;
      const double blue = (p[2] - std::max(p[0], p[1])) / 255.0;
      if (blue > 0.2) {
        weight += blue;
        sum += blue * (row + 0.5);
      }
    }
    ASSERT_GT(weight, 0.0) << "no curve in column " << column << " (t = " << samples[k].t << ")";
    EXPECT_NEAR(sum / weight, here.y(), 1.0) << "t = " << samples[k].t;
    ++checked;
  }
  EXPECT_GT(checked, 60) << "columns checked";
}

}  // namespace
}  // namespace tumble::view
