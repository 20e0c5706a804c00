#version 330 core
// A ball: the sphere of diameter 1 scaled to the ball's box (its diameter each way) and posed. One
// instance per ball (render/box_instances.hpp, the records body.vert reads), all balls in one
// draw. Lit per pixel (ball.frag): the normal turns over the surface.
layout(location = 0) in vec3 in_position;  // on the sphere of diameter 1
layout(location = 2) in mat4 in_model;     // body to world, including the scale to the diameter
layout(location = 6) in mat3 in_rotation;  // body to world, for the normals
layout(location = 10) in vec3 in_albedo;   // linear
layout(location = 12) in vec4 in_occluders;  // render/box_instances.hpp

uniform mat4 u_view_projection;
uniform mat4 u_light_view_projection;

out vec3 v_world_position;
out vec3 v_world_normal;  // interpolated: normalised per pixel
out vec3 v_body_point;    // on the sphere, body frame: where the great circles are drawn
out vec4 v_light_clip;
flat out vec3 v_albedo;
flat out vec4 v_occluders;

void main() {
  vec4 world = in_model * vec4(in_position, 1.0);
  v_world_position = world.xyz;
  v_light_clip = u_light_view_projection * world;
  gl_Position = u_view_projection * world;
  v_world_normal = in_rotation * in_position;
  v_body_point = in_position;
  v_albedo = in_albedo;
  v_occluders = in_occluders;
}
