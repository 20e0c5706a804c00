// The ground: a matte plane of one colour, so its lighting is two constants worked out once per
// frame on the CPU (lit and in shadow); per pixel only the grid, the shadow and the fade remain.
// Shadow lookups are the costliest part of a software render, so the ground is drawn with them
// (RECEIVE_SHADOWS) only where a shadow can fall, then without them everywhere else.
in vec3 v_world_position;
in vec4 v_light_clip;

uniform vec3 u_lit_color;     // linear: albedo × (ambient + key × cos(angle of incidence))
uniform vec3 u_shadow_color;  // linear: albedo × ambient
uniform vec3 u_background;    // linear
uniform float u_grid_spacing;  // m; 0 = no grid
uniform vec3 u_center;
uniform float u_half_extent;
uniform float u_fade_start;  // of u_half_extent: render/view_extent.hpp's kGroundFadeStart
// For a transparent picture (≥ 0) the ground is not drawn, only its shadows, as black of this
// opacity where the key light is wholly hidden; negative otherwise (Renderer::draw_ground_with).
uniform float u_shadow_opacity;
// The fill light the bodies leave each pixel's ground (render/occlusion_layer.hpp), read by
// the shadowed pass when the look has occlusion (RECEIVE_OCCLUSION).
uniform sampler2D u_occlusion;   // a texel per 4 × 4 pixels, filtered bilinearly
uniform vec2 u_occlusion_scale;  // pixel position to the buffer's coordinates
out vec4 out_color;

void main() {
  float grid = 1.0;
  if (u_grid_spacing > 0.0) {
    vec2 cell = v_world_position.xz / u_grid_spacing;
    vec2 width = fwidth(cell);
    vec2 line = abs(fract(cell - 0.5) - 0.5) / max(width, vec2(1e-6));
    float on_line = 1.0 - min(min(line.x, line.y), 1.0);
    // Lines thinner than a pixel become grey haze instead of moiré.
    on_line *= 1.0 - smoothstep(0.3, 0.8, max(width.x, width.y));
    grid = 1.0 - 0.35 * on_line;
  }
#ifdef RECEIVE_OCCLUSION
  float fill = texture(u_occlusion, gl_FragCoord.xy * u_occlusion_scale).r;
#else
  float fill = 1.0;
#endif
#ifdef RECEIVE_SHADOWS
  float visibility = key_light_visibility(v_light_clip, vec3(0.0, 1.0, 0.0));
#else
  float visibility = 1.0;
#endif
  // The fill (u_shadow_color) times what the occlusion leaves of it, plus the key where it falls.
  vec3 color = grid * mix(u_shadow_color * fill, u_lit_color - u_shadow_color * (1.0 - fill),
                          visibility);
  float distance_to_center = length(v_world_position.xz - u_center.xz);
  float fade = smoothstep(u_fade_start * u_half_extent, u_half_extent, distance_to_center);
  if (u_shadow_opacity >= 0.0) {
    // Black of opacity `shadow` over the background colour the frame was cleared to, as every
    // layer of a transparent frame is (render/straight_alpha.hpp makes it straight black).
    float shadow = ((1.0 - visibility) * u_shadow_opacity + (1.0 - fill) * (1.0 - u_shadow_opacity)) *
                   (1.0 - fade);
    out_color = vec4(encode_srgb(u_background) * (1.0 - shadow), shadow);
    return;
  }
  out_color = vec4(encode_srgb(mix(color, u_background, fade)), 1.0);
}
