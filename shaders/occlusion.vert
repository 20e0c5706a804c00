#version 330 core
// Ambient occlusion on the ground (render/occlusion_layer.hpp): one square on the ground per
// body near it, large enough to hold the ground the body darkens, all bodies in one draw.
layout(location = 0) in vec2 in_corner;     // [-1, 1]^2
layout(location = 1) in vec3 in_square;     // the square's centre x, z and half its edge (m)
layout(location = 2) in vec3 in_center;     // the body's centre, world frame (m)
layout(location = 3) in mat3 in_rotation;   // body to world
layout(location = 6) in vec3 in_half_size;  // half the body's box (m)
layout(location = 7) in vec2 in_kind_reach; // 0 a box, 1 a sphere; how far from it it darkens (m)

uniform mat4 u_view_projection;
uniform float u_ground_height;

out vec3 v_point;  // on the ground, world frame
flat out vec3 v_center;
flat out mat3 v_rotation;
flat out vec3 v_half_size;
flat out vec2 v_kind_reach;

void main() {
  v_point = vec3(in_square.x + in_square.z * in_corner.x, u_ground_height,
                 in_square.y + in_square.z * in_corner.y);
  gl_Position = u_view_projection * vec4(v_point, 1.0);
  v_center = in_center;
  v_rotation = in_rotation;
  v_half_size = in_half_size;
  v_kind_reach = in_kind_reach;
}
