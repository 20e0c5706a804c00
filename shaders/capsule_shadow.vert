// Depth from the key light, for the shadow map: the capsules, one instance per capsule (as
// capsule.vert places them).
layout(location = 0) in vec3 in_position;  // on the sphere of diameter 1
layout(location = 1) in vec3 in_stretch;   // (0, ±1, 0)
layout(location = 2) in mat4 in_model;     // body to world, including the scale to the size
layout(location = 9) in vec3 in_size;
uniform mat4 u_light_view_projection;

void main() {
  gl_Position =
      u_light_view_projection * in_model * capsule_in_unit_box(in_position, in_stretch.y, in_size);
}
