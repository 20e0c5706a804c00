#include "scene/plane_tables.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include "physics/pair_contact.hpp"

#include "scene/joint_tables.hpp"
#include "scene/limits.hpp"
#include "scene/scene_builder.hpp"
#include "sim/simulation.hpp"

namespace tumble::scene::detail {
namespace {

// A body may start touching a plane; this much overlap is the round-off of writing a resting
// body's position in decimal (m).
constexpr double kStartOverlapAllowed = 1e-9;

// `size` of a plane: [across, up the slope], each in (0, kMaxPosition] m.
void read_drawn_size(TableReader& in, PlaneSpec& plane) {
  if (!in.has("size")) return;
  const toml::node& node = *in.table().get("size");
  const toml::array* array = node.as_array();
  if (!array || array->size() != 2) {
    in.fail("size", "expected an array of 2 numbers [across, up the slope] (m), found " +
                        (array ? "an array of " + std::to_string(array->size())
                               : std::string(type_name(node))));
  }
  for (std::size_t i = 0; i < 2; ++i) plane.size[i] = in.number("size", (*array)[i]);
  // Appended, not "[" + ...: GCC 12 warns falsely (-Wrestrict) on a literal plus a temporary.
  std::string written = "[";
  written += format_number(plane.size[0]) + ", " + format_number(plane.size[1]) + "]";
  if (!(plane.size[0] > 0.0 && plane.size[1] > 0.0)) {
    in.fail("size", "both extents must be greater than 0 (got " + written + ")");
  }
  if (plane.size[0] > sim::kMaxPosition || plane.size[1] > sim::kMaxPosition) {
    in.fail("size", "an extent is past the " + format_number(sim::kMaxPosition) +
                        " m tumble can draw (got " + written + ")");
  }
}

PlaneSpec read_plane(TableReader& in, std::size_t index) {
  PlaneSpec plane;
  plane.name = in.optional_string("name", "plane" + std::to_string(index));
  if (!is_safe_name(plane.name)) in.fail("name", kSafeNameRule);
  plane.point = vector_within(in, "point", in.required_vector("point"), sim::kMaxPosition, "m");
  const Vec3 normal = in.required_vector("normal");
  // Divided by its largest component first, so that neither 1e-300 nor 1e300 under- or
  // overflows on the way to unit length.
  const double largest = normal.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) in.fail("normal", "must not be the zero vector");
  plane.normal = (normal / largest).normalized();
  plane.material = read_material(in, plane.material);
  plane.visible = in.optional_bool("visible", plane.visible);
  read_drawn_size(in, plane);
  in.reject_unknown_keys();
  return plane;
}

// A body's initial box must be outside every plane: the contact would otherwise start by
// throwing it out. Blamed on the body's position if written, else on the plane's point.
void refuse_bodies_inside(const TableReader& root, const Scene& scene,
                          std::span<const std::size_t> table_of_body) {
  const toml::array& bodies = *root.table().get("bodies")->as_array();
  const toml::array& planes = *root.table().get("planes")->as_array();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const BodySpec& body = scene.bodies[i];
    if (body.is_static) continue;  // never moved by a plane: a ramp may stand in the floor
    const physics::BodyState start = initial_state(body);
    for (std::size_t j = 0; j < scene.planes.size(); ++j) {
      const PlaneSpec& spec = scene.planes[j];
      const double depth =
          -physics::closest_separation(start, physics_shape(body), scene::plane(spec));
      if (!(depth > kStartOverlapAllowed)) continue;
      const std::string what = "body " + in_quotes(body.name) + " starts " + format_number(depth) +
                               " m inside plane " + in_quotes(spec.name);
      const std::size_t table = table_of_body[i];
      const toml::table& body_table = *bodies[table].as_table();
      if (body_table.contains("position")) {
        TableReader(body_table, "bodies[" + std::to_string(table) + "]", root.file())
            .fail("position", what);
      }
      TableReader(*planes[j].as_table(), "planes[" + std::to_string(j) + "]", root.file())
          .fail("point", what);
    }
  }
}

}  // namespace

physics::Material read_material(TableReader& in, const physics::Material& fallback) {
  physics::Material out;
  out.restitution = in.optional_number("restitution", fallback.restitution);
  if (!(out.restitution >= 0.0 && out.restitution <= 1.0)) {
    in.fail("restitution", "must be from 0 to 1 (got " + format_number(out.restitution) + ")");
  }
  out.friction = in.optional_number("friction", fallback.friction);
  require_non_negative(in, "friction", out.friction);
  out.rolling_resistance = in.optional_number("rolling_resistance", fallback.rolling_resistance);
  require_non_negative(in, "rolling_resistance", out.rolling_resistance);
  return out;
}

physics::ContactSettings read_contact_settings(TableReader& in) {
  physics::ContactSettings out;
  const bool written = in.has("contact");
  const std::string name = in.optional_string("contact", physics::contact_method_name(out.method));
  std::string known;
  for (const physics::ContactMethod method : physics::kAllContactMethods) {
    if (name == physics::contact_method_name(method)) out.method = method;
    known += (known.empty() ? "" : " or ") + std::string(physics::contact_method_name(method));
  }
  if (name != physics::contact_method_name(out.method)) {
    in.fail("contact", "unknown contact method " + in_quotes(name) + " (expected " + known + ")");
  }
  // A setting of the other method would be silently unused: refused instead.
  const auto only_with = [&](const char* key, physics::ContactMethod method) {
    if (!in.has(key) || out.method == method) return;
    in.fail(key, std::string("is for contact = \"") + physics::contact_method_name(method) +
                     "\" only, and this scene's contact is \"" + name + "\"" +
                     (written ? "" : " (the default)"));
  };
  only_with("contact_stiffness", physics::ContactMethod::penalty);
  only_with("contact_damping", physics::ContactMethod::penalty);
  only_with("restitution_threshold", physics::ContactMethod::impulse);
  only_with("sleep", physics::ContactMethod::impulse);
  out.stiffness = in.optional_number("contact_stiffness", out.stiffness);
  require_positive(in, "contact_stiffness", out.stiffness);
  out.damping = in.optional_number("contact_damping", out.damping);
  require_non_negative(in, "contact_damping", out.damping);
  out.restitution_threshold =
      in.optional_number("restitution_threshold", out.restitution_threshold);
  require_non_negative(in, "restitution_threshold", out.restitution_threshold);
  out.collide_bodies = in.optional_bool("collide_bodies", out.collide_bodies);
  out.sleep = in.optional_bool("sleep", out.sleep);
  return out;
}

namespace {

// How deep two bodies overlap at their start (m; <= 0 apart).
double start_overlap(const BodySpec& a, const BodySpec& b) {
  const physics::Shape sa = physics_shape(a), sb = physics_shape(b);
  return -physics::pair_separation({a.position, a.orientation.toRotationMatrix(), &sa},
                                   {b.position, b.orientation.toRotationMatrix(), &sb}, 0.0);
}

}  // namespace

void refuse_overlapping_bodies(const TableReader& root, const Scene& scene,
                               std::span<const std::size_t> table_of_body) {
  // Both methods act between bodies: impulse contact would throw overlapping bodies apart, and
  // penalty contact's springs would start compressed by the overlap.
  if (!scene.physics.contact.collide_bodies) return;
  const toml::array& bodies = *root.table().get("bodies")->as_array();
  // Sorted along x by the lower end of each bounding sphere, so that only neighbours are tested:
  // a scene of a thousand boxes is checked in milliseconds.
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].collide) order.push_back(i);
  }
  const auto radius = [&](std::size_t i) { return 0.5 * scene.bodies[i].size.norm(); };
  const auto lower = [&](std::size_t i) { return scene.bodies[i].position.x() - radius(i); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return lower(a) < lower(b) || (lower(a) == lower(b) && a < b);
  });
  for (std::size_t n = 0; n < order.size(); ++n) {
    for (std::size_t m = n + 1; m < order.size(); ++m) {
      const std::size_t a = std::min(order[n], order[m]), b = std::max(order[n], order[m]);
      const BodySpec& first = scene.bodies[a];
      const BodySpec& second = scene.bodies[b];
      if (lower(order[m]) > scene.bodies[order[n]].position.x() + radius(order[n])) break;
      if (first.is_static && second.is_static) continue;  // a board of pegs may be one piece
      if (kept_from_colliding(scene, a, b)) continue;     // the links of a chain may overlap
      if ((first.position - second.position).norm() >= radius(a) + radius(b)) continue;
      const double overlap = start_overlap(first, second);
      if (!(overlap > kStartOverlapAllowed)) continue;
      const std::string what = "bodies " + in_quotes(first.name) + " and " +
                               in_quotes(second.name) + " start overlapping by " +
                               format_number(overlap) +
                               (first.is_static || second.is_static
                                    ? " m (a static body holds its place: move the other out)"
                                    : " m (bodies collide; give one `collide = false`, or set "
                                      "[physics] collide_bodies = false)");
      const auto reader_of = [&](std::size_t body) {
        const std::size_t table = table_of_body[body];
        return TableReader(*bodies[table].as_table(), "bodies[" + std::to_string(table) + "]",
                           root.file());
      };
      // Two bodies of one array overlap by its spacing.
      TableReader reader = reader_of(b);
      if (table_of_body[a] == table_of_body[b] && reader.table().contains("spacing")) {
        reader.fail("spacing", what);
      }
      if (reader.table().contains("position")) reader.fail("position", what);
      reader_of(a).fail("position", what);
    }
  }
}

void read_planes(TableReader& root, Scene& scene, std::span<const std::size_t> table_of_body) {
  if (!root.has("planes")) return;
  const toml::array* planes = root.table().get("planes")->as_array();
  if (!planes) root.fail("planes", "expected [[planes]] tables");
  std::set<std::string> names;
  root.each_table(*planes, "planes", static_cast<std::size_t>(kMaxPlanes), "a [[planes]] table",
                  [&](TableReader& in, std::size_t i) {
                    scene.planes.push_back(read_plane(in, i));
                    if (scene.physics.contact.method == physics::ContactMethod::penalty &&
                        scene.planes.back().material.rolling_resistance > 0.0) {
                      in.fail("rolling_resistance",
                              "rolling resistance needs [physics] contact = \"impulse\" (the "
                              "default): penalty contact's springs sit at a box's corners");
                    }
                    if (!names.insert(scene.planes.back().name).second) {
                      in.fail("name",
                              "duplicate plane name " + in_quotes(scene.planes.back().name));
                    }
                  });
  refuse_bodies_inside(root, scene, table_of_body);
}

}  // namespace tumble::scene::detail
