#version 330 core
// First of every program's fragment sources that use lighting.glsl (and of nothing else).
