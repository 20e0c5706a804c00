#include "scene/scene_loader.hpp"

#include "scene/scene_builder.hpp"

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace tumble::scene {
namespace {

using physics::Quat;
using physics::Vec3;

// Thrown inside the loader only; load_scene_file/parse_scene turn it into a SceneError.
struct LoadFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string_view type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a date or time";
  }
}

// Levenshtein distance, for "did you mean" hints on misspelt keys.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// A table being read: knows its dotted path for messages and which keys were asked for, so that
// every key nobody asked for can be reported as unknown.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string path, const std::string& file)
      : table_(table), path_(std::move(path)), file_(file) {}

  [[noreturn]] void fail_at(const toml::source_region& where, std::string_view key,
                            std::string_view what) const {
    std::ostringstream out;
    out << file_ << ':' << where.begin.line << ':' << where.begin.column << ": " << key << ": "
        << what;
    throw LoadFailure(out.str());
  }
  [[noreturn]] void fail(std::string_view key, std::string_view what) const {
    const toml::node* node = table_.get(key);
    fail_at(node ? node->source() : table_.source(), qualified(key), what);
  }

  std::string qualified(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }

  bool has(std::string_view key) {
    known_.insert(std::string(key));
    return table_.contains(key);
  }

  const toml::node& required(std::string_view key) {
    if (!has(key)) {
      // A missing key is often a misspelt one: point at the misspelling instead.
      for (auto&& [written, node] : table_) {
        if (!known_.count(std::string(written.str())) && edit_distance(written.str(), key) <= 2) {
          fail_at(written.source(), qualified(written.str()),
                  "unknown key (did you mean \"" + std::string(key) + "\"?)");
        }
      }
      fail_at(table_.source(), qualified(key),
              "missing required key" + (path_.empty() ? std::string() : " in " + path_));
    }
    return *table_.get(key);
  }

  double number(std::string_view key, const toml::node& node) const {
    if (!node.is_number()) {
      fail(key, "expected a number, found " + std::string(type_name(node)));
    }
    // toml++ will not convert integers beyond 2^53 to double; do it ourselves (rounding).
    const double value = node.is_integer() ? static_cast<double>(node.as_integer()->get())
                                           : node.as_floating_point()->get();
    if (!std::isfinite(value)) fail(key, "must be a finite number");
    return value;
  }

  double required_number(std::string_view key) { return number(key, required(key)); }
  double optional_number(std::string_view key, double fallback) {
    return has(key) ? number(key, *table_.get(key)) : fallback;
  }

  std::string required_string(std::string_view key) { return string(key, required(key)); }
  std::string optional_string(std::string_view key, std::string fallback) {
    return has(key) ? string(key, *table_.get(key)) : std::move(fallback);
  }

  Vec3 vector(std::string_view key, const toml::node& node) const {
    const toml::array* array = node.as_array();
    if (!array || array->size() != 3) {
      fail(key, "expected an array of 3 numbers [x, y, z], found " +
                    (array ? "an array of " + std::to_string(array->size())
                           : std::string(type_name(node))));
    }
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = number(key, (*array)[static_cast<std::size_t>(i)]);
    return out;
  }
  Vec3 required_vector(std::string_view key) { return vector(key, required(key)); }
  Vec3 optional_vector(std::string_view key, const Vec3& fallback) {
    return has(key) ? vector(key, *table_.get(key)) : fallback;
  }

  // A unit quaternion written [w, x, y, z]; a small normalisation error is forgiven.
  Quat optional_quaternion(std::string_view key) {
    if (!has(key)) return Quat::Identity();
    const toml::node& node = *table_.get(key);
    const toml::array* array = node.as_array();
    if (!array || array->size() != 4) {
      fail(key, "expected a unit quaternion [w, x, y, z], found " +
                    (array ? "an array of " + std::to_string(array->size())
                           : std::string(type_name(node))));
    }
    double c[4];
    for (std::size_t i = 0; i < 4; ++i) c[i] = number(key, (*array)[i]);
    const Quat q(c[0], c[1], c[2], c[3]);
    if (std::abs(q.norm() - 1.0) > 1e-3) {
      fail(key, "must be a unit quaternion [w, x, y, z] (its length is " + format_number(q.norm()) +
                    ")");
    }
    return q.normalized();
  }

  const toml::table& table() const { return table_; }
  const std::string& path() const { return path_; }

  // Call after reading every key the schema allows.
  void reject_unknown_keys() const {
    for (auto&& [key, node] : table_) {
      if (known_.count(std::string(key.str()))) continue;
      std::string allowed;
      for (const std::string& k : known_) allowed += (allowed.empty() ? "" : ", ") + k;
      fail_at(key.source(), qualified(key.str()), "unknown key (allowed here: " + allowed + ")");
    }
  }

 private:
  std::string string(std::string_view key, const toml::node& node) const {
    if (!node.is_string()) fail(key, "expected a string, found " + std::string(type_name(node)));
    return *node.value<std::string>();
  }

  const toml::table& table_;
  std::string path_;
  const std::string& file_;
  std::set<std::string> known_;
};

void require_positive(TableReader& reader, std::string_view key, double value) {
  if (!(value > 0.0)) reader.fail(key, "must be greater than 0 (got " + format_number(value) + ")");
}
void require_non_negative(TableReader& reader, std::string_view key, double value) {
  if (value < 0.0) reader.fail(key, "must not be negative (got " + format_number(value) + ")");
}

// Names become folder and file names: keep them to a safe alphabet.
bool is_safe_name(const std::string& name) {
  if (name.empty() || name.front() == '.' || name.size() > 100) return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

physics::ForceLaw read_force(TableReader& in) {
  const std::string kind = in.required_string("kind");
  physics::ForceLaw law;
  if (kind == "gravity") {
    law = physics::Gravity{.acceleration =
                               in.optional_vector("acceleration", physics::Gravity{}.acceleration)};
  } else if (kind == "force") {
    law = physics::ConstantForce{.force = in.required_vector("force")};
  } else if (kind == "torque") {
    law = physics::ConstantTorque{.torque = in.required_vector("torque")};
  } else if (kind == "linear_damping" || kind == "angular_damping") {
    const double coefficient = in.required_number("coefficient");
    require_non_negative(in, "coefficient", coefficient);
    if (kind == "linear_damping") {
      law = physics::LinearDamping{.coefficient = coefficient};
    } else {
      law = physics::AngularDamping{.coefficient = coefficient};
    }
  } else if (kind == "force_at_point") {
    physics::ForceAtPoint push{.force = in.required_vector("force"),
                               .point = in.required_vector("point")};
    push.start = in.optional_number("start", push.start);
    push.end = in.optional_number("end", push.end);
    if (push.start > push.end) {
      in.fail("start", "start (" + format_number(push.start) + ") is after end (" +
                           format_number(push.end) + ")");
    }
    law = push;
  } else if (kind == "spring") {
    physics::Spring spring{.anchor = in.required_vector("anchor"),
                           .attachment = in.optional_vector("attachment", Vec3::Zero()),
                           .stiffness = in.required_number("stiffness")};
    spring.damping = in.optional_number("damping", 0.0);
    spring.rest_length = in.optional_number("rest_length", 0.0);
    require_non_negative(in, "stiffness", spring.stiffness);
    require_non_negative(in, "damping", spring.damping);
    require_non_negative(in, "rest_length", spring.rest_length);
    law = spring;
  } else {
    in.fail("kind", "unknown force kind \"" + kind +
                        "\" (expected gravity, force, torque, linear_damping, angular_damping, "
                        "force_at_point or spring)");
  }
  in.reject_unknown_keys();
  return law;
}

BodySpec read_body(TableReader& in, std::size_t index, const std::string& file) {
  BodySpec body;
  body.name = in.optional_string("name", "body" + std::to_string(index));
  if (!is_safe_name(body.name)) {
    in.fail("name", "must be 1-100 letters, digits, '_', '-' or '.', not starting with '.'");
  }
  const std::string shape = in.required_string("shape");
  const toml::node& size = in.required("size");
  if (shape == "cube") {
    body.shape = Shape::cube;
    if (size.is_array())
      in.fail("size", "a cube's size is its side, one number (a box takes [x, y, z])");
    body.size = Vec3::Constant(in.number("size", size));
  } else if (shape == "box") {
    body.shape = Shape::box;
    body.size = in.vector("size", size);
  } else {
    in.fail("shape", "unknown shape \"" + shape + "\" (expected cube or box)");
  }
  if (!(body.size.minCoeff() > 0.0)) in.fail("size", "every edge must be greater than 0");
  body.mass = in.required_number("mass");
  require_positive(in, "mass", body.mass);
  const physics::BodyConstants constants = body_constants(body);
  if (!(std::isfinite(constants.inverse_mass) && constants.inverse_inertia.allFinite() &&
        constants.inertia.allFinite())) {
    in.fail("mass", "with this size, the moments of inertia are beyond double precision");
  }
  body.position = in.optional_vector("position", Vec3::Zero());
  body.velocity = in.optional_vector("velocity", Vec3::Zero());
  body.orientation = in.optional_quaternion("orientation");
  body.angular_velocity = in.optional_vector("angular_velocity", Vec3::Zero());
  if (in.has("forces")) {
    const toml::array* forces = in.table().get("forces")->as_array();
    if (!forces) in.fail("forces", "expected [[bodies.forces]] tables");
    for (std::size_t i = 0; i < forces->size(); ++i) {
      const toml::table* table = (*forces)[i].as_table();
      const std::string path = in.path() + ".forces[" + std::to_string(i) + "]";
      if (!table) in.fail_at((*forces)[i].source(), path, "expected a table");
      TableReader force(*table, path, file);
      body.forces.push_back(read_force(force));
    }
  }
  in.reject_unknown_keys();
  return body;
}

Scene read_scene(const toml::table& root, const std::string& file) {
  Scene scene;
  scene.source_path = file;
  TableReader in(root, "", file);
  scene.name = in.optional_string("name", std::filesystem::path(file).stem().string());
  if (!is_safe_name(scene.name)) {
    in.fail("name",
            "must be 1-100 letters, digits, '_', '-' or '.', not starting with '.' "
            "(it names the output folder)");
  }
  scene.duration = in.required_number("duration");
  require_positive(in, "duration", scene.duration);

  if (in.has("physics")) {
    const toml::table* table = root.get("physics")->as_table();
    if (!table) in.fail("physics", "expected a [physics] table");
    TableReader physics(*table, "physics", file);
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
      physics.fail("integrator", "unknown integrator \"" + name + "\" (expected " + known + ")");
    }
    scene.physics.integrator = *integrator;
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
  for (std::size_t i = 0; i < bodies->size(); ++i) {
    const std::string path = "bodies[" + std::to_string(i) + "]";
    const toml::table* table = (*bodies)[i].as_table();
    if (!table) in.fail_at((*bodies)[i].source(), path, "expected a [[bodies]] table");
    TableReader body(*table, path, file);
    scene.bodies.push_back(read_body(body, i, file));
    if (!names.insert(scene.bodies.back().name).second) {
      body.fail("name", "duplicate body name \"" + scene.bodies.back().name + "\"");
    }
  }
  in.reject_unknown_keys();
  return scene;
}

}  // namespace

SceneOrError parse_scene(std::string_view text, const std::string& path) {
  try {
    const toml::table root = toml::parse(text, path);
    return read_scene(root, path);
  } catch (const toml::parse_error& error) {
    std::ostringstream out;
    out << path << ':' << error.source().begin.line << ':' << error.source().begin.column
        << ": TOML syntax error: " << error.description();
    return SceneError{out.str()};
  } catch (const LoadFailure& failure) {
    return SceneError{failure.what()};
  }
}

SceneOrError load_scene_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return SceneError{path + ": cannot open scene file"};
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) return SceneError{path + ": error reading scene file"};
  return parse_scene(text.str(), path);
}

}  // namespace tumble::scene
