// The camera of every frame, in one place: the scene's camera or the framing pass's choice, moved
// along [[camera.keys]], turned by [camera] orbit_period and kept on the body [camera] follow
// names.
#pragma once

#include <vector>

#include "physics/rigid_body.hpp"
#include "render/frame.hpp"
#include "scene/scene.hpp"

namespace tumble::view {

// The ease between two keys: smoothstep, 3s² − 2s³ for s in [0, 1] (the cubic Hermite curve with
// zero slope at both ends), so the camera starts and stops each move at rest.
double ease(double s);

// The camera the keys give at time t (s): before the first key the first, after the last the
// last, exactly a key at its time, and between keys i and i+1 position, look_at and fov_degrees
// each key i's value plus ease(s) times the change to key i+1's, s = (t − tᵢ) / (tᵢ₊₁ − tᵢ).
// `keys` are not empty and in increasing time; `up` is copied.
render::Camera keyed_camera(const std::vector<scene::CameraKey>& keys, const render::Vec3& up,
                            double t);

// The camera of the frame at time t (s): `base` (the framing's camera), replaced by the keys
// when there are any; then the look-at point moved onto the followed body (`follow_index` ≥ 0,
// keeping the offset position − look_at); then that offset turned about `up` through the look-at
// point by 2π t / orbit_period (counter-clockwise seen from above, right-handed about up).
render::Camera camera_at(const scene::CameraSpec& spec, const render::Camera& base,
                         int follow_index, const std::vector<physics::BodyState>& states, double t);

}  // namespace tumble::view
