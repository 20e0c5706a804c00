// The scene as plain data, as read from a scene file and validated. Building the physics from it
// is scene_builder's job; drawing it is the app's and render's,
// which the scene never includes (cmake/check_layers.cmake).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/render_settings.hpp"
#include "common/video_format.hpp"
#include "physics/contact.hpp"
#include "physics/forces.hpp"
#include "physics/hull_shape.hpp"
#include "physics/integrators.hpp"
#include "physics/joints.hpp"
#include "physics/rigid_body.hpp"
#include "physics/shapes.hpp"
#include "scene/overlays.hpp"

namespace tumble::scene {

enum class Shape { cube, box, sphere, capsule, cylinder, hull };

struct BodySpec {
  std::string name;
  Shape shape = Shape::cube;
  // Edge lengths along the body axes (m); for a round shape, those of the box around it (a
  // sphere's 2r each; a capsule's 2r, length + 2r, 2r; a cylinder's 2r, length, 2r).
  physics::Vec3 size = physics::Vec3::Ones();
  double radius = 0.0;  // a sphere's, capsule's or cylinder's (m)
  // Along body y (m): a capsule's between its end centres, a cylinder's between its ends.
  double length = 0.0;
  // A hull's: its corners about its centre of mass and its constants (physics/hull_shape.hpp),
  // made once when the scene is read. `position` places its centre of mass and `orientation`
  // turns its body axes (its principal axes: the loader folds the turn from the points' frame in).
  std::shared_ptr<const physics::HullBody> hull;
  double mass = 1.0;                                       // kg
  physics::Vec3 position = physics::Vec3::Zero();          // world frame (m)
  physics::Vec3 velocity = physics::Vec3::Zero();          // world frame (m/s)
  physics::Quat orientation = physics::Quat::Identity();   // body-to-world, unit
  physics::Vec3 angular_velocity = physics::Vec3::Zero();  // world frame (rad/s)
  std::vector<physics::ForceLaw> forces;                   // only what the scene lists
  physics::Material material = {};                         // restitution 0, friction 0.5
  bool collide = true;     // with other bodies (planes stop every body)
  bool is_static = false;  // fixed in the world (`static = true`): never moves, no mass needed
  common::Color color = common::Color(0.85, 0.35, 0.2);  // sRGB
};

// A static plane, as written: `point` and the unit `normal` place it; `size` is only how much of
// it is drawn around `point`, since the contact plane is infinite.
struct PlaneSpec {
  std::string name;
  physics::Vec3 point = physics::Vec3::Zero();    // world frame (m)
  physics::Vec3 normal = physics::Vec3::UnitY();  // unit (normalised by the loader), world frame
  physics::Material material = {};                // restitution 0, friction 0.5
  bool visible = true;
  double size[2] = {20.0, 20.0};  // drawn extent along the plane's two in-plane axes (m)
};

// A [[joints]] table, as written: its anchors and axis in the world frame at t = 0, its bodies by
// index (physics::kWorldBody for the world). scene_builder places it on the bodies' start.
struct JointSpec {
  std::string name;
  physics::JointKind kind = physics::JointKind::ball;
  std::uint32_t body_a = 0;
  std::uint32_t body_b = physics::kWorldBody;
  physics::Vec3 anchor_a = physics::Vec3::Zero();  // world frame at t = 0 (m)
  physics::Vec3 anchor_b = physics::Vec3::Zero();  // the same point but for a distance (m)
  physics::Vec3 axis = physics::Vec3::UnitZ();     // hinge, slider: world frame at t = 0
  std::optional<physics::JointLimits> limits;      // rad (hinge) or m (slider)
  std::optional<physics::JointMotor> motor;
  // Distance: its range (m); both the anchors' distance at t = 0 unless written (a rod). With
  // stiffness > 0 (N/m, damping N s/m) a spring of that rest length, the range only a stop.
  double min_length = 0.0;
  double max_length = 0.0;
  double stiffness = 0.0;
  double damping = 0.0;
  bool collide_connected = false;
  bool visible = true;  // drawn: a rod or string between a distance's anchors, a pin at others'
};

struct PhysicsSettings {
  double dt = 0.01;  // fixed step (s)
  physics::Integrator integrator = physics::Integrator::rk4;
  physics::ContactSettings contact;  // used only when the scene has planes
};

// One [[camera.keys]] entry: where the camera is at `time`; between two keys it moves along an
// eased path (app/camera_path.hpp).
struct CameraKey {
  double time = 0.0;  // s, from 0 to the duration, increasing key to key
  physics::Vec3 position = physics::Vec3::Zero();  // world frame (m)
  physics::Vec3 look_at = physics::Vec3::Zero();   // world frame (m)
  double fov_degrees = 40.0;  // vertical; [camera] fov_degrees when not written
};

// The camera as written; what is left out is chosen to frame the whole motion.
struct CameraSpec {
  std::optional<physics::Vec3> position;  // world frame (m)
  std::optional<physics::Vec3> look_at;   // world frame (m)
  physics::Vec3 up = physics::Vec3::UnitY();
  double fov_degrees = 40.0;           // vertical
  std::string follow;                  // a body name: the camera keeps its offset to that body
  std::vector<CameraKey> keys;         // [[camera.keys]], in time order; none: a still camera
  std::optional<double> orbit_period;  // s per turn about `up` through the look-at point
};

struct OutputSpec {
  std::string directory;  // below the output root chosen on the command line; default: name
  bool frames = true;     // PNG frames
  bool video = true;      // the videos of `formats`; false: none
  std::vector<common::VideoFormat> formats = {common::VideoFormat::mp4};  // each once, in order
  bool gltf = false;     // <name>.glb: formats lists "gltf" (common/video_format.hpp), video or not
  bool html = false;     // <name>.html: formats lists "html", the replay page, video or not
  bool gif_loop = true;  // the GIF plays forever (else once)
  std::optional<int> gif_fps;  // the GIF's frames per second, at most fps (default: fps)
  int gif_colors = common::kMaxGifColors;                   // the GIF's palette, 2 to 256
  common::GifDither gif_dither = common::GifDither::bayer;  // how frames map onto it
  std::optional<double> poster_time;  // s; poster.png shows the frame nearest it (default: middle)
  int crf = 20;                       // x264 constant rate factor, 0 (lossless) to 51
  int webm_crf = 30;                  // VP9's constant quality, 0 (best) to 63
  std::string preset = "veryfast";    // x264 speed preset
};

// The flag of `output` that [output] formats (or --format) sets by `name` when it names a format
// that is no video ("gltf", "html"); null for any other name.
inline bool* file_format_flag(OutputSpec& output, std::string_view name) {
  if (name == common::kGltfFormatName) return &output.gltf;
  if (name == common::kHtmlFormatName) return &output.html;
  return nullptr;
}

struct Scene {
  std::string name;         // used for output folder and file names
  std::string source_path;  // the file it was read from, for messages
  double duration = 0.0;    // simulated time (s)
  PhysicsSettings physics;
  std::vector<BodySpec> bodies;
  std::vector<PlaneSpec> planes;  // in the order written; none means no contact code runs
  std::vector<JointSpec> joints;  // [[joints]], in the order written; none means no joint code runs
  // Rendering. The ground's height, when not written, is chosen below the whole motion; a scene
  // with planes has no ground_height (its floor is a plane, app/plane_view.hpp).
  common::RenderSettings render;
  std::optional<double> ground_height;  // m
  int fps = 60;                         // video frames per simulated second
  CameraSpec camera;
  OutputSpec output;
  // Drawn over the bodies in the order written ([[overlays]], scene/overlays.hpp); none means
  // no overlay code runs.
  std::vector<OverlaySpec> overlays;
  std::string font;  // [render] font: the fontconfig family texts are drawn in; "" = the default
};

}  // namespace tumble::scene
