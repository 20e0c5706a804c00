#version 330 core
// Shared by the capsule's vertex shaders (prepended to them): where a vertex of the capsule mesh
// (render/geometry.hpp's capsule_vertices: a sphere of diameter 1 cut at its equator, each half's
// vertices carrying the way it moves along y) lies in the capsule's body, and in the unit box the
// instance's model matrix scales to the capsule's size (2r, length + 2r, 2r).
vec3 capsule_body_point(vec3 on_sphere, float stretch, vec3 size) {
  float radius = 0.5 * size.x;
  float half_length = max(0.5 * size.y - radius, 0.0);
  return 2.0 * radius * on_sphere + vec3(0.0, stretch * half_length, 0.0);
}
vec4 capsule_in_unit_box(vec3 on_sphere, float stretch, vec3 size) {
  return vec4(capsule_body_point(on_sphere, stretch, size) / size, 1.0);
}
