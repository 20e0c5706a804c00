#include "view/overlay_view.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "render/utf8.hpp"
#include "view/overlay_values.hpp"

namespace tumble::view {
namespace {

// The body's axes x, y, z in the usual red, green, blue.
const render::Rgba kAxisColors[3] = {render::Rgba(0.90, 0.16, 0.16, 1.0),
                                     render::Rgba(0.15, 0.70, 0.20, 1.0),
                                     render::Rgba(0.15, 0.35, 0.95, 1.0)};
constexpr double kLabelSize = 28.0;  // em size of an arrow's label (px at 720 rows)

// How much of a text shows at time t (s): 0 outside [start, end), rising over `fade` seconds
// after start and falling over `fade` seconds before end.
double text_opacity(const scene::TextOverlay& text, double t) {
  if (t < text.start || t >= text.end) return 0.0;
  if (text.fade <= 0.0) return 1.0;
  return std::clamp(std::min(t - text.start, text.end - t) / text.fade, 0.0, 1.0);
}

void add_text(const scene::TextOverlay& overlay, const std::vector<physics::BodyState>& states,
              const StepPair& steps, double t, std::int64_t frame,
              std::span<const JointValue> joints, render::FrameView& view) {
  const double opacity = text_opacity(overlay, t);
  if (opacity <= 0.0) return;
  if (overlay.body) {  // at its point on the drawn body, as a label
    view.labels.push_back(render::Label{
        .text = format_text(overlay.text, steps, t, frame, joints),
        .position = physics::body_point_to_world(states[*overlay.body], overlay.point),
        .height = overlay.size,
        .color = overlay.color,
        .offset = overlay.offset,
        .background = overlay.background,
        .opacity = opacity});
    return;
  }
  view.texts.push_back(render::Text{.text = format_text(overlay.text, steps, t, frame, joints),
                                    .anchor = overlay.anchor,
                                    .offset = overlay.offset,
                                    .height = overlay.size,
                                    .color = overlay.color,
                                    .background = overlay.background,
                                    .opacity = opacity});
}

void add_vector(const scene::VectorOverlay& overlay, const scene::Scene& scene,
                const std::vector<physics::BodyState>& states, const StepPair& steps, double t,
                std::span<const JointValue> joints, std::span<const BodyContact> contacts,
                render::FrameView& view) {
  const physics::BodyState& state = states[overlay.body];
  physics::Vec3 from, to;
  if (overlay.quantity == scene::VectorQuantity::joint_force) {
    from = joints[overlay.joint].anchor;
    to = from + overlay.scale * joints[overlay.joint].force;
  } else if (overlay.quantity == scene::VectorQuantity::contact_force) {
    from = contacts[overlay.body].point;
    to = from + overlay.scale * contacts[overlay.body].force;
  } else {
    from = physics::body_point_to_world(state, overlay.point);
    to = from + overlay.scale * vector_value(overlay, scene.bodies[overlay.body], steps, state, t);
  }
  // A label at the tip; the renderer draws neither when the arrow is too short to read.
  view.arrows.push_back(render::Arrow{.from = from,
                                      .to = to,
                                      .color = overlay.color,
                                      .label = overlay.label,
                                      .label_height = kLabelSize});
}

void add_axes(const scene::AxesOverlay& overlay, const std::vector<physics::BodyState>& states,
              render::FrameView& view) {
  const physics::BodyState& state = states[overlay.body];
  const Eigen::Matrix3d rotation = state.orientation().toRotationMatrix();  // body to world
  for (int axis = 0; axis < 3; ++axis) {
    view.arrows.push_back(
        render::Arrow{.from = state.position(),
                      .to = state.position() + overlay.length * rotation.col(axis),
                      .color = kAxisColors[axis]});
  }
}

}  // namespace

bool overlays_need_font(const scene::Scene& scene) {
  return std::any_of(scene.overlays.begin(), scene.overlays.end(), [](const auto& overlay) {
    const auto* vector = std::get_if<scene::VectorOverlay>(&overlay);
    return std::holds_alternative<scene::TextOverlay>(overlay) ||
           std::holds_alternative<scene::PlotOverlay>(overlay) ||
           (vector && !vector->label.empty());
  });
}

bool overlays_need_lines(const scene::Scene& scene) {
  return std::any_of(scene.overlays.begin(), scene.overlays.end(), [](const auto& overlay) {
    return !std::holds_alternative<scene::TextOverlay>(overlay) &&
           !std::holds_alternative<scene::PlotOverlay>(overlay);  // drawn on the CPU
  });
}

std::string overlay_font(const scene::Scene& scene) {
  return scene.font.empty() ? std::string(render::kDefaultFontFamily) : scene.font;
}

std::vector<std::string> missing_character_warnings(const scene::Scene& scene,
                                                    const render::Font* font) {
  if (!font) return {};
  std::string fixed;
  for (const scene::OverlaySpec& overlay : scene.overlays) {
    if (const auto* text = std::get_if<scene::TextOverlay>(&overlay)) {
      for (const std::string& piece : text->text.pieces) fixed += piece;
    } else if (const auto* vector = std::get_if<scene::VectorOverlay>(&overlay)) {
      fixed += vector->label;
    } else if (const auto* plot = std::get_if<scene::PlotOverlay>(&overlay)) {
      for (const std::string& label : plot->labels) fixed += label;
      fixed += plot->unit;
    }
  }
  std::vector<std::string> out;
  const Result<std::u32string> decoded = render::decode_utf8(fixed);
  if (!decoded) return {decoded.error()};
  for (const char32_t c : font->missing_characters(*decoded)) {
    out.push_back(scene.source_path + ": the font has no glyph for " +
                  render::describe_character(c) + ": it is left out of the overlays' text");
  }
  return out;
}

OverlayItems::OverlayItems(const scene::Scene& scene)
    : scene_(scene), trails_(scene.overlays.size()), plots_(scene.overlays.size()) {}

std::int64_t OverlayItems::frames_of_history() const {
  double longest = 0.0;  // s
  for (const scene::OverlaySpec& overlay : scene_.overlays) {
    if (const auto* trail = std::get_if<scene::TrailOverlay>(&overlay)) {
      longest = std::max(longest, trail->length);
    } else if (const auto* plot = std::get_if<scene::PlotOverlay>(&overlay)) {
      longest = std::max(longest, plot->window);
    }
  }
  return static_cast<std::int64_t>(std::ceil(longest * scene_.fps));
}

void OverlayItems::record(const std::vector<physics::BodyState>& states, const StepPair& steps,
                          double t, std::span<const JointValue> joints) {
  for (std::size_t i = 0; i < scene_.overlays.size(); ++i) {
    if (const auto* plot = std::get_if<scene::PlotOverlay>(&scene_.overlays[i])) {
      std::deque<PlotSample>& samples = plots_[i];
      PlotSample sample{.t = t, .values = {}};
      for (const scene::Placeholder& value : plot->values) {
        sample.values.push_back(placeholder_number(value, steps, joints));
      }
      samples.push_back(std::move(sample));
      // Only the window's samples are drawn (plot_view.hpp); older ones go.
      while (!samples.empty() && samples.front().t < t - plot->window - 1e-9) samples.pop_front();
      continue;
    }
    const auto* trail = std::get_if<scene::TrailOverlay>(&scene_.overlays[i]);
    if (!trail) continue;
    std::deque<TrailPoint>& points = trails_[i];
    points.push_back({t, physics::body_point_to_world(states[trail->body], trail->point)});
    // A point exactly `length` old stays, whatever the rounding of k / fps (1 ns is far below
    // any frame interval).
    const double oldest = t - trail->length - 1e-9;  // s
    while (points.front().time < oldest) points.pop_front();
  }
}

bool OverlayItems::needs_contacts() const {
  return std::any_of(scene_.overlays.begin(), scene_.overlays.end(), [](const auto& overlay) {
    const auto* vector = std::get_if<scene::VectorOverlay>(&overlay);
    return vector && vector->quantity == scene::VectorQuantity::contact_force;
  });
}

void OverlayItems::add_to(const std::vector<physics::BodyState>& states, const StepPair& steps,
                          double t, std::int64_t frame, render::FrameView& view,
                          std::span<const JointValue> joints,
                          std::span<const BodyContact> contacts) const {
  for (std::size_t i = 0; i < scene_.overlays.size(); ++i) {
    const scene::OverlaySpec& overlay = scene_.overlays[i];
    if (const auto* text = std::get_if<scene::TextOverlay>(&overlay)) {
      add_text(*text, states, steps, t, frame, joints, view);
    } else if (const auto* vector = std::get_if<scene::VectorOverlay>(&overlay)) {
      add_vector(*vector, scene_, states, steps, t, joints, contacts, view);
    } else if (const auto* axes = std::get_if<scene::AxesOverlay>(&overlay)) {
      add_axes(*axes, states, view);
    } else if (const auto* plot = std::get_if<scene::PlotOverlay>(&overlay)) {
      const std::vector<PlotSample> samples(plots_[i].begin(), plots_[i].end());
      add_plot(*plot, samples, t, scene_.render.width, scene_.render.height, view);
    } else if (const auto* trail = std::get_if<scene::TrailOverlay>(&overlay)) {
      // Opacity falls from 1 at the body to 0 at `length` seconds old.
      render::Polyline line{.points = {}, .opacity = {}, .color = trail->color};
      for (const TrailPoint& point : trails_[i]) {
        line.points.push_back(point.position);
        line.opacity.push_back(1.0 - (t - point.time) / trail->length);
      }
      view.lines.push_back(std::move(line));
    }
  }
}

}  // namespace tumble::view
