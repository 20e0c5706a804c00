// A quad of a plane: matte like the ground (so a level quad matches it), its grid in its own
// coordinates from its centre, and a dark border so that its extent reads. Lit with the normal of
// the side the camera sees.
in vec3 v_world_position;
in vec2 v_local_position;
in vec4 v_light_clip;

uniform vec3 u_albedo;          // linear
uniform vec3 u_normal;          // unit, world frame, on the camera's side
uniform vec2 u_half_size;       // m
uniform float u_grid_spacing;   // m; 0 = no grid
uniform float u_opacity;        // 1, or less for a quad seen from its back
out vec4 out_color;

void main() {
  float grid = 1.0;
  if (u_grid_spacing > 0.0) {
    vec2 cell = v_local_position / u_grid_spacing;
    vec2 width = fwidth(cell);
    vec2 line = abs(fract(cell - 0.5) - 0.5) / max(width, vec2(1e-6));
    float on_line = 1.0 - min(min(line.x, line.y), 1.0);
    // Lines thinner than a pixel become grey haze instead of moiré (as on the ground).
    on_line *= 1.0 - smoothstep(0.3, 0.8, max(width.x, width.y));
    grid = 1.0 - 0.35 * on_line;
  }
  // Pixels to the nearest edge: the border is about two pixels wide at any distance.
  vec2 to_edge = (u_half_size - abs(v_local_position)) / max(fwidth(v_local_position), vec2(1e-6));
  float border = 1.0 - smoothstep(1.0, 2.5, min(to_edge.x, to_edge.y));
  vec3 albedo = u_albedo * grid * mix(1.0, 0.35, border);
  float visibility = key_light_visibility(v_light_clip, u_normal);
  vec3 color = shade(albedo, v_world_position, u_normal, visibility, 1.0, 0.0);
  // The border stays opaque on a translucent quad, so its extent still reads.
  out_color = vec4(encode_srgb(color), mix(u_opacity, 1.0, border));
}
