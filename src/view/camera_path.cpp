#include "view/camera_path.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::view {

double ease(double s) {
  return s * s * (3.0 - 2.0 * s);
}

render::Camera keyed_camera(const std::vector<scene::CameraKey>& keys, const render::Vec3& up,
                            double t) {
  // The last key at or before t: at a key's own time that key, so the camera is exactly it.
  const auto after =
      std::upper_bound(keys.begin(), keys.end(), t,
                       [](double time, const scene::CameraKey& key) { return time < key.time; });
  const scene::CameraKey& from = after == keys.begin() ? keys.front() : *(after - 1);
  render::Camera camera{.position = from.position,
                        .look_at = from.look_at,
                        .up = up,
                        .fov_degrees = from.fov_degrees};
  if (after == keys.begin() || after == keys.end()) return camera;
  const scene::CameraKey& to = *after;
  const double e = ease((t - from.time) / (to.time - from.time));
  camera.position += e * (to.position - from.position);
  camera.look_at += e * (to.look_at - from.look_at);
  camera.fov_degrees += e * (to.fov_degrees - from.fov_degrees);
  return camera;
}

render::Camera camera_at(const scene::CameraSpec& spec, const render::Camera& base,
                         int follow_index, const std::vector<physics::BodyState>& states,
                         double t) {
  render::Camera camera = spec.keys.empty() ? base : keyed_camera(spec.keys, base.up, t);
  if (follow_index < 0 && !spec.orbit_period) return camera;
  render::Vec3 offset = camera.position - camera.look_at;  // m, world frame
  if (follow_index >= 0) camera.look_at = states[static_cast<std::size_t>(follow_index)].position();
  if (spec.orbit_period) {
    const double angle = 2.0 * M_PI * t / *spec.orbit_period;  // rad
    offset = Eigen::AngleAxisd(angle, camera.up.normalized()) * offset;
  }
  camera.position = camera.look_at + offset;
  return camera;
}

}  // namespace tumble::view
