#version 330 core
// The screen (scissored to where the occlusion lies): render/occlusion_layer.hpp's apply().
layout(location = 0) in vec2 in_corner;  // [-1, 1]^2, clip space
void main() { gl_Position = vec4(in_corner, 0.0, 1.0); }
