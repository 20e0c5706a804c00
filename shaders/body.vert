#version 330 core
// A box: the unit cube's vertices scaled to the box's size, then posed. One instance per box
// (render/box_instances.hpp), all boxes in one draw. A face is flat, so all of its lighting but
// the highlight and the shadow is the same over the whole face: worked out here, once per
// vertex, and handed on flat (lighting.glsl's shade() for this face's normal).
layout(location = 0) in vec3 in_position;  // unit cube, [-0.5, 0.5]^3
layout(location = 1) in vec3 in_normal;    // face normal, body frame
layout(location = 2) in mat4 in_model;     // body to world, including the scale to the box's size
layout(location = 6) in mat3 in_rotation;  // body to world, for the normals
layout(location = 9) in vec3 in_size;      // edge lengths (m)
layout(location = 10) in vec3 in_albedo;   // linear
layout(location = 12) in vec4 in_occluders;  // render/box_instances.hpp: indices + 1, 0 none

uniform mat4 u_view_projection;
uniform mat4 u_light_view_projection;
uniform vec3 u_light_direction;  // the way the light travels, world frame, unit
uniform vec3 u_light_color;      // linear, times the exposure
uniform float u_ambient;         // fraction of the key light
uniform float u_fill_low;        // the fill on a face turned down, of that on a face turned up

out vec3 v_world_position;
out vec2 v_face_position;  // body frame, along the face's two edges from its centre (m)
out vec4 v_light_clip;
flat out vec3 v_world_normal;    // unit
flat out vec2 v_face_half_size;  // half the face's two edges (m)
flat out float v_frame_width;    // of the dark frame along the edges (m)
flat out vec3 v_ambient;         // linear: the ambient light the face sends back
flat out vec3 v_diffuse;         // linear: the key light it sends back where lit
flat out vec3 v_specular;        // linear: the highlight's colour; 0 on a face turned away
flat out vec4 v_occluders;

void main() {
  vec4 world = in_model * vec4(in_position, 1.0);
  v_world_position = world.xyz;
  v_light_clip = u_light_view_projection * world;
  gl_Position = u_view_projection * world;

  vec3 a = abs(in_normal);
  int axis = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
  int first = axis == 0 ? 1 : 0;   // the face's two edge directions
  int second = axis == 2 ? 1 : 2;
  vec3 local = in_position * in_size;
  v_face_position = vec2(local[first], local[second]);
  v_face_half_size = 0.5 * vec2(in_size[first], in_size[second]);
  v_frame_width = 0.025 * min(in_size.x, min(in_size.y, in_size.z));

  vec3 normal = normalize(in_rotation * in_normal);
  v_world_normal = normal;
  vec3 albedo = in_albedo;  // the body's colour as given: faces differ by their light alone
  float diffuse = max(dot(normal, -u_light_direction), 0.0);
  float hemisphere = mix(u_fill_low, 1.0, normal.y * 0.5 + 0.5);  // lighting.glsl's hemisphere()
  v_ambient = u_ambient * hemisphere * u_light_color * albedo;
  v_diffuse = diffuse * u_light_color * albedo;
  v_specular = diffuse > 0.0 ? 0.25 * u_light_color : vec3(0.0);  // highlight strength 0.25
  v_occluders = in_occluders;
}
