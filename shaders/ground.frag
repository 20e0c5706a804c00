// The ground: a grid of anti-aliased lines, lit and shadowed, fading into the background
// with distance so that it has no hard horizon.
in vec3 v_world_position;
in vec4 v_light_clip;

uniform vec3 u_albedo;            // linear
uniform vec3 u_background;        // linear
uniform float u_grid_spacing;     // m; 0 = no grid
uniform vec3 u_center;
uniform float u_half_extent;
out vec4 out_color;

void main() {
  vec3 albedo = u_albedo;
  if (u_grid_spacing > 0.0) {
    vec2 cell = v_world_position.xz / u_grid_spacing;
    vec2 width = fwidth(cell);
    vec2 line = abs(fract(cell - 0.5) - 0.5) / max(width, vec2(1e-6));
    float on_line = 1.0 - min(min(line.x, line.y), 1.0);
    // Lines thinner than a pixel become grey haze instead of moiré.
    on_line *= 1.0 - smoothstep(0.3, 0.8, max(width.x, width.y));
    albedo *= 1.0 - 0.35 * on_line;
  }
  vec3 normal = vec3(0.0, 1.0, 0.0);
  vec3 color = shade(albedo, v_world_position, normal,
                     key_light_visibility(v_light_clip, normal), 16.0, 0.05);
  float distance_to_center = length(v_world_position.xz - u_center.xz);
  float fade = smoothstep(0.35 * u_half_extent, u_half_extent, distance_to_center);
  out_color = vec4(encode_srgb(mix(color, u_background, fade)), 1.0);
}
