#version 330 core
// Depth from the key light, for the shadow map: the boxes, one instance per box (as body.vert).
layout(location = 0) in vec3 in_position;  // unit cube, [-0.5, 0.5]^3
layout(location = 2) in mat4 in_model;     // body to world, including the scale to the box's size
uniform mat4 u_light_view_projection;

void main() { gl_Position = u_light_view_projection * in_model * vec4(in_position, 1.0); }
