// The contact parts of a scene file: [[planes]], the surface material of bodies and planes, and
// the contact settings in [physics]. Internal to src/scene/.
#pragma once

#include <span>

#include "scene/scene.hpp"
#include "scene/table_reader.hpp"

namespace tumble::scene::detail {

// `restitution` (0 to 1) and `friction` (>= 0) of a [[bodies]] or [[planes]] table; what is
// left out keeps its value in `fallback`.
physics::Material read_material(TableReader& in, const physics::Material& fallback);

// contact, contact_stiffness, contact_damping, restitution_threshold and collide_bodies of
// [physics]: each setting only with the method that uses it.
physics::ContactSettings read_contact_settings(TableReader& physics);

// The [[planes]] tables of `root` into scene.planes, then refuses a body that starts inside a
// plane. Needs scene.bodies read; `table_of_body` says which [[bodies]] table wrote each (a body
// array writes many), for the message's place.
void read_planes(TableReader& root, Scene& scene, std::span<const std::size_t> table_of_body);

// Refuses two colliding bodies whose boxes overlap at the start, naming both, but for two that a
// joint keeps from colliding. Needs scene.bodies, scene.physics and scene.joints read.
void refuse_overlapping_bodies(const TableReader& root, const Scene& scene,
                               std::span<const std::size_t> table_of_body);

}  // namespace tumble::scene::detail
