#version 330 core
// A cylinder: the cylinder of diameter 1 and height 1 scaled to its size (2r, length, 2r) and
// posed. One instance per cylinder (render/box_instances.hpp, the records body.vert reads), all
// cylinders in one draw. Lit per pixel by ball.frag: the side's normals along the radius, the
// caps' along the axis; its lines cross the caps and run along the side, with a ring round the
// middle.
layout(location = 0) in vec3 in_position;  // on the unit cylinder
layout(location = 1) in vec3 in_normal;    // body frame
layout(location = 2) in mat4 in_model;     // body to world, including the scale to the size
layout(location = 6) in mat3 in_rotation;  // body to world, for the normals
layout(location = 10) in vec3 in_albedo;   // linear
layout(location = 12) in vec4 in_occluders;  // render/box_instances.hpp

uniform mat4 u_view_projection;
uniform mat4 u_light_view_projection;

out vec3 v_world_position;
out vec3 v_world_normal;  // interpolated: normalised per pixel
out vec3 v_body_point;    // what ball.frag marks: its lines where a coordinate is 0
out vec4 v_light_clip;
flat out vec3 v_albedo;
flat out vec4 v_occluders;

void main() {
  vec4 world = in_model * vec4(in_position, 1.0);
  v_world_position = world.xyz;
  v_light_clip = u_light_view_projection * world;
  gl_Position = u_view_projection * world;
  v_world_normal = in_rotation * in_normal;
  v_body_point = in_position;
  v_albedo = in_albedo;
  v_occluders = in_occluders;
}
