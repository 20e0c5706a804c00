// What the renderer draws, as plain data: a camera, lights, boxes with poses, quads and text
// over the picture. It knows nothing of bodies, planes, forces or time.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/anchor.hpp"
#include "common/render_settings.hpp"
#include "render/offscreen_context.hpp"

namespace tumble::render {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

// The picture's settings (size, smoothing, colours, light, ground) are plain data the scene
// reads too: they live in common/, named here as render's own.
using common::Color;
using common::DirectionalLight;
using common::Ground;
using common::kEdgeFilter;
// sRGB-encoded colour and a straight (not premultiplied) opacity, each in [0, 1].
using Rgba = Eigen::Vector4d;

struct Camera {
  Vec3 position = Vec3(4.0, 3.0, 6.0);  // world frame (m)
  Vec3 look_at = Vec3::Zero();          // world frame (m)
  Vec3 up = Vec3::UnitY();              // world frame, need not be unit
  double fov_degrees = 40.0;            // vertical field of view
};

// What a Box draws: the box itself, or the round solid inside it. The round ones are smooth,
// with dark lines where the planes x = 0, y = 0 and z = 0 of the body meet their surface (a
// ball's three great circles), so that their turning reads.
enum class Solid : std::uint8_t {
  box,
  ball,      // the sphere the box holds: its size is the diameter along every axis
  capsule,   // along body y: size (2r, length + 2r, 2r), r the radius
  cylinder,  // along body y: size (2r, length, 2r)
  // A convex hull (RenderSettings::hulls[Box::mesh]), its size the box around it: flat-shaded per
  // face, with dark edges.
  hull,
};

// A convex hull's surface, body frame (m): its corners, its faces as polygons wound
// counter-clockwise seen from outside, and their outward normals.
struct HullMesh {
  std::vector<Vec3> corners;
  std::vector<std::vector<std::uint32_t>> faces;
  std::vector<Vec3> normals;
};

// A box (a cube when the edges are equal) at a pose, or the ball inside it.
struct Box {
  Vec3 position = Vec3::Zero();          // centre, world frame (m)
  Quat orientation = Quat::Identity();   // body-to-world rotation
  Vec3 size = Vec3::Ones();              // edge lengths along the body axes (m)
  Color color = Color(0.85, 0.35, 0.2);  // sRGB
  Solid solid = Solid::box;
  std::uint32_t mesh = 0;  // Solid::hull: its index in RenderSettings::hulls
};

// A finite piece of a plane (a wall, a slope, a raised floor): matte, gridded, framed by a dark
// border, lit, casting and receiving shadows. Seen from its back it is a pane of glass instead:
// drawn translucent after the boxes and casting no shadow, so that a wall between the camera and
// the boxes never hides or darkens them.
struct Quad {
  Vec3 center = Vec3::Zero();             // world frame (m)
  Quat orientation = Quat::Identity();    // quad to world: edges along local x and z, front along y
  double width = 1.0;                     // edge along local x (m)
  double depth = 1.0;                     // edge along local z (m)
  Color color = Color(0.62, 0.64, 0.66);  // sRGB
  double grid_spacing = 1.0;              // m between grid lines, from the centre; 0 = no grid
};

// Where on the frame a text's box sits (common/anchor.hpp).
using common::Anchor;

// Text over the picture (a title, a caption, a live value), drawn after the scene. Sizes are
// given for a 720-row frame and scale with the frame's height, so that a render at 180 or 2160
// rows shows the same layout.
struct Text {
  std::string text;                  // UTF-8, '\n' between lines
  Anchor anchor = Anchor::kTopLeft;  // of the frame, and of the text's box
  Eigen::Vector2d offset =
      Eigen::Vector2d::Zero();            // box from the anchor, x right, y down (px at 720 rows)
  double height = 32.0;                   // em size (px at 720 rows)
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);  // of the glyphs
  std::optional<Rgba> background = std::nullopt;  // a box behind the text, padded around it
  double opacity = 1.0;                           // of glyphs and box together, to fade (0-1)
  // A label's (Label): its box pushed inside the frame, then down clear of the boxes of the
  // earlier texts that keep apart, so that labels never cover each other (place_apart).
  bool keep_apart = false;
};

// An arrow in the 3D scene (a body's vector, one of its axes): a shaft and a head of fixed widths
// on the picture (overlay_geometry.hpp), so that it reads alike near and far.
// One shorter than kMinArrowPixels on the picture (a zero vector, or one pointing at the camera)
// draws neither itself nor its label.
struct Arrow {
  Vec3 from = Vec3::Zero();  // world frame (m)
  Vec3 to = Vec3::UnitX();   // the tip, world frame (m)
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);
  std::string label = {};      // UTF-8 text at the tip, as a Label there; empty for none
  double label_height = 28.0;  // its em size (px at 720 rows)
};
// px at 720 rows: below this an arrow's direction cannot be read.
inline constexpr double kMinArrowPixels = 3.0;

// A line through points of the 3D scene (a trail), each point with an opacity of its own so that
// the line can fade along its length. Fixed width on the picture.
struct Polyline {
  std::vector<Vec3> points;     // world frame (m)
  std::vector<double> opacity;  // one per point (0-1), times color's
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);
};

// Text at a point of the 3D scene (an arrow's name at its tip, a caption that follows a body):
// its box's left edge just right of the point on the picture (and `offset` from there), centred
// on it vertically. Kept inside the frame, and moved down clear of the labels drawn before it
// (Text::keep_apart). Not drawn when the point is behind the camera.
struct Label {
  std::string text;              // UTF-8
  Vec3 position = Vec3::Zero();  // world frame (m)
  double height = 28.0;          // em size (px at 720 rows)
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // x right, y down (px at 720 rows)
  std::optional<Rgba> background = std::nullopt;     // a box behind the text
  double opacity = 1.0;                              // of glyphs and box together (0-1)
};

// A filled rectangle on the picture (a plot's background), in px at 720 rows from the frame's
// top-left corner, x right, y down: it scales with the frame's height, as Text does.
struct Panel {
  Eigen::Vector2d corner = Eigen::Vector2d::Zero();  // top-left
  Eigen::Vector2d size = Eigen::Vector2d::Zero();    // width, height
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);
};

// A line through points on the picture (a plot's curve, axis or tick), antialiased, `width` px
// at 720 rows wide, in px at 720 rows from the frame's top-left corner as Panel.
struct Stroke {
  std::vector<Eigen::Vector2d> points;
  double width = 2.0;
  Rgba color = Rgba(1.0, 1.0, 1.0, 1.0);
};

// Fixed for a whole render: what the scene asks for (common/render_settings.hpp, with the back
// end that draws it), and the font its text is drawn in.
struct RenderSettings : common::RenderSettings {
  // The fontconfig family FrameView::texts are drawn in (kDefaultFontFamily, render/font.hpp,
  // unless the scene chooses); empty for a render without text, which then loads no font.
  std::string font;
  // Whether frames may have lines and arrows (FrameView::lines, arrows): only then are their
  // shaders built.
  bool overlays = false;
  // Whether frames may have round solids (Solid::ball, capsule, cylinder): only then are their
  // shaders built and their meshes set up.
  bool round_solids = false;
  // The hulls frames may have (Solid::hull), with the size of the box each is drawn in (m): each
  // is one mesh, set up once, drawn instanced for every body of it.
  std::vector<HullMesh> hulls = {};
  std::vector<Vec3> hull_sizes = {};
};

// Changes every frame.
struct FrameView {
  Camera camera;
  std::vector<Box> boxes;
  // Motion blur: the boxes at each of the pictures the frame averages, in time order; when not
  // empty they are drawn in place of `boxes`, each picture with the same camera, quads and
  // overlays, and the pictures averaged in linear light before panels and texts are drawn.
  std::vector<std::vector<Box>> blurred_boxes;
  std::vector<Quad> quads;
  // Overlays, drawn after the scene in this order: lines and arrows (over the scene, fainter
  // where it hides them), then labels and texts (over everything; they need settings' font).
  std::vector<Polyline> lines;
  std::vector<Arrow> arrows;
  std::vector<Label> labels;
  // Drawn over the picture after lines and arrows, before labels and texts: panels, then
  // strokes, each in order (sketch_layer.hpp).
  std::vector<Panel> panels;
  std::vector<Stroke> strokes;
  std::vector<Text> texts;  // drawn in order, each over the ones before
};

}  // namespace tumble::render
