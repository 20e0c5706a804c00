// A box face: its colour tinted per face and framed by dark edges, so the rotation reads.
in vec3 v_world_position;
in vec3 v_world_normal;
in vec3 v_local_position;
in vec3 v_local_normal;
in vec4 v_light_clip;
flat in vec3 v_size;    // edge lengths (m)
flat in vec3 v_albedo;  // linear

out vec4 out_color;

// Per-face tints (+x, -x, +y, -y, +z, -z), mixed into the body colour.
const vec3 kFaceTints[6] = vec3[6](vec3(1.00, 0.90, 0.80), vec3(0.80, 0.90, 1.00),
                                   vec3(1.00, 1.00, 0.85), vec3(0.85, 0.80, 0.95),
                                   vec3(0.90, 1.00, 0.90), vec3(1.00, 0.85, 0.90));

void main() {
  vec3 n = v_local_normal;
  vec3 a = abs(n);
  int axis = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
  int face = axis * 2 + (n[axis] > 0.0 ? 0 : 1);
  vec3 albedo = v_albedo * kFaceTints[face];

  // Distance (m) to the nearest edge of this face, from the two in-face coordinates.
  vec3 to_edge = 0.5 * v_size - abs(v_local_position);
  to_edge[axis] = 1e9;
  float d = min(to_edge.x, min(to_edge.y, to_edge.z));
  float width = 0.025 * min(v_size.x, min(v_size.y, v_size.z));
  float blur = fwidth(d);
  float edge = 1.0 - smoothstep(width - blur, width + blur, d);
  albedo = mix(albedo, albedo * 0.18, edge);

  vec3 normal = normalize(v_world_normal);
  float visibility = key_light_visibility(v_light_clip, normal);
  vec3 color = shade(albedo, v_world_position, normal, visibility, 48.0, 0.25);
  out_color = vec4(encode_srgb(color), 1.0);
}
