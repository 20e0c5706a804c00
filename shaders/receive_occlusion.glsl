// Prepended to ground.frag for the passes that read the ambient occlusion (see Renderer::draw).
#define RECEIVE_OCCLUSION 1
