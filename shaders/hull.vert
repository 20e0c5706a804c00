#version 330 core
// A convex hull: its mesh (render/geometry.hpp's hull_vertices, in the unit box its size scales)
// posed, one instance per body of that hull, flat-shaded per face by hull.frag.
layout(location = 0) in vec3 in_position;  // in the unit box
layout(location = 1) in vec3 in_normal;    // the face's, body frame
layout(location = 2) in mat4 in_model;     // body to world, including the scale to the size
layout(location = 6) in mat3 in_rotation;  // body to world, for the normals
layout(location = 10) in vec3 in_albedo;   // linear
layout(location = 11) in vec3 in_edge;     // how far from the face's edges (hull_vertices)
layout(location = 12) in vec4 in_occluders;  // render/box_instances.hpp

uniform mat4 u_view_projection;
uniform mat4 u_light_view_projection;

out vec3 v_world_position;
out vec3 v_edge;
out vec4 v_light_clip;
flat out vec3 v_world_normal;
flat out vec3 v_albedo;
flat out vec4 v_occluders;

void main() {
  vec4 world = in_model * vec4(in_position, 1.0);
  v_world_position = world.xyz;
  v_light_clip = u_light_view_projection * world;
  gl_Position = u_view_projection * world;
  v_world_normal = in_rotation * in_normal;
  v_edge = in_edge;
  v_albedo = in_albedo;
  v_occluders = in_occluders;
}
