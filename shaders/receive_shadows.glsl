// Prepended to ground.frag for the pass that receives shadows (see Renderer::draw).
#define RECEIVE_SHADOWS 1
