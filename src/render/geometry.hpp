// The maths of drawing, free of GL: colours to linear light, camera matrices, the unit cube's
// vertices and the model matrices of boxes and quads. Internal to src/render/, but for
// linear_from_srgb and camera_rotation, which a glTF file needs too (job/gltf_scene.cpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "render/frame.hpp"

namespace tumble::render {

using Mat4 = Eigen::Matrix4d;

// The sRGB decoding function (IEC 61966-2-1): written colours to linear light.
// The sRGB transfer function (IEC 61966-2-1) of one component in [0, 1]: encoded to linear
// light, and back.
double linear_from_srgb(double encoded);
double srgb_from_linear(double linear);
Eigen::Vector3f linear_from_srgb(const Color& srgb);

// World to camera (looking down -z), as gluLookAt; any `up` not along the view will do.
Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up);

// The camera's frame to the world's: look_at's rotation undone (the camera looks down its -z with
// its +y up, as a glTF camera does).
Quat camera_rotation(const Camera& camera);

// Camera to clip space, as gluPerspective; `near` and `far` are distances (m).
Mat4 perspective(double fov_y_radians, double aspect, double near, double far);

// Camera to clip space for the key light: a square of 2 × half_width (m), near to far (m).
Mat4 orthographic(double half_width, double near, double far);

// The unit cube [-0.5, 0.5]^3 to the box in the world.
Mat4 model_matrix(const Box& box);

// The square [-1, 1]^2 of the x-z plane to the quad in the world.
Mat4 model_matrix(const Quad& quad);

// The unit normal of the quad's front (its local +y), world frame.
Vec3 front_normal(const Quad& quad);

// Whether a camera at `eye` (world frame, m) sees the quad's back: then the quad is drawn
// translucent and casts no shadow, like a pane of glass.
bool seen_from_back(const Quad& quad, const Vec3& eye);

// The quad's corners, world frame (m), in triangle-strip order.
std::array<Vec3, 4> corners(const Quad& quad);

// The square [-1, 1]^2 of the x-z plane as (x, 0, z), in triangle-strip order: the quads' mesh.
inline constexpr float kUnitSquare[4][3] = {{-1, 0, -1}, {1, 0, -1}, {-1, 0, 1}, {1, 0, 1}};

// The unit cube, four vertices per face so that each face has its own normal.
struct CubeVertex {
  float position[3];
  float normal[3];
};

std::vector<CubeVertex> cube_vertices();
// cube_vertices' two triangles a face, counter-clockwise seen from outside.
std::vector<std::uint16_t> cube_indices();

// A ball's cube faces are divided 16 × 16: its outline is a polygon of 64 sides, whose sides
// bulge in by 0.12% of the radius (1 − cos(π/64)), a tenth of a pixel for a ball 160 px across;
// the shading's normal is the sphere's own at every pixel (ball.frag).
inline constexpr int kBallDivisions = 16;
// A cylinder's side is a prism of 64 faces, its outline as close to a circle as a ball's.
inline constexpr int kCylinderSides = 64;

// The sphere of diameter 1 (the ball in the unit cube), each face of the cube divided into
// `divisions` × `divisions` cells pushed out onto the sphere, normals along the radius; into
// `indices`, two triangles a cell, counter-clockwise seen from outside.
std::vector<CubeVertex> sphere_vertices(int divisions, std::vector<std::uint16_t>& indices);

// A capsule's mesh: sphere_vertices cut at its equator into two halves joined by a band, each
// vertex's `normal` slot holding not its normal but the way its half moves along the axis,
// (0, ±1, 0): capsule.glsl stretches the halves apart by the capsule's length (its normal is the
// sphere's, along the position). Into `indices` as sphere_vertices.
std::vector<CubeVertex> capsule_vertices(int divisions, std::vector<std::uint16_t>& indices);

// A hull's vertex: where it is in the unit box the hull's size scales, its face's normal (body
// frame), and how far it is from the face's edges: each triangle of a face's fan has (1, 0, 0),
// (0, 1, 0), (0, 0, 1) at its corners, a component the distance from the side opposite its corner,
// and a large value instead where that side is inside the face, so that hull.frag darkens the
// face's own edges only.
struct HullVertex {
  float position[3];
  float normal[3];
  float edge[3];
};
std::vector<HullVertex> hull_vertices(const HullMesh& mesh, const Vec3& size,
                                      std::vector<std::uint16_t>& indices);

// The cylinder of diameter 1 and height 1 along y (in the unit cube): its side of `sides` faces
// with normals along the radius (smooth when interpolated), and its two flat caps. Into
// `indices`, counter-clockwise seen from outside.
std::vector<CubeVertex> cylinder_vertices(int sides, std::vector<std::uint16_t>& indices);

}  // namespace tumble::render
