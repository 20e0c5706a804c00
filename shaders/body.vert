#version 330 core
// A box: the unit cube's vertices scaled to the box's size, then posed.
layout(location = 0) in vec3 in_position;  // unit cube, [-0.5, 0.5]^3
layout(location = 1) in vec3 in_normal;    // face normal, body frame

uniform mat4 u_model;  // body to world, including the scale to the box's size
uniform mat3 u_normal_matrix;
uniform mat4 u_view_projection;
uniform mat4 u_light_view_projection;
uniform vec3 u_size;  // edge lengths (m)

out vec3 v_world_position;
out vec3 v_world_normal;
out vec3 v_local_position;  // body frame (m)
out vec3 v_local_normal;
out vec4 v_light_clip;

void main() {
  vec4 world = u_model * vec4(in_position, 1.0);
  v_world_position = world.xyz;
  v_world_normal = normalize(u_normal_matrix * in_normal);
  v_local_position = in_position * u_size;
  v_local_normal = in_normal;
  v_light_clip = u_light_view_projection * world;
  gl_Position = u_view_projection * world;
}
