#version 330 core
// A quad: the square [-1, 1]^2 in the quad's local x-z plane, scaled to its edges and posed.
layout(location = 0) in vec3 in_position;  // (x, 0, z) with x, z in [-1, 1]

uniform mat4 u_model;      // quad to world, including the scale to half its edges
uniform vec2 u_half_size;  // half the edges along local x and z (m)
uniform mat4 u_view_projection;
uniform mat4 u_light_view_projection;

out vec3 v_world_position;
out vec2 v_local_position;  // from the centre along local x and z (m)
out vec4 v_light_clip;

void main() {
  vec4 world = u_model * vec4(in_position, 1.0);
  v_world_position = world.xyz;
  v_local_position = in_position.xz * u_half_size;
  v_light_clip = u_light_view_projection * world;
  gl_Position = u_view_projection * world;
}
