// The boxes of a frame as the instanced shaders read them (body.vert, box_shadow.vert): one
// record per box, uploaded in one buffer per frame and drawn with one call per pass. Free of GL.
// Internal to src/render/.
#pragma once

#include <array>
#include <vector>

#include "render/frame.hpp"
#include "render/occluders.hpp"

namespace tumble::render {

// Floats laid out as the vertex attributes take them; every matrix column-major, as GL wants.
struct BoxInstance {
  float model[16];    // the unit cube [-0.5, 0.5]^3 to the box in the world (model_matrix)
  float rotation[9];  // body to world, turns the face normals
  float size[3];      // edge lengths along the body axes (m)
  float albedo[3];    // linear (linear_from_srgb of the box's colour)
  // The bodies whose occlusion it receives (occluders.hpp), as their indices plus one; 0 past
  // the last (and when the look has no occlusion).
  float occluders[4] = {0.0f, 0.0f, 0.0f, 0.0f};
};

// One record per box of `solid`, nearest to `eye` (world frame, m) first, ties in the given order.
// Drawn so, most of a box hidden behind nearer ones fails the depth test before it is shaded
// (llvmpipe tests depth before shading when the shader writes no depth and discards nothing). The
// picture is the same in any order (opaque boxes, GL_LESS) but where faces of two boxes meet at
// exactly equal depth.
// A hull's batch takes the boxes of its `mesh` only. `occluders`, when given, has a list per box
// (nearest_occluders()), and the boxes with none come first (each part nearest first).
std::vector<BoxInstance> box_instances(
    const std::vector<Box>& boxes, const Vec3& eye, Solid solid = Solid::box,
    std::uint32_t mesh = 0,
    const std::vector<std::array<int, kOccludersPerBody>>* occluders = nullptr);

}  // namespace tumble::render
