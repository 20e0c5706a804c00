// A round solid (a ball; a capsule, a cylinder: their vertex shaders give the normal and the
// point marked): its colour lit per pixel with the surface normal (lighting.glsl's shade(), as the
// planes), and three dark great circles where the body's axes meet its surface (the planes
// x = 0, y = 0, z = 0 of its body frame), so that a ball's roll and spin read as a box's edges do.
in vec3 v_world_position;
in vec3 v_world_normal;
in vec3 v_body_point;
in vec4 v_light_clip;
flat in vec3 v_albedo;
flat in vec4 v_occluders;  // render/box_instances.hpp

out vec4 out_color;

// Half the width of a great circle, as a fraction of the radius (a box's frame is 2.5% of its
// shortest edge).
const float kCircleHalfWidth = 0.03;

void main() {
  vec3 normal = normalize(v_world_normal);
  vec3 p = normalize(v_body_point);
  float nearest = min(abs(p.x), min(abs(p.y), abs(p.z)));  // to the closest circle's plane
  float blur = fwidth(nearest);
  float circle = 1.0 - smoothstep(kCircleHalfWidth - blur, kCircleHalfWidth + blur, nearest);
  vec3 albedo = v_albedo * mix(1.0, 0.18, circle);  // darkened as a box's frame is
  float visibility = key_light_visibility(v_light_clip, normal);
#ifdef RECEIVE_BODY_OCCLUSION
  float fill = fill_left(v_world_position, normal, v_occluders);
#else
  float fill = 1.0;
#endif
  out_color = vec4(
      encode_srgb(shade_filled(albedo, v_world_position, normal, visibility, 48.0, 0.25, fill)),
      1.0);
}
