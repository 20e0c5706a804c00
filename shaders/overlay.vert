#version 330 core
// A corner of a line's or an arrow's triangles, already in clip space (overlay_geometry.cpp):
// offset on the picture at its own depth, so only the depth test is left to do.
layout(location = 0) in vec4 in_clip;   // clip space
layout(location = 1) in vec4 in_color;  // sRGB-encoded, premultiplied by its opacity

out vec4 v_color;

void main() {
  gl_Position = in_clip;
  v_color = in_color;
}
