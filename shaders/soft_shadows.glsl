// Between version.glsl and lighting.glsl when [render] shadow_softness > 0.
#define SOFT_SHADOWS 1
