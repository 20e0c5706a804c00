// A Box's solid and a Quad as plain triangle meshes, GL-free: the meshes the renderer draws
// (render/geometry.hpp, with box_batch's divisions), at the box's size and in its body frame, as
// the shaders would place them (capsule.glsl stretches a capsule's halves apart by its length).
// For a file that must carry the shapes themselves, a glTF (job/gltf_scene.hpp); the renderer
// draws the unit meshes, scaled per instance.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "render/frame.hpp"

namespace tumble::render {

struct SolidMesh {
  std::vector<Eigen::Vector3f> positions;  // body frame (m)
  std::vector<Eigen::Vector3f> normals;    // unit, body frame: one per position
  std::vector<std::uint32_t> triangles;    // 3 positions each, counter-clockwise seen from outside
};

// The surface of `solid` in a box of `size` (edge lengths along the body axes, m). `hull` is the
// box's RenderSettings::hulls entry for Solid::hull, and unused for the others.
SolidMesh solid_mesh(Solid solid, const Vec3& size, const HullMesh* hull = nullptr);

// A quad of `width` along its local x and `depth` along z (m), centred at its origin, its front
// (counter-clockwise) facing its local +y: two triangles.
SolidMesh quad_mesh(double width, double depth);

}  // namespace tumble::render
