// A plot overlay (scene::PlotOverlay) in a frame: its box, axes, ticks, grid, legend and curves
// as the renderer's panels, strokes and texts, all in px at 720 rows from the frame's top-left.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "render/frame.hpp"
#include "scene/overlays.hpp"

namespace tumble::view {

// The plotted values at one frame's time.
struct PlotSample {
  double t = 0.0;  // s
  std::vector<double> values;
};

// Where a plot goes on the frame and what its axes span.
struct PlotLayout {
  Eigen::Vector2d corner = Eigen::Vector2d::Zero();  // the plot's box, top-left (px at 720 rows)
  Eigen::Vector2d size = Eigen::Vector2d::Zero();
  Eigen::Vector2d area_corner = Eigen::Vector2d::Zero();  // the graph inside it, top-left
  Eigen::Vector2d area_size = Eigen::Vector2d::Zero();
  double t_low = 0.0, t_high = 1.0;  // s, left and right edges of the graph
  double y_low = 0.0, y_high = 1.0;  // bottom and top edges of the graph
  double y_step = 1.0;               // between y ticks (from y_low)

  // The point of the graph at time t (s) and value y (px at 720 rows from the frame's top-left).
  Eigen::Vector2d at(double t, double y) const;
};

// Ticks from `low` to `high` at a round step (1, 2 or 5 × 10^k) giving at most `most`
// intervals: the step.
double tick_step(double low, double high, int most);

// The layout of `plot` at time t (s) on a frame of `frame_width` × `frame_height` px, from the
// samples it has so far: the time axis spans the last `window` seconds (the first `window`
// seconds until then); the value axis [y_min, y_max] as given, or the range of the samples
// shown widened to whole ticks.
PlotLayout plot_layout(const scene::PlotOverlay& plot, std::span<const PlotSample> samples,
                       double t, int frame_width, int frame_height);

// Adds the plot's items to `view`.
void add_plot(const scene::PlotOverlay& plot, std::span<const PlotSample> samples, double t,
              int frame_width, int frame_height, render::FrameView& view);

}  // namespace tumble::view
