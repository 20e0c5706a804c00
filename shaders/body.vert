#version 330 core
// A box: the unit cube's vertices scaled to the box's size, then posed. One instance per box
// (render/box_instances.hpp), all boxes in one draw.
layout(location = 0) in vec3 in_position;  // unit cube, [-0.5, 0.5]^3
layout(location = 1) in vec3 in_normal;    // face normal, body frame
layout(location = 2) in mat4 in_model;     // body to world, including the scale to the box's size
layout(location = 6) in mat3 in_rotation;  // body to world, for the normals
layout(location = 9) in vec3 in_size;      // edge lengths (m)
layout(location = 10) in vec3 in_albedo;   // linear

uniform mat4 u_view_projection;
uniform mat4 u_light_view_projection;

out vec3 v_world_position;
out vec3 v_world_normal;
out vec3 v_local_position;  // body frame (m)
out vec3 v_local_normal;
out vec4 v_light_clip;
flat out vec3 v_size;
flat out vec3 v_albedo;

void main() {
  vec4 world = in_model * vec4(in_position, 1.0);
  v_world_position = world.xyz;
  v_world_normal = normalize(in_rotation * in_normal);
  v_local_position = in_position * in_size;
  v_local_normal = in_normal;
  v_light_clip = u_light_view_projection * world;
  v_size = in_size;
  v_albedo = in_albedo;
  gl_Position = u_view_projection * world;
}
