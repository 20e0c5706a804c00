// A capsule: the two halves of a ball pulled apart along body y by its length, the band between
// them its side (capsule.glsl). One instance per capsule (render/box_instances.hpp, the records
// body.vert reads), all capsules in one draw. Lit per pixel by ball.frag: the normal is the
// sphere's at every vertex, and body y is marked at the middle of the side, where the ball's
// equator would be.
layout(location = 0) in vec3 in_position;  // on the sphere of diameter 1
layout(location = 1) in vec3 in_stretch;   // (0, ±1, 0): the half the vertex belongs to
layout(location = 2) in mat4 in_model;     // body to world, including the scale to the size
layout(location = 6) in mat3 in_rotation;  // body to world, for the normals
layout(location = 9) in vec3 in_size;      // (2r, length + 2r, 2r)
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
  vec4 world = in_model * capsule_in_unit_box(in_position, in_stretch.y, in_size);
  v_world_position = world.xyz;
  v_light_clip = u_light_view_projection * world;
  gl_Position = u_view_projection * world;
  v_world_normal = in_rotation * in_position;
  // Across the side, y in radii (halved, as the sphere's points are): 0 at its middle.
  float radius = 0.5 * in_size.x;
  v_body_point = vec3(in_position.x,
                      0.5 * capsule_body_point(in_position, in_stretch.y, in_size).y / radius,
                      in_position.z);
  v_albedo = in_albedo;
  v_occluders = in_occluders;
}
