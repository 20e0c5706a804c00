// The fraction of the fill light one body leaves a point of the ground (normal +y), written for
// blending by multiplication: the ground's occlusion buffer ends as the product over the bodies
// near it (render/occlusion_layer.hpp). After version.glsl and form_factor.glsl, whose
// occlusion_by() is exact while the body is above the ground, as a body resting on it is: its
// faces are not cut to the point's hemisphere (a corner a resting box presses into the ground,
// a fraction of a millimetre, counts a sliver below the horizon).
in vec3 v_point;
flat in vec3 v_center;
flat in mat3 v_rotation;
flat in vec3 v_half_size;
flat in vec2 v_kind_reach;

uniform float u_strength;  // [render] ambient_occlusion

out vec4 out_visibility;

void main() {
  float occlusion = occlusion_by(v_point, vec3(0.0, 1.0, 0.0), v_center, v_rotation, v_half_size,
                                 v_kind_reach.x > 0.5, v_kind_reach.y, false);
  if (occlusion <= 0.0) discard;  // none counted: the buffer keeps its value
  out_visibility = vec4(1.0 - u_strength * occlusion);
}
