#version 330 core
// Darkens the lit ground drawn already (the kept ground, before the bodies) by the fill light the
// bodies hide, multiplying it in place (blending: destination × this colour). Lit ground sends
// back L (1 − a (1 − fill)), a = the fill's share of its light: the factor on the linear colour.
// The frame holds sRGB-encoded colours, whose curve is nearly the power 1/2.4: the factor's own
// power 1/2.4 on the encoded colour is within 0.6 of a level of the exact encoding's for factors
// down to 0.5 (the fill's share of the ground's light keeps them above 0.7 by default). In
// shadow the ground is shaded again, exactly (ground.frag, RECEIVE_SHADOWS).
uniform sampler2D u_occlusion;   // a texel per 4 × 4 pixels, filtered bilinearly
uniform vec2 u_occlusion_scale;  // pixel position to the buffer's coordinates
uniform float u_fill_share;      // a
out vec4 out_factor;

void main() {
  float fill = texture(u_occlusion, gl_FragCoord.xy * u_occlusion_scale).r;
  if (fill == 1.0) discard;  // nothing hidden: the colour stays (and is not written)
  // d = 1 - factor; factor^(1/2.4) to second order in d: within 0.2% for d up to 0.3.
  float d = u_fill_share * (1.0 - fill);
  out_factor = vec4(vec3(1.0 - d * (0.416667 + 0.121528 * d)), 1.0);
}
