#include "scene/camera_keys.hpp"

namespace tumble::scene::detail {
namespace {

CameraKey read_key(TableReader& in, const Scene& scene, const CameraKey* previous) {
  CameraKey key;
  key.time = in.required_number("time");
  if (key.time < 0.0 || key.time > scene.duration) {
    in.fail("time", "must be from 0 to the duration, " + format_number(scene.duration) +
                        " s (got " + format_number(key.time) + ")");
  }
  if (previous && key.time <= previous->time) {
    in.fail("time", "must be later than the key before, at " + format_number(previous->time) +
                        " s (got " + format_number(key.time) + "): keys go in time order");
  }
  key.position = in.required_vector("position");
  key.look_at = in.required_vector("look_at");
  if ((key.position - key.look_at).norm() == 0.0) {
    in.fail("look_at", "the camera cannot look at its own position");
  }
  key.fov_degrees = in.optional_number("fov_degrees", scene.camera.fov_degrees);
  if (!(key.fov_degrees > 1.0 && key.fov_degrees < 170.0)) {
    in.fail("fov_degrees", "must be more than 1 and less than 170 degrees (got " +
                               format_number(key.fov_degrees) + ")");
  }
  in.reject_unknown_keys();
  return key;
}

}  // namespace

void read_camera_moves(TableReader& in, Scene& scene) {
  CameraSpec& camera = scene.camera;
  if (in.has("orbit_period")) {
    camera.orbit_period = in.required_number("orbit_period");
    require_positive(in, "orbit_period", *camera.orbit_period);
  }
  if (!in.has("keys")) return;
  const toml::array* keys = in.table().get("keys")->as_array();
  if (!keys || keys->empty()) in.fail("keys", "expected one or more [[camera.keys]] tables");
  // The keys say where the camera is at every time: a position or look_at beside them would be a
  // second answer.
  for (const char* key : {"position", "look_at"}) {
    if (in.has(key)) {
      in.fail(key,
              "not used with [[camera.keys]], which place the camera at every time: move "
              "it into a key");
    }
  }
  for (std::size_t i = 0; i < keys->size(); ++i) {
    const std::string path = in.qualified("keys") + "[" + std::to_string(i) + "]";
    const toml::table* table = (*keys)[i].as_table();
    if (!table) in.fail_at((*keys)[i].source(), path, "expected a [[camera.keys]] table");
    TableReader key(*table, path, in.file());
    camera.keys.push_back(
        read_key(key, scene, camera.keys.empty() ? nullptr : &camera.keys.back()));
  }
}

}  // namespace tumble::scene::detail
