#version 330 core
// The ground: a square in the plane y = height, centred under the point the camera looks at.
layout(location = 0) in vec2 in_corner;  // [-1, 1]^2

uniform vec3 u_center;     // world frame (m), y = ground height
uniform float u_half_extent;  // m
uniform mat4 u_view_projection;
uniform mat4 u_light_view_projection;

out vec3 v_world_position;
out vec4 v_light_clip;
// The pass with shadows meets the kept ground's depths exactly (Renderer: GL_LEQUAL).
invariant gl_Position;

void main() {
  vec4 world = vec4(u_center + vec3(in_corner.x, 0.0, in_corner.y) * u_half_extent, 1.0);
  v_world_position = world.xyz;
  v_light_clip = u_light_view_projection * world;
  gl_Position = u_view_projection * world;
}
