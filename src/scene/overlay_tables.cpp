#include "scene/overlay_tables.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <variant>

#include "scene/text_template.hpp"
#include "sim/simulation.hpp"

namespace tumble::scene::detail {
namespace {

// Enough for any explanation; beyond it a scene is surely generated wrong.
constexpr std::size_t kMaxOverlays = 100;
// A trail keeps a point per frame of its length: a minute at 240 fps is 14 400 points a frame.
constexpr double kMaxTrailLength = 60.0;  // s
// Larger than any frame is tall at 720 rows.
constexpr double kMaxTextSize = 720.0;  // px at 720 rows
// From the frame's edges the anchor touches, when no offset is written.
constexpr double kDefaultMargin = 24.0;  // px at 720 rows

// A default colour per quantity, so that two arrows on one body tell apart unasked.
// Each quantity's default colour, none near the red, green and blue of a body's axes (an
// `axes` overlay) nor near another's: cyan, magenta, yellow, orange.
const Rgba kVelocityColor(0.0, 0.72, 0.80, 1.0);
const Rgba kAngularVelocityColor(0.80, 0.20, 0.80, 1.0);
const Rgba kAngularMomentumColor(0.95, 0.85, 0.15, 1.0);
const Rgba kForceColor(1.0, 0.50, 0.05, 1.0);
const Rgba kContactForceColor(0.55, 0.30, 0.10, 1.0);  // brown
const Rgba kTorqueColor(1.0, 0.45, 0.70, 1.0);         // pink
const Rgba kConstantColor(0.35, 0.35, 0.38, 1.0);

// The index of the body `key` names; an error suggests a near name.
std::size_t read_body(TableReader& in, const Scene& scene, std::string_view key = "body") {
  const std::string name = in.required_string(key);
  std::string nearest;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].name == name) return i;
    if (edit_distance(scene.bodies[i].name, name) <= 2) nearest = scene.bodies[i].name;
  }
  in.fail(key, "no body is named " + in_quotes(name) +
                   (nearest.empty() ? "" : " (did you mean " + in_quotes(nearest) + "?)"));
}

std::vector<std::string> body_names(const Scene& scene) {
  std::vector<std::string> names;
  for (const BodySpec& body : scene.bodies) names.push_back(body.name);
  return names;
}

// [x, y] (px at 720 rows).
Eigen::Vector2d read_offset(TableReader& in) {
  const toml::node& node = in.required("offset");
  const toml::array* array = node.as_array();
  if (!array || array->size() != 2) {
    in.fail("offset", "expected [x, y] in pixels at 720 rows, found " +
                          (array ? "an array of " + std::to_string(array->size())
                                 : std::string(type_name(node))));
  }
  return Eigen::Vector2d(in.number("offset", (*array)[0]), in.number("offset", (*array)[1]));
}

// `anchor`, or `fallback` when it is not given.
common::Anchor read_anchor(TableReader& in, const std::string& fallback) {
  const std::string anchor = in.optional_string("anchor", fallback);
  const std::optional<common::Anchor> known = common::anchor_from_name(anchor);
  if (!known) {
    in.fail("anchor", "unknown anchor " + in_quotes(anchor) +
                          " (expected top-left, top, top-right, left, centre, right, "
                          "bottom-left, bottom or bottom-right)");
  }
  return *known;
}

// kDefaultMargin in from each edge the anchor touches: a corner's text clears both edges.
Eigen::Vector2d default_offset(common::Anchor anchor) {
  const int column = static_cast<int>(anchor) % 3, row = static_cast<int>(anchor) / 3;
  return kDefaultMargin * Eigen::Vector2d(column == 0   ? 1.0
                                          : column == 2 ? -1.0
                                                        : 0.0,
                                          row == 0   ? 1.0
                                          : row == 2 ? -1.0
                                                     : 0.0);
}

std::vector<JointName> joint_names(const Scene& scene) {
  std::vector<JointName> out;
  for (const JointSpec& joint : scene.joints) out.push_back({joint.name, joint.kind});
  return out;
}

// A `point` given on a hull is in the frame of its points (m), as they are; left out, the centre
// of mass.
physics::Vec3 on_body(TableReader& in, const BodySpec& body, const physics::Vec3& point) {
  return body.hull && in.has("point") ? body.hull->body_point(point) : point;
}

TextOverlay read_text(TableReader& in, const Scene& scene) {
  TextOverlay out;
  const Result<TextTemplate> text =
      parse_text_template(in.required_string("text"), body_names(scene), joint_names(scene));
  if (!text) in.fail("text", text.error());
  out.text = *text;
  if (in.has("body")) {
    if (in.has("anchor")) {
      in.fail("anchor",
              "a text that follows a body (`body`) is drawn at its point: it takes no "
              "anchor (`offset` moves it from the point)");
    }
    out.body = read_body(in, scene);
    out.point =
        vector_within(in, "point", in.optional_vector("point", out.point), sim::kMaxPosition, "m");
    out.point = on_body(in, scene.bodies[*out.body], out.point);
  } else if (in.has("point")) {
    in.fail("point", "only a text that follows a body (`body = \"NAME\"`) takes a point");
  }
  out.anchor = read_anchor(in, "top-left");
  out.offset = in.has("offset") ? read_offset(in)
               : out.body       ? Eigen::Vector2d::Zero()
                                : default_offset(out.anchor);
  out.size = in.optional_number("size", out.size);
  if (!(out.size > 0.0 && out.size <= kMaxTextSize)) {
    in.fail("size", "must be more than 0 and at most " + format_number(kMaxTextSize) +
                        " px at 720 rows (got " + format_number(out.size) + ")");
  }
  out.color = in.optional_rgba("color", out.color);
  if (in.has("background")) out.background = in.optional_rgba("background", Rgba::Zero());
  out.start = in.optional_number("start", out.start);
  out.end = in.optional_number("end", out.end);
  if (!(out.start < out.end)) {
    in.fail("start", "start (" + format_number(out.start) + " s) must be before end (" +
                         format_number(out.end) + " s)");
  }
  out.fade = in.optional_number("fade", out.fade);
  require_non_negative(in, "fade", out.fade);
  return out;
}

// The kind name [[bodies.forces]] gives the law (scene_loader.cpp's read_force).
std::string_view force_kind(const physics::ForceLaw& law) {
  constexpr std::array<std::string_view, std::variant_size_v<physics::ForceLaw>> kKinds = {
      "gravity",         "force",          "torque", "linear_damping",
      "angular_damping", "force_at_point", "spring", "penalty_contact"};
  return kKinds[law.index()];
}

// `law` names a kind of the body's [[bodies.forces]]; every law of that kind is summed. Without
// `law`, every law of the body.
std::vector<std::size_t> read_laws(TableReader& in, const BodySpec& body) {
  const std::string kind = in.optional_string("law", "");
  std::vector<std::size_t> laws;
  std::string kinds;
  for (std::size_t i = 0; i < body.forces.size(); ++i) {
    const std::string_view name = force_kind(body.forces[i]);
    if (kind.empty() || name == kind) laws.push_back(i);
    if (kinds.find(name) == std::string::npos)
      kinds += (kinds.empty() ? "" : ", ") + std::string(name);
  }
  if (body.forces.empty()) {
    in.fail("quantity", "body " + in_quotes(body.name) + " has no [[bodies.forces]] to draw");
  }
  if (laws.empty()) {
    in.fail("law", "body " + in_quotes(body.name) + " has no " + in_quotes(kind) +
                       " law (its laws: " + kinds + ")");
  }
  return laws;
}

// `joint = "NAME"` of a joint_force vector: drawn at the joint's anchor on its body_a.
void read_joint_force(TableReader& in, const Scene& scene, VectorOverlay& out) {
  for (const char* key : {"body", "point"}) {
    if (in.has(key)) {
      in.fail(key, std::string("a joint's force is drawn on its body_a at its anchor: it takes "
                               "`joint`, not ") +
                       key);
    }
  }
  const std::string name = in.required_string("joint");
  for (std::size_t j = 0; j < scene.joints.size(); ++j) {
    if (scene.joints[j].name != name) continue;
    out.joint = j;
    out.body = scene.joints[j].body_a;
    return;
  }
  std::string known;
  for (const JointSpec& joint : scene.joints) known += (known.empty() ? "" : ", ") + joint.name;
  in.fail("joint",
          "no joint is named " + in_quotes(name) +
              (known.empty() ? " (the scene has no [[joints]])" : " (joints: " + known + ")"));
}

VectorOverlay read_vector(TableReader& in, const Scene& scene) {
  VectorOverlay out;
  const toml::node& quantity = in.required("quantity");
  const std::string name = quantity.is_string() ? *quantity.value<std::string>() : "";
  if (name == "joint_force") {
    out.quantity = VectorQuantity::joint_force;
    read_joint_force(in, scene, out);
    if (in.has("law")) in.fail("law", "only a vector of quantity = \"force\" takes a law");
    out.scale = in.optional_number("scale", out.scale);
    require_positive(in, "scale", out.scale);
    out.color = in.optional_rgba("color", kForceColor);
    out.label = in.optional_string("label", out.label);
    return out;
  }
  if (in.has("joint"))
    in.fail("joint", "only a vector of quantity = \"joint_force\" takes a joint");
  out.body = read_body(in, scene);
  const std::pair<std::string_view, std::pair<VectorQuantity, Rgba>> kNames[] = {
      {"velocity", {VectorQuantity::velocity, kVelocityColor}},
      {"angular_velocity", {VectorQuantity::angular_velocity, kAngularVelocityColor}},
      {"angular_momentum", {VectorQuantity::angular_momentum, kAngularMomentumColor}},
      {"force", {VectorQuantity::force, kForceColor}},
      {"contact_force", {VectorQuantity::contact_force, kContactForceColor}},
      {"torque", {VectorQuantity::torque, kTorqueColor}}};
  Rgba color = kConstantColor;
  if (quantity.is_array()) {
    out.quantity = VectorQuantity::constant;
    out.constant = in.vector("quantity", quantity);
  } else {
    const auto* known = std::find_if(std::begin(kNames), std::end(kNames),
                                     [&](const auto& entry) { return entry.first == name; });
    if (!quantity.is_string() || known == std::end(kNames)) {
      in.fail("quantity",
              "expected velocity, angular_velocity, angular_momentum, force, contact_force, "
              "torque, joint_force or a constant vector [x, y, z], found " +
                  (quantity.is_string() ? in_quotes(name) : std::string(type_name(quantity))));
    }
    out.quantity = known->second.first;
    color = known->second.second;
  }
  if (out.quantity == VectorQuantity::force || out.quantity == VectorQuantity::torque) {
    out.laws = read_laws(in, scene.bodies[out.body]);
  } else if (in.has("law")) {
    in.fail("law", "only a vector of quantity = \"force\" or \"torque\" takes a law");
  }
  if (out.quantity == VectorQuantity::contact_force && in.has("point")) {
    in.fail("point", "a contact force is drawn at its centre of pressure: it takes no point");
  }
  out.point =
      vector_within(in, "point", in.optional_vector("point", out.point), sim::kMaxPosition, "m");
  out.point = on_body(in, scene.bodies[out.body], out.point);
  out.scale = in.optional_number("scale", out.scale);
  require_positive(in, "scale", out.scale);
  out.color = in.optional_rgba("color", color);
  out.label = in.optional_string("label", out.label);
  return out;
}

TrailOverlay read_trail(TableReader& in, const Scene& scene) {
  TrailOverlay out;
  out.body = read_body(in, scene);
  out.point =
      vector_within(in, "point", in.optional_vector("point", out.point), sim::kMaxPosition, "m");
  out.point = on_body(in, scene.bodies[out.body], out.point);
  out.length = in.optional_number("length", out.length);
  if (!(out.length > 0.0 && out.length <= kMaxTrailLength)) {
    in.fail("length", "must be more than 0 and at most " + format_number(kMaxTrailLength) +
                          " s (got " + format_number(out.length) + ")");
  }
  const common::Color& body = scene.bodies[out.body].color;
  out.color = in.optional_rgba("color", Rgba(body.x(), body.y(), body.z(), 1.0));
  return out;
}

AxesOverlay read_axes(TableReader& in, const Scene& scene) {
  AxesOverlay out;
  out.body = read_body(in, scene);
  out.length = in.optional_number("length", scene.bodies[out.body].size.maxCoeff());
  require_positive(in, "length", out.length);
  return out;
}

// Colours of a plot's curves, in turn: none of them the axes' red, green or blue.
const Rgba kPlotColors[] = {Rgba(0.0, 0.45, 0.70, 1.0),  Rgba(0.84, 0.37, 0.0, 1.0),
                            Rgba(0.0, 0.62, 0.45, 1.0),  Rgba(0.80, 0.47, 0.65, 1.0),
                            Rgba(0.35, 0.35, 0.38, 1.0), Rgba(0.90, 0.62, 0.0, 1.0)};
constexpr std::size_t kMaxPlotValues = 8;
constexpr double kMaxPlotWindow = 600.0;  // s

// The strings of the array at `key`, at most `limit`.
std::vector<std::string> read_strings(TableReader& in, std::string_view key, std::size_t limit) {
  const toml::array* array = in.table().get(key)->as_array();
  if (!array || array->empty() || array->size() > limit) {
    in.fail(key, "expected an array of 1 to " + std::to_string(limit) + " strings");
  }
  std::vector<std::string> out;
  for (const toml::node& node : *array) {
    if (!node.is_string()) in.fail(key, "expected strings, found " + std::string(type_name(node)));
    out.push_back(*node.value<std::string>());
  }
  return out;
}

PlotOverlay read_plot(TableReader& in, const Scene& scene) {
  PlotOverlay out;
  in.required("values");
  const std::vector<std::string> values = read_strings(in, "values", kMaxPlotValues);
  for (const std::string& value : values) {
    const Result<TextTemplate> parsed =
        parse_text_template(value, body_names(scene), joint_names(scene));
    if (!parsed) in.fail("values", parsed.error());
    if (parsed->values.size() != 1 || !parsed->pieces[0].empty() || !parsed->pieces[1].empty()) {
      in.fail("values",
              "each value is one placeholder alone, such as \"{cube.kinetic_energy}\" "
              "(found " +
                  in_quotes(value) + ")");
    }
    const Placeholder& p = parsed->values[0];
    const bool number =
        (p.source == Placeholder::Source::body && (p.component >= 0 || !is_vector(p.quantity))) ||
        (p.source == Placeholder::Source::joint &&
         (p.component >= 0 || p.joint_quantity != JointQuantity::force));
    if (!number) {
      in.fail("values", value +
                            ": a plot draws numbers: a body's or a joint's quantity, a "
                            "vector's with .x, .y or .z");
    }
    out.values.push_back(p);
    out.labels.push_back(value.substr(1, value.size() - 2));
  }
  if (in.has("labels")) {
    out.labels = read_strings(in, "labels", kMaxPlotValues);
    if (out.labels.size() != out.values.size()) {
      in.fail("labels", "one label per value: " + std::to_string(out.values.size()) + " values, " +
                            std::to_string(out.labels.size()) + " labels");
    }
  }
  for (std::size_t i = 0; i < out.values.size(); ++i) {
    out.colors.push_back(kPlotColors[i % std::size(kPlotColors)]);
  }
  if (in.has("colors")) {
    const toml::array* array = in.table().get("colors")->as_array();
    if (!array || array->size() != out.values.size()) {
      in.fail("colors",
              "expected one colour per value (" + std::to_string(out.values.size()) + ")");
    }
    for (std::size_t i = 0; i < array->size(); ++i) {
      const Vec3 rgb = in.color("colors", *array->get(i));
      out.colors[i] = Rgba(rgb.x(), rgb.y(), rgb.z(), 1.0);
    }
  }
  out.window = in.optional_number("window", out.window);
  if (!(out.window > 0.0 && out.window <= kMaxPlotWindow)) {
    in.fail("window", "must be more than 0 and at most " + format_number(kMaxPlotWindow) +
                          " s (got " + format_number(out.window) + ")");
  }
  if (in.has("y_min")) out.y_min = in.optional_number("y_min", 0.0);
  if (in.has("y_max")) out.y_max = in.optional_number("y_max", 0.0);
  if (out.y_min.has_value() != out.y_max.has_value()) {
    in.fail(out.y_min ? "y_min" : "y_max",
            "give y_min and y_max together, or neither (the "
            "values' range)");
  }
  if (out.y_min && !(*out.y_min < *out.y_max)) {
    in.fail("y_min", "y_min (" + format_number(*out.y_min) + ") must be below y_max (" +
                         format_number(*out.y_max) + ")");
  }
  out.unit = in.optional_string("unit", out.unit);
  out.anchor = read_anchor(in, "top-right");
  out.offset = in.has("offset") ? read_offset(in) : default_offset(out.anchor);
  if (in.has("size")) {
    const toml::array* array = in.table().get("size")->as_array();
    if (!array || array->size() != 2) in.fail("size", "expected [width, height] (px at 720 rows)");
    out.size =
        Eigen::Vector2d(in.number("size", *array->get(0)), in.number("size", *array->get(1)));
    if (!(out.size.x() >= 120.0 && out.size.y() >= 80.0 && out.size.maxCoeff() <= 4000.0)) {
      in.fail("size", "must be at least [120, 80] and at most 4000 px at 720 rows");
    }
  }
  out.text_size = in.optional_number("text_size", out.text_size);
  // Its margins take 6 em across and 4 em down: the graph keeps at least half the plot.
  const double largest = std::min(out.size.x() / 12.0, out.size.y() / 8.0);
  if (!(out.text_size >= 6.0 && out.text_size <= largest)) {
    in.fail("text_size", "must be at least 6 and at most " + format_number(largest) +
                             " px at 720 rows for a plot of this size (a twelfth of its width "
                             "and an eighth of its height: its graph keeps half of it)");
  }
  out.background = in.optional_rgba("background", out.background);
  out.ink = in.optional_rgba("color", out.ink);
  return out;
}

OverlaySpec read_overlay(TableReader& in, const Scene& scene) {
  const std::string kind = in.required_string("kind");
  OverlaySpec out;
  if (kind == "text") {
    out = read_text(in, scene);
  } else if (kind == "vector") {
    out = read_vector(in, scene);
  } else if (kind == "trail") {
    out = read_trail(in, scene);
  } else if (kind == "axes") {
    out = read_axes(in, scene);
  } else if (kind == "plot") {
    out = read_plot(in, scene);
  } else {
    in.fail("kind", "unknown overlay kind " + in_quotes(kind) +
                        " (expected text, vector, trail, axes or plot)");
  }
  in.reject_unknown_keys();
  return out;
}

}  // namespace

void read_overlays(TableReader& root, Scene& scene) {
  if (!root.has("overlays")) return;
  const toml::array* overlays = root.table().get("overlays")->as_array();
  if (!overlays) root.fail("overlays", "expected [[overlays]] tables");
  root.each_table(
      *overlays, "overlays", kMaxOverlays, "an [[overlays]] table",
      [&](TableReader& in, std::size_t) { scene.overlays.push_back(read_overlay(in, scene)); });
}

}  // namespace tumble::scene::detail
