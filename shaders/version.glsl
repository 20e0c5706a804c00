#version 330 core
// First of every program's fragment sources that are built from several files (lighting.glsl,
// form_factor.glsl and the shaders that use them).
