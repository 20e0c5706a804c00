// What a scene's [[overlays]] ask to be drawn over its bodies, as plain data checked at load:
// texts with live values, arrows of a body's vectors, trails of a body point, a body's axes.
// The values are computed per frame outside the scene (app/overlay_values.hpp), from the
// interpolated state the frame shows.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "common/anchor.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::scene {

// sRGB-encoded colour and a straight (not premultiplied) opacity, each in [0, 1].
using Rgba = Eigen::Vector4d;

// What a text placeholder reads from a body's state (world frame, SI units).
enum class BodyQuantity {
  position,          // of the centre (m)
  velocity,          // of the centre (m/s)
  speed,             // |velocity| (m/s)
  angular_velocity,  // rad/s
  angular_speed,     // |angular_velocity| (rad/s)
  angular_momentum,  // about the centre (kg m²/s)
  kinetic_energy     // translational + rotational (J)
};

// What a text placeholder reads from a joint (physics::joint_coordinate, physics::joint_wrenches).
enum class JointQuantity {
  angle,  // a hinge's angle from t = 0 (rad)
  speed,  // a hinge's rate (rad/s), a slider's (m/s), a distance's rate of length (m/s)
  force   // the force it applies to body_a, world frame (N)
};

// One {…} of a text overlay, resolved against the scene's bodies and joints at load.
struct Placeholder {
  enum class Source { time, frame, body, joint };
  Source source = Source::time;
  std::size_t body = 0;  // index into Scene::bodies, for Source::body
  BodyQuantity quantity = BodyQuantity::position;
  std::size_t joint = 0;  // index into Scene::joints, for Source::joint
  JointQuantity joint_quantity = JointQuantity::angle;
  int component = -1;     // 0, 1, 2 for .x .y .z of a vector quantity; -1 for the whole value
  int precision = 2;      // printf's precision: digits after the point (f, e), significant (g)
  char conversion = 'f';  // printf's f, e or g; {frame} is a whole number and takes neither
  // Python's format mini-language, the subset [[fill]align][sign][0][width]: the sign of a
  // positive number ('-' none, '+' a plus, ' ' a space), the width each number is padded to
  // (characters; 0 = none), with `fill`, aligned left '<', right '>', centred '^' or after the
  // sign '='.
  char sign = '-';
  int width = 0;
  char fill = ' ';
  char align = '>';
};

// A text overlay's text as parsed at load: literal pieces and placeholders in turn, so that a
// frame only formats numbers. Always pieces.size() == values.size() + 1.
struct TextTemplate {
  std::vector<std::string> pieces;  // UTF-8, with {{ and }} already turned into { and }
  std::vector<Placeholder> values;
};

// A title, a caption or a live value over the picture, shown while start <= t < end.
struct TextOverlay {
  TextTemplate text;
  common::Anchor anchor = common::Anchor::kTopLeft;
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // x right, y down (px at 720 rows)
  double size = 28.0;                                // em size (px at 720 rows)
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);
  std::optional<Rgba> background;                        // a box behind the text
  double start = 0.0;                                    // s
  double end = std::numeric_limits<double>::infinity();  // s
  double fade = 0.0;  // s of fading in after start and out before end
  // A text that follows a body (`body = "NAME"`): drawn at `point` of it (body frame, m) as a
  // label is (render::Label: beside the point, `offset` from there, kept inside the frame and
  // clear of other labels); its `anchor` is then not used.
  std::optional<std::size_t> body;
  physics::Vec3 point = physics::Vec3::Zero();
};

// What a vector overlay's arrow shows.
enum class VectorQuantity {
  velocity,          // of the arrow's start point (m/s)
  angular_velocity,  // rad/s
  angular_momentum,  // about the centre (kg m²/s)
  force,             // the sum of some of the body's force laws (N)
  constant,          // a fixed world vector
  joint_force,       // the force a joint applies to its body_a (N), at its anchor
  contact_force,     // the total contact force on the body (N), at its centre of pressure
  torque             // the torque of some of the body's force laws about its centre (N m)
};

// An arrow from a body's centre (or a body point) along one of its vectors.
struct VectorOverlay {
  std::size_t body = 0;   // index into Scene::bodies (a joint's body_a for joint_force)
  std::size_t joint = 0;  // for joint_force: index into Scene::joints
  VectorQuantity quantity = VectorQuantity::velocity;
  std::vector<std::size_t> laws;  // for force: indices into the body's forces, summed
  physics::Vec3 constant = physics::Vec3::Zero();  // for constant: world frame
  physics::Vec3 point = physics::Vec3::Zero();     // where the arrow starts, body frame (m)
  double scale = 1.0;                              // m of arrow per unit of the quantity
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);
  std::string label;  // UTF-8, drawn at the tip; empty for none
};

// The path of a body point over the last `length` seconds, fading with age.
struct TrailOverlay {
  std::size_t body = 0;                         // index into Scene::bodies
  physics::Vec3 point = physics::Vec3::Zero();  // body frame (m)
  double length = 2.0;                          // s
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);
};

// The body's own x, y and z axes as arrows from its centre (red, green, blue).
struct AxesOverlay {
  std::size_t body = 0;  // index into Scene::bodies
  double length = 1.0;   // m of each arrow
};

// A live graph of numbers over the last `window` seconds (plot_view.hpp draws it): each value a
// placeholder of one number (a body's or a joint's quantity, or a vector's component), with its
// legend entry and colour; axes with ticks, the y axis's unit, a legend, all in the scene's font.
struct PlotOverlay {
  std::vector<Placeholder> values;
  std::vector<std::string> labels;     // UTF-8, one per value
  std::vector<Rgba> colors;            // one per value
  double window = 4.0;                 // s of the past shown
  std::optional<double> y_min, y_max;  // fixed; else the values' range so far, to round ticks
  std::string unit;                    // of the values, beside the y axis ("J"); may be empty
  common::Anchor anchor = common::Anchor::kTopRight;
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();      // x right, y down (px at 720 rows)
  Eigen::Vector2d size = Eigen::Vector2d(440.0, 240.0);  // px at 720 rows
  double text_size = 16.0;                               // em size of its text (px at 720 rows)
  Rgba background = Rgba(1.0, 1.0, 1.0, 0.85);
  Rgba ink = Rgba(0.15, 0.15, 0.17, 1.0);  // axes, ticks and their text
};

using OverlaySpec =
    std::variant<TextOverlay, VectorOverlay, TrailOverlay, AxesOverlay, PlotOverlay>;

}  // namespace tumble::scene
