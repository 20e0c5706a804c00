#version 330 core
// A flat colour, premultiplied, faded as a whole where the scene hides it (overlay_layer.hpp).
uniform float u_opacity;  // 0-1

in vec4 v_color;

out vec4 out_color;

void main() {
  out_color = v_color * u_opacity;
}
