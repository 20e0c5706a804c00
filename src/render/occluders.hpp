// The bodies whose ambient occlusion a body receives (shaders/form_factor.glsl,
// receive_body_occlusion.glsl): for each body, up to kOccludersPerBody others near enough to darken
// it, and every body's shape as the shaders read it from a texture. Free of GL. Internal to
// src/render/.
#pragma once

#include <array>
#include <vector>

#include "render/frame.hpp"

namespace tumble::render {

// How far from a body the ground or another body is darkened: fully out to half this, fading to
// nothing at it, as a multiple of the body's longest edge.
inline constexpr double kOcclusionReach = 1.25;

// A box is darkened by the bodies nearest to it, at most this many: a box in a pile touches
// about four others, and each costs its pixels a closed-form occlusion.
inline constexpr int kOccludersPerBody = 4;

// For each of `boxes`, the indices of the boxes and balls among the others whose occlusion reaches
// it (their bounding spheres closer than kOcclusionReach times the other's longest edge), nearest
// first (by the gap between the bounding spheres, ties by index), -1 past the last. A capsule, a
// cylinder or a hull darkens no body: the box around it, which is how it darkens the ground,
// would darken points of a neighbour it does not cover.
std::vector<std::array<int, kOccludersPerBody>> nearest_occluders(const std::vector<Box>& boxes);

// Bodies a row of the occluder texture (body.frag's kOccludersPerRow): 4 RGBA texels each.
inline constexpr int kOccludersPerRow = 256;

// The occluder texture's texels, kOccludersPerRow bodies a row (the last row padded with zeros):
// four RGBA texels a body, as form_factor.glsl's occlusion_by() takes them: (centre, reach) and
// the rotation's three columns, each with the half edge along it; a ball's reach is negative
// (it occludes as a sphere of radius half its x edge). Shapes other than boxes and balls occlude
// as their box.
std::vector<float> occluder_texels(const std::vector<Box>& boxes);

}  // namespace tumble::render
