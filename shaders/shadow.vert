#version 330 core
// Depth from the key light, for the shadow map: the quads, one draw each (the boxes are in
// box_shadow.vert).
layout(location = 0) in vec3 in_position;
uniform mat4 u_model;
uniform mat4 u_light_view_projection;

void main() { gl_Position = u_light_view_projection * u_model * vec4(in_position, 1.0); }
