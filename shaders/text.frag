#version 330 core
// Glyph coverage (or full coverage for a background) times a premultiplied colour: blended with
// glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA), the result stays premultiplied for compositing.
uniform sampler2D u_atlas;  // single channel: coverage 0-1

in vec2 v_texel;
in vec4 v_color;

out vec4 out_color;

void main() {
  // Rectangles are whole pixels and one texel per pixel, so each pixel centre lands at a texel
  // centre: fetched exactly, no filtering, the same wherever the glyph sits in the atlas.
  float coverage = v_texel.x < 0.0 ? 1.0 : texelFetch(u_atlas, ivec2(v_texel), 0).r;
  out_color = v_color * coverage;
}
