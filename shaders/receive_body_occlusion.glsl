// Prepended to body.frag (after form_factor.glsl) when the look has ambient occlusion: each box
// receives the occlusion of the bodies beside it (see Renderer::Resources::create).
#define RECEIVE_BODY_OCCLUSION 1
