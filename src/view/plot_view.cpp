#include "view/plot_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace tumble::view {
namespace {

// Margins around the graph inside the plot's box, in em of its text.
constexpr double kLeftMargin = 4.4;    // the value ticks' labels
constexpr double kRightMargin = 1.6;   // half of the last time tick's label
constexpr double kTopMargin = 2.0;     // the unit and the legend
constexpr double kBottomMargin = 2.0;  // the time ticks' labels

// A tick's value as text, with as many decimals as the step needs ("0.5", "10", "-2.5").
std::string tick_text(double value, double step, const char* unit) {
  const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 12);
  if (std::abs(value) < 1e-9 * step) value = 0.0;  // never "-0"
  char text[64];
  std::snprintf(text, sizeof text, "%.*f%s", decimals, value, unit);
  return text;
}

}  // namespace

Eigen::Vector2d PlotLayout::at(double t, double y) const {
  return Eigen::Vector2d(
      area_corner.x() + (t - t_low) / (t_high - t_low) * area_size.x(),
      area_corner.y() + area_size.y() - (y - y_low) / (y_high - y_low) * area_size.y());
}

double tick_step(double low, double high, int most) {
  const double raw = (high - low) / most;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double nice : {1.0, 2.0, 5.0}) {
    if (nice * magnitude >= raw * (1.0 - 1e-12)) return nice * magnitude;
  }
  return 10.0 * magnitude;
}

PlotLayout plot_layout(const scene::PlotOverlay& plot, std::span<const PlotSample> samples,
                       double t, int frame_width, int frame_height) {
  PlotLayout out;
  const double frame_w = static_cast<double>(frame_width) * 720.0 / frame_height;  // at 720 rows
  const int column = static_cast<int>(plot.anchor) % 3, row = static_cast<int>(plot.anchor) / 3;
  out.size = plot.size;
  out.corner = Eigen::Vector2d(column == 0   ? 0.0
                               : column == 1 ? 0.5 * (frame_w - plot.size.x())
                                             : frame_w - plot.size.x(),
                               row == 0   ? 0.0
                               : row == 1 ? 0.5 * (720.0 - plot.size.y())
                                          : 720.0 - plot.size.y()) +
               plot.offset;
  const double em = plot.text_size;
  out.area_corner = out.corner + Eigen::Vector2d(kLeftMargin * em, kTopMargin * em);
  out.area_size = plot.size - Eigen::Vector2d((kLeftMargin + kRightMargin) * em,
                                              (kTopMargin + kBottomMargin) * em);
  out.t_low = std::max(0.0, t - plot.window);
  out.t_high = out.t_low + plot.window;
  if (plot.y_min) {
    out.y_low = *plot.y_min;
    out.y_high = *plot.y_max;
    out.y_step = tick_step(out.y_low, out.y_high, 5);
    return out;
  }
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const PlotSample& sample : samples) {
    if (sample.t < out.t_low || sample.t > t) continue;
    for (const double v : sample.values) {
      if (!std::isfinite(v)) continue;
      low = std::min(low, v);
      high = std::max(high, v);
    }
  }
  if (!(low <= high)) low = high = 0.0;
  // Flat (to rounding, or a noise of 1e-12 about 0): a unit of its size around it, so that no
  // axis magnifies rounding into ticks of 1e-15.
  if (high - low <= 1e-9 * std::max(std::abs(low), std::abs(high)) || high - low < 1e-12) {
    // About 0 (within 1e-12): [-1, 1]; else a half unit of its size each way.
    const double middle = 0.5 * (low + high);
    const bool zero = std::abs(middle) < 1e-12;
    const double half = zero ? 1.0 : 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(middle))));
    if (zero) low = high = 0.0;
    low -= half;
    high += half;
  }
  out.y_step = tick_step(low, high, 4);
  // Whole ticks around the values; a rounding's worth past a tick (a kinetic energy of -1e-19 at
  // rest) is not a tick more.
  out.y_low = std::floor(low / out.y_step + 1e-9) * out.y_step;
  out.y_high = std::ceil(high / out.y_step - 1e-9) * out.y_step;
  if (out.y_high <= out.y_low) out.y_high = out.y_low + out.y_step;
  return out;
}

void add_plot(const scene::PlotOverlay& plot, std::span<const PlotSample> samples, double t,
              int frame_width, int frame_height, render::FrameView& view) {
  const PlotLayout layout = plot_layout(plot, samples, t, frame_width, frame_height);
  const double frame_w = static_cast<double>(frame_width) * 720.0 / frame_height;
  const double em = plot.text_size;
  view.panels.push_back(
      render::Panel{.corner = layout.corner, .size = layout.size, .color = plot.background});
  const render::Rgba grid(plot.ink.x(), plot.ink.y(), plot.ink.z(), 0.18 * plot.ink.w());
  const Eigen::Vector2d& a = layout.area_corner;
  const Eigen::Vector2d b = a + layout.area_size;
  const auto text = [&](std::string words, render::Anchor anchor, Eigen::Vector2d offset,
                        const render::Rgba& color) {
    view.texts.push_back(render::Text{.text = std::move(words),
                                      .anchor = anchor,
                                      .offset = offset,
                                      .height = em,
                                      .color = color});
  };
  // Value ticks at the whole multiples of the step within the axis: a grid line and the value,
  // right-aligned left of the graph.
  const double first_tick = std::ceil(layout.y_low / layout.y_step - 1e-9);
  const double last_tick = std::floor(layout.y_high / layout.y_step + 1e-9);
  for (double k = first_tick; k <= last_tick; k += 1.0) {
    const double value = k * layout.y_step;
    const double y = layout.at(layout.t_low, value).y();
    view.strokes.push_back({.points = {{a.x(), y}, {b.x(), y}}, .width = 1.0, .color = grid});
    text(tick_text(value, layout.y_step, ""), render::Anchor::kRight,
         Eigen::Vector2d(a.x() - 0.3 * em - frame_w, y - 360.0), plot.ink);
  }
  // Time ticks: a grid line and the time in seconds, centred under it.
  const double t_step = tick_step(layout.t_low, layout.t_high, 5);
  for (double tick = std::ceil(layout.t_low / t_step - 1e-9) * t_step;
       tick <= layout.t_high + 1e-9 * t_step; tick += t_step) {
    const double x = layout.at(tick, layout.y_low).x();
    view.strokes.push_back({.points = {{x, a.y()}, {x, b.y()}}, .width = 1.0, .color = grid});
    text(tick_text(tick, t_step, " s"), render::Anchor::kTop,
         Eigen::Vector2d(x - 0.5 * frame_w, b.y() + 0.2 * em), plot.ink);
  }
  // The graph's frame.
  view.strokes.push_back(
      {.points = {a, {b.x(), a.y()}, b, {a.x(), b.y()}, a}, .width = 1.2, .color = plot.ink});
  // The curves, each value clamped to the graph's edges (a value past a fixed y_min or y_max
  // runs along the edge).
  for (std::size_t v = 0; v < plot.values.size(); ++v) {
    render::Stroke curve{.points = {}, .width = 2.0, .color = plot.colors[v]};
    for (const PlotSample& sample : samples) {
      if (sample.t < layout.t_low || sample.t > t || !std::isfinite(sample.values[v])) continue;
      Eigen::Vector2d point = layout.at(sample.t, sample.values[v]);
      point.y() = std::clamp(point.y(), a.y(), b.y());
      curve.points.push_back(point);
    }
    if (!curve.points.empty()) view.strokes.push_back(std::move(curve));
  }
  // The unit over the value ticks, then the legend: a short line of each colour and its label.
  const double row = layout.corner.y() + 0.9 * em;  // the legend row's middle
  double x = layout.corner.x() + 0.4 * em;
  if (!plot.unit.empty()) {
    text(plot.unit, render::Anchor::kLeft, Eigen::Vector2d(x, row - 360.0), plot.ink);
    x = a.x();
  } else {
    x = a.x();
  }
  for (std::size_t v = 0; v < plot.values.size(); ++v) {
    view.strokes.push_back(
        {.points = {{x, row}, {x + 1.2 * em, row}}, .width = 2.0, .color = plot.colors[v]});
    text(plot.labels[v], render::Anchor::kLeft, Eigen::Vector2d(x + 1.3 * em, row - 360.0),
         plot.ink);
    // The label's width at about 0.6 em a character (code points), then a gap.
    const double characters = static_cast<double>(std::count_if(
        plot.labels[v].begin(), plot.labels[v].end(), [](char c) { return (c & 0xC0) != 0x80; }));
    x += 1.3 * em + 0.6 * em * characters + 1.2 * em;
  }
}

}  // namespace tumble::view
