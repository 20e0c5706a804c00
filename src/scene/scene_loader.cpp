#include "scene/scene_loader.hpp"

#include "scene/body_arrays.hpp"
#include "scene/joint_tables.hpp"
#include "scene/key_depth.hpp"
#include "scene/limits.hpp"
#include "scene/mesh_file.hpp"
#include "scene/orientation_keys.hpp"
#include "scene/overlay_tables.hpp"
#include "scene/plane_tables.hpp"
#include "scene/render_tables.hpp"
#include "scene/scene_builder.hpp"
#include "scene/table_reader.hpp"
#include "sim/simulation.hpp"

#include <toml++/toml.h>
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <variant>
#include <vector>

namespace tumble::scene {
namespace {

using namespace detail;

constexpr double kLargest = std::numeric_limits<double>::max();

// `start` and `end` (s) of a law that acts while start <= t < end, into `start` and `end`.
void read_acting_time(TableReader& in, double& start, double& end) {
  start = in.optional_number("start", start);
  end = in.optional_number("end", end);
  if (start > end) {
    in.fail("start",
            "start (" + format_number(start) + ") is after end (" + format_number(end) + ")");
  }
}

// anchor_keys = [{ time = t, anchor = [x, y, z] }, ...]: at least one key, times strictly
// increasing, each anchor and each segment's speed within what a body may have.
std::vector<physics::AnchorKey> read_anchor_keys(TableReader& in) {
  const toml::array* array = in.table().get("anchor_keys")->as_array();
  const char* form = "[{ time = t, anchor = [x, y, z] }, ...]";
  if (!array) in.fail("anchor_keys", std::string("expected an array of keys ") + form);
  if (array->empty()) in.fail("anchor_keys", std::string("expected at least one key ") + form);
  std::vector<physics::AnchorKey> keys;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string path = in.qualified("anchor_keys") + "[" + std::to_string(i) + "]";
    const toml::table* table = (*array)[i].as_table();
    if (!table)
      in.fail_at((*array)[i].source(), path, "expected a key { time = t, anchor = [x, y, z] }");
    TableReader key(*table, path, in.file());
    const double time = key.required_number("time");
    const Vec3 anchor =
        vector_within(key, "anchor", key.required_vector("anchor"), sim::kMaxPosition, "m");
    key.reject_unknown_keys();
    if (!keys.empty()) {
      const physics::AnchorKey& previous = keys.back();
      if (!(time > previous.time)) {
        key.fail("time", "must be after the previous key's time " + format_number(previous.time) +
                             " s (got " + format_number(time) + " s)");
      }
      // The anchor's velocity enters the damper: a large move in next to no time would kick the
      // body past anything a run survives.
      const double speed = (anchor - previous.anchor).stableNorm() / (time - previous.time);
      if (!(speed <= sim::kMaxSpeed)) {
        key.fail("anchor", "it moves at " + format_number(speed) +
                               " m/s from the previous key, past the " +
                               format_number(sim::kMaxSpeed) + " m/s tumble can simulate");
      }
    }
    keys.push_back({.time = time, .anchor = anchor});
  }
  return keys;
}

// A spring takes either a fixed `anchor` or moving `anchor_keys`; read last, so that a misspelt
// one is reported as the unknown key it is.
physics::Spring read_spring(TableReader& in) {
  physics::Spring spring{
      .attachment = vector_within(in, "attachment", in.optional_vector("attachment", Vec3::Zero()),
                                  sim::kMaxPosition, "m"),
      .stiffness = in.required_number("stiffness")};
  spring.damping = in.optional_number("damping", 0.0);
  spring.rest_length = in.optional_number("rest_length", 0.0);
  require_non_negative(in, "stiffness", spring.stiffness);
  require_non_negative(in, "damping", spring.damping);
  require_non_negative(in, "rest_length", spring.rest_length);
  read_acting_time(in, spring.start, spring.end);
  const bool fixed = in.has("anchor");
  const bool moving = in.has("anchor_keys");
  if (fixed && moving) {
    in.fail("anchor_keys", "give either anchor (fixed) or anchor_keys (moving), not both");
  } else if (fixed) {
    spring.anchor =
        vector_within(in, "anchor", in.required_vector("anchor"), sim::kMaxPosition, "m");
  } else if (moving) {
    spring.anchor_keys = read_anchor_keys(in);
  } else {
    in.reject_unknown_keys();
    in.fail(
        "anchor",
        "missing required key: a spring needs anchor = [x, y, z] (fixed) or anchor_keys (moving)");
  }
  return spring;
}

physics::ForceLaw read_force(TableReader& in) {
  const std::string kind = in.required_string("kind");
  physics::ForceLaw law;
  if (kind == "gravity") {
    law = physics::Gravity{.acceleration = vector_within(
                               in, "acceleration",
                               in.optional_vector("acceleration", physics::Gravity{}.acceleration),
                               kLargest, "m/s²")};
  } else if (kind == "force") {
    law = physics::ConstantForce{
        .force = vector_within(in, "force", in.required_vector("force"), kLargest, "N")};
  } else if (kind == "torque") {
    law = physics::ConstantTorque{
        .torque = vector_within(in, "torque", in.required_vector("torque"), kLargest, "N m")};
  } else if (kind == "linear_damping" || kind == "angular_damping") {
    const double coefficient = in.required_number("coefficient");
    require_non_negative(in, "coefficient", coefficient);
    if (kind == "linear_damping") {
      law = physics::LinearDamping{.coefficient = coefficient};
    } else {
      law = physics::AngularDamping{.coefficient = coefficient};
    }
  } else if (kind == "force_at_point") {
    physics::ForceAtPoint push{
        .force = vector_within(in, "force", in.required_vector("force"), kLargest, "N"),
        .point = vector_within(in, "point", in.required_vector("point"), sim::kMaxPosition, "m")};
    read_acting_time(in, push.start, push.end);
    law = push;
  } else if (kind == "spring") {
    law = read_spring(in);
  } else {
    in.fail("kind", "unknown force kind " + in_quotes(kind) +
                        " (expected gravity, force, torque, linear_damping, angular_damping, "
                        "force_at_point or spring)");
  }
  in.reject_unknown_keys();
  return law;
}

// What the scene's contact cannot hold, refused at its key: penalty contact's corner springs hold
// no sphere, static body or rolling resistance; and a static body among bodies that do not
// collide would be passed through.
void refuse_what_the_contact_cannot_hold(TableReader& in, const BodySpec& body,
                                         const PhysicsSettings& physics) {
  const auto fail_unless_impulse = [&](const char* key, const std::string& what) {
    if (physics.contact.method == physics::ContactMethod::penalty) {
      in.fail(key, what +
                       " needs [physics] contact = \"impulse\" (the default): penalty "
                       "contact's springs sit at a box's corners");
    }
  };
  if (body.shape == Shape::sphere) fail_unless_impulse("shape", "a sphere");
  if (body.shape == Shape::capsule) fail_unless_impulse("shape", "a capsule");
  if (body.shape == Shape::cylinder) fail_unless_impulse("shape", "a cylinder");
  if (body.shape == Shape::hull) fail_unless_impulse("shape", "a hull");
  if (body.is_static) fail_unless_impulse("static", "a static body");
  if (in.has("rolling_resistance")) fail_unless_impulse("rolling_resistance", "rolling resistance");
  if (body.is_static && !physics.contact.collide_bodies) {
    in.fail("static",
            "a static body with [physics] collide_bodies = false is passed through by "
            "every body: let bodies collide, or use a plane");
  }
}

// A hull body's corners, from `points` or the vertices of `mesh` (relative to the scene file)
// times `scale`, made a hull of the body's mass; its size the box around it.
void read_hull(TableReader& in, const std::string& file, BodySpec& body) {
  const bool has_points = in.has("points"), has_mesh = in.has("mesh");
  if (has_points == has_mesh) {
    in.fail(has_points ? "mesh" : "shape",
            "a hull takes `points` (its corners, m) or `mesh` (an OBJ or STL file), one of them");
  }
  std::vector<Vec3> points;
  const char* key = has_points ? "points" : "mesh";
  if (has_points) {
    if (in.has("scale")) in.fail("scale", "`scale` applies to a mesh's vertices");
    const toml::array* list = in.table().get("points")->as_array();
    if (!list) in.fail("points", "expected an array of points [[x, y, z], ...]");
    if (list->size() > kMostHullPoints) {
      in.fail("points", "at most " + std::to_string(kMostHullPoints) + " points");
    }
    for (const toml::node& point : *list) points.push_back(in.vector("points", point));
  } else {
    const double scale = in.optional_number("scale", 1.0);
    require_positive(in, "scale", scale);
    const std::string mesh = in.required_string("mesh");
    const std::filesystem::path at = std::filesystem::path(file).parent_path() / mesh;
    Result<std::vector<Vec3>> read = read_mesh_vertices(at.string(), scale);
    if (!read) in.fail("mesh", read.error());
    points = std::move(read).value();
  }
  Result<physics::HullBody> made = physics::hull_body(points, body.mass > 0.0 ? body.mass : 1.0);
  if (!made) in.fail(key, made.error());
  body.hull = std::make_shared<const physics::HullBody>(std::move(made).value());
  Vec3 reach = Vec3::Zero();
  for (const Vec3& v : body.hull->hull->vertices) reach = reach.cwiseMax(v.cwiseAbs());
  body.size = 2.0 * reach;
}

BodySpec read_body(TableReader& in, std::size_t index, const std::string& file) {
  BodySpec body;
  body.name = in.optional_string("name", "body" + std::to_string(index));
  if (!is_safe_name(body.name)) in.fail("name", kSafeNameRule);
  const std::string shape = in.required_string("shape");
  if (shape != "cube" && shape != "box" && shape != "sphere" && shape != "capsule" &&
      shape != "cylinder" && shape != "hull") {
    in.fail("shape", "unknown shape " + in_quotes(shape) +
                         " (expected cube, box, sphere, capsule, cylinder or hull)");
  }
  if (shape != "hull") {
    for (const char* key : {"points", "mesh", "scale"}) {
      if (in.has(key)) in.fail(key, std::string("only a hull takes ") + key);
    }
  }
  const bool round = shape == "sphere" || shape == "capsule" || shape == "cylinder";
  if (shape != "capsule" && shape != "cylinder" && in.has("length")) {
    in.fail("length", "only a capsule or a cylinder has a length (a " + shape + " has " +
                          (shape == "sphere" ? "a radius)" : "a size)"));
  }
  if (shape == "hull") {
    body.shape = Shape::hull;
    for (const char* key : {"size", "radius", "length"}) {
      if (in.has(key)) in.fail(key, std::string("a hull has points or a mesh, not a ") + key);
    }
  } else if (round) {
    body.shape = shape == "sphere"    ? Shape::sphere
                 : shape == "capsule" ? Shape::capsule
                                      : Shape::cylinder;
    if (in.has("size")) in.fail("size", "a " + shape + " has a radius, not a size");
    body.radius = in.required_number("radius");
    require_positive(in, "radius", body.radius);
    if (body.shape == Shape::capsule) {
      body.length = in.required_number("length");
      if (!(body.length >= 0.0)) {
        in.fail("length", "a capsule's length (between its end centres) must be 0 or more");
      }
    }
    if (body.shape == Shape::cylinder) {
      body.length = in.required_number("length");
      require_positive(in, "length", body.length);
    }
    const double ends = body.shape == Shape::cylinder ? 0.0 : 2.0 * body.radius;
    body.size = Vec3(2.0 * body.radius, body.length + ends, 2.0 * body.radius);
  } else {
    if (in.has("radius"))
      in.fail("radius",
              "only a sphere, a capsule or a cylinder has a radius (a " + shape + " has a size)");
    const toml::node& size = in.required("size");
    if (shape == "cube") {
      body.shape = Shape::cube;
      if (size.is_array())
        in.fail("size", "a cube's size is its side, one number (a box takes [x, y, z])");
      body.size = Vec3::Constant(in.number("size", size));
    } else {
      body.shape = Shape::box;
      body.size = in.vector("size", size);
    }
    if (!(body.size.minCoeff() > 0.0)) in.fail("size", "every edge must be greater than 0");
  }
  body.is_static = in.optional_bool("static", false);
  if (body.is_static) {
    // Fixed in the world: it needs no mass (one written is not used) and cannot move.
    for (const char* key : {"velocity", "angular_velocity", "forces"}) {
      if (in.has(key)) in.fail(key, std::string("a static body never moves: it takes no ") + key);
    }
    if (in.optional_bool("collide", true) == false) {
      in.fail("collide",
              "a static body that collides with nothing is only scenery: leave it out "
              "or let it collide");
    }
    body.mass = in.optional_number("mass", 1.0);  // 0 allowed, as other engines write a static
    require_non_negative(in, "mass", body.mass);
  } else {
    body.mass = in.required_number("mass");
    require_positive(in, "mass", body.mass);
  }
  if (body.shape == Shape::hull) read_hull(in, file, body);
  const physics::BodyConstants constants = body_constants(body);
  if (!(std::isfinite(constants.inverse_mass) && constants.inverse_inertia.allFinite() &&
        constants.inertia.allFinite())) {
    in.fail("mass", "with this size, the moments of inertia are beyond double precision");
  }
  body.position = in.optional_vector("position", Vec3::Zero());
  body.velocity = in.optional_vector("velocity", Vec3::Zero());
  body.orientation = read_orientation(in);
  // A hull's body axes are its principal axes, turned from the frame its points were given in.
  if (body.hull) body.orientation = (body.orientation * Quat(body.hull->axes)).normalized();
  body.angular_velocity = in.optional_vector("angular_velocity", Vec3::Zero());
  vector_within(in, "position", body.position, sim::kMaxPosition, "m");
  vector_within(in, "velocity", body.velocity, sim::kMaxSpeed, "m/s");
  vector_within(in, "angular_velocity", body.angular_velocity, sim::kMaxAngularSpeed, "rad/s");
  const physics::BodyState start = initial_state(body);
  if (!start.primary().momentum.allFinite()) {
    in.fail("velocity", "with this mass the momentum is beyond double precision");
  }
  if (!start.primary().angular_momentum.allFinite()) {
    in.fail("angular_velocity",
            "with this mass and size the angular momentum is beyond double precision");
  }
  if (!std::isfinite(physics::kinetic_energy(start))) {
    in.fail("mass", "with this mass and motion the kinetic energy is beyond double precision");
  }
  body.material = read_material(in, body.material);
  body.collide = in.optional_bool("collide", body.collide);
  body.color = in.optional_color("color", default_body_color(index));
  if (in.has("forces")) {
    const toml::array* forces = in.table().get("forces")->as_array();
    if (!forces) in.fail("forces", "expected [[bodies.forces]] tables");
    if (forces->size() > static_cast<std::size_t>(kMaxForcesPerBody)) {
      in.fail("forces", std::to_string(forces->size()) + " force laws, more than the limit of " +
                            std::to_string(kMaxForcesPerBody) + " per body");
    }
    for (std::size_t i = 0; i < forces->size(); ++i) {
      const toml::table* table = (*forces)[i].as_table();
      const std::string path = in.path() + ".forces[" + std::to_string(i) + "]";
      if (!table) in.fail_at((*forces)[i].source(), path, "expected a table");
      TableReader force(*table, path, file);
      body.forces.push_back(read_force(force));
      // A hull's points on it are given in the frame of its points, as they are.
      if (body.hull) {
        if (auto* push = std::get_if<physics::ForceAtPoint>(&body.forces.back())) {
          push->point = body.hull->body_point(push->point);
        }
        auto* spring = std::get_if<physics::Spring>(&body.forces.back());
        if (spring && force.has("attachment")) {
          spring->attachment = body.hull->body_point(spring->attachment);
        }
      }
    }
  }
  return body;
}

// [physics] gravity: a law of its own ahead of the body's laws, for every moving body whose
// table lists no gravity law (its own wins); written first, it is summed as a body's first law.
void add_scene_gravity(BodySpec& body, const std::optional<Vec3>& gravity) {
  if (!gravity || body.is_static) return;
  for (const physics::ForceLaw& law : body.forces) {
    if (std::holds_alternative<physics::Gravity>(law)) return;
  }
  body.forces.insert(body.forces.begin(), physics::Gravity{.acceleration = *gravity});
}

// The bodies of one [[bodies]] table, the `index`-th body of the scene first: one, or an array's.
std::vector<BodySpec> read_bodies(TableReader& in, std::size_t index, const std::string& file,
                                  const std::optional<Vec3>& gravity) {
  BodySpec body = read_body(in, index, file);
  add_scene_gravity(body, gravity);
  const BodyArray array = read_body_array(in, body.position);
  in.reject_unknown_keys();
  return expand_body_array(in, body, array, index);
}

Scene read_scene(const toml::table& root, const std::string& file) {
  Scene scene;
  scene.source_path = file;
  TableReader in(root, "", file);
  const bool named = in.has("name");
  scene.name = in.optional_string("name", std::filesystem::path(file).stem().string());
  if (!is_safe_name(scene.name)) {
    in.fail("name", std::string(named ? "" : "missing, and the file name ") +
                        (named ? "" : in_quotes(scene.name) + " cannot stand in for it: ") +
                        "must be 1-100 letters, digits, '_', '-' or '.', not starting with '.' "
                        "(it names the output folder)");
  }
  scene.duration = in.required_number("duration");
  require_positive(in, "duration", scene.duration);

  std::optional<Vec3> gravity;  // m/s², world frame: [physics] gravity
  if (in.has("physics")) {
    const toml::table* table = root.get("physics")->as_table();
    if (!table) in.fail("physics", "expected a [physics] table");
    TableReader physics(*table, "physics", file);
    if (physics.has("gravity")) {
      gravity =
          vector_within(physics, "gravity", physics.required_vector("gravity"), kLargest, "m/s²");
    }
    scene.physics.dt = physics.optional_number("dt", scene.physics.dt);
    require_positive(physics, "dt", scene.physics.dt);
    const std::string name = physics.optional_string(
        "integrator", std::string(physics::integrator_name(scene.physics.integrator)));
    const auto integrator = physics::integrator_from_name(name);
    if (!integrator) {
      std::string known;
      for (const auto i : physics::kAllIntegrators) {
        known += (known.empty() ? "" : ", ") + std::string(physics::integrator_name(i));
      }
      physics.fail("integrator",
                   "unknown integrator " + in_quotes(name) + " (expected " + known + ")");
    }
    scene.physics.integrator = *integrator;
    scene.physics.contact = read_contact_settings(physics);
    physics.reject_unknown_keys();
  }
  // Checked whether dt was written or defaulted; blamed on dt if written, else on duration.
  const bool dt_written = root.at_path("physics.dt").node() != nullptr;
  const auto fail_on_dt = [&](const std::string& what) {
    if (dt_written) {
      TableReader(*root.get("physics")->as_table(), "physics", file).fail("dt", what);
    }
    in.fail("duration", what + " (dt defaults to " + format_number(scene.physics.dt) + " s)");
  };
  if (scene.physics.dt > scene.duration) {
    fail_on_dt("step " + format_number(scene.physics.dt) + " s is longer than duration " +
               format_number(scene.duration) + " s");
  }
  if (scene.duration / scene.physics.dt > static_cast<double>(kMaxSteps)) {
    fail_on_dt("duration / dt asks for more than " + std::to_string(kMaxSteps) + " steps");
  }

  const toml::array* bodies = in.required("bodies").as_array();
  if (!bodies || bodies->empty()) in.fail("bodies", "expected at least one [[bodies]] table");
  std::set<std::string> names;
  std::vector<std::size_t> table_of_body;  // which [[bodies]] table wrote each body
  in.each_table(*bodies, "bodies", static_cast<std::size_t>(kMaxBodies), "a [[bodies]] table",
                [&](TableReader& body, std::size_t i) {
                  for (BodySpec& made : read_bodies(body, scene.bodies.size(), file, gravity)) {
                    refuse_what_the_contact_cannot_hold(body, made, scene.physics);
                    if (!names.insert(made.name).second) {
                      body.fail("name", "duplicate body name \"" + made.name + "\"");
                    }
                    scene.bodies.push_back(std::move(made));
                    table_of_body.push_back(i);
                  }
                  if (scene.bodies.size() > static_cast<std::size_t>(kMaxBodies)) {
                    body.fail("count", std::to_string(scene.bodies.size()) +
                                           " bodies in all, more than the limit of " +
                                           std::to_string(kMaxBodies));
                  }
                });
  const double body_steps =
      static_cast<double>(scene.bodies.size()) * (scene.duration / scene.physics.dt);
  if (body_steps > static_cast<double>(kMaxBodySteps)) {
    char what[160];
    std::snprintf(what, sizeof what,
                  "%zu bodies × duration / dt asks for %.3g body steps, more than the limit of "
                  "%.0e",
                  scene.bodies.size(), body_steps, static_cast<double>(kMaxBodySteps));
    fail_on_dt(what);
  }
  read_planes(in, scene, table_of_body);
  read_joints(in, scene);
  refuse_overlapping_bodies(in, scene, table_of_body);
  read_render_tables(in, scene);
  read_overlays(in, scene);
  in.reject_unknown_keys();
  return scene;
}

}  // namespace

Result<Scene> parse_scene(std::string_view text, const std::string& path) {
  if (const std::optional<TextPosition> at = find_overlong_dotted_key(text)) {
    return Error{path + ':' + std::to_string(at->line) + ':' + std::to_string(at->column) +
                 ": a dotted key of more than " + std::to_string(kMaxKeyParts) +
                 " parts (scene keys have at most 3)"};
  }
  try {
    const toml::table root = toml::parse(text, path);
    return read_scene(root, path);
  } catch (const toml::parse_error& error) {
    std::ostringstream out;
    out << path << ':' << error.source().begin.line << ':' << error.source().begin.column
        << ": TOML syntax error: " << error.description();
    return Error{out.str()};
  } catch (const LoadFailure& failure) {
    return Error{failure.what()};
  }
}

Result<std::string> read_scene_text(const std::string& path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    return Error{path + ": is a folder, not a scene file"};
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) return Error{path + ": cannot open scene file: " + std::strerror(errno)};
  std::string text;
  char chunk[1 << 16];
  while (file.read(chunk, sizeof chunk) || file.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(file.gcount()));
    if (text.size() > static_cast<std::size_t>(kMaxSceneFileBytes)) {
      return Error{path + ": scene file is larger than the limit of " +
                   std::to_string(kMaxSceneFileBytes / (1024 * 1024)) + " MB"};
    }
  }
  if (file.bad()) return Error{path + ": error reading scene file"};
  return text;
}

Result<Scene> load_scene_file(const std::string& path) {
  const Result<std::string> text = read_scene_text(path);
  if (!text) return Error{text.error()};
  return parse_scene(*text, path);
}

}  // namespace tumble::scene
