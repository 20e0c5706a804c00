// Prepended, after form_factor.glsl, to the fragment shaders of the solids (body.frag, ball.frag,
// hull.frag) when the look has ambient occlusion: each receives the occlusion of the bodies beside
// it (render/occluders.hpp; see Renderer::Resources::create).
#define RECEIVE_BODY_OCCLUSION 1

// Four texels a body (render/occluders.hpp): (centre, reach; negative for a ball) and the
// rotation's columns, each with the half edge along it; kOccludersPerRow bodies a row.
uniform sampler2D u_occluders;
const int kOccludersPerRow = 256;
uniform float u_occlusion_strength;  // [render] ambient_occlusion

// What the bodies beside it leave of the fill light at a point of a body: the product of
// 1 - strength × occlusion over them (form_factor.glsl). `occluders`: their indices + 1, 0 past
// the last (render/box_instances.hpp), from the vertex shader's location 12.
float fill_left(vec3 point, vec3 normal, vec4 occluders) {
  float left = 1.0;
  for (int k = 0; k < 4; ++k) {
    int index = int(occluders[k]) - 1;
    if (index < 0) break;
    ivec2 at = ivec2(4 * (index % kOccludersPerRow), index / kOccludersPerRow);
    vec4 center = texelFetch(u_occluders, at, 0);
    vec4 x = texelFetch(u_occluders, at + ivec2(1, 0), 0);
    vec4 y = texelFetch(u_occluders, at + ivec2(2, 0), 0);
    vec4 z = texelFetch(u_occluders, at + ivec2(3, 0), 0);
    left *= 1.0 - u_occlusion_strength *
                      occlusion_by(point, normal, center.xyz, mat3(x.xyz, y.xyz, z.xyz),
                                   vec3(x.w, y.w, z.w), center.w < 0.0, abs(center.w), true);
  }
  return left;
}
