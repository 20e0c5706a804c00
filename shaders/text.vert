#version 330 core
// A corner of a glyph's or a background's rectangle, in the frame's pixels.
layout(location = 0) in vec2 in_position;  // px from the frame's top-left, x right, y down
layout(location = 1) in vec2 in_texel;     // the atlas texel at this corner; negative: solid
layout(location = 2) in vec4 in_color;     // sRGB-encoded, premultiplied by its opacity

uniform vec2 u_frame_size;  // px

out vec2 v_texel;
out vec4 v_color;

void main() {
  // Pixels to clip space; rows count down from the top, GL's y points up.
  gl_Position = vec4(2.0 * in_position.x / u_frame_size.x - 1.0,
                     1.0 - 2.0 * in_position.y / u_frame_size.y, 0.0, 1.0);
  v_texel = in_texel;
  v_color = in_color;
}
