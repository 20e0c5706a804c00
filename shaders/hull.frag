// A convex hull's face: its colour lit with the face's own normal (flat, as a box's faces are) and
// its edges drawn dark, 1.5 px wide whatever the face's size, as a box's frame reads its turning.
in vec3 v_world_position;
in vec3 v_edge;
in vec4 v_light_clip;
flat in vec3 v_world_normal;
flat in vec3 v_albedo;
flat in vec4 v_occluders;  // render/box_instances.hpp

out vec4 out_color;

const float kEdgePixels = 1.5;

void main() {
  vec3 normal = normalize(v_world_normal);
  // Each component falls to 0 on one side of the triangle (large where that side is inside the
  // face): in pixels, the nearest edge is the smallest over the component's screen-space rate.
  vec3 pixels = v_edge / max(fwidth(v_edge), vec3(1e-6));
  float nearest = min(pixels.x, min(pixels.y, pixels.z));
  float edge = 1.0 - smoothstep(kEdgePixels - 0.5, kEdgePixels + 0.5, nearest);
  vec3 albedo = v_albedo * mix(1.0, 0.18, edge);
  float visibility = key_light_visibility(v_light_clip, normal);
#ifdef RECEIVE_BODY_OCCLUSION
  float fill = fill_left(v_world_position, normal, v_occluders);
#else
  float fill = 1.0;
#endif
  out_color = vec4(
      encode_srgb(shade_filled(albedo, v_world_position, normal, visibility, 32.0, 0.2, fill)),
      1.0);
}
