// A box face: its colour lit (body.vert) and framed by dark edges, so the rotation reads.
// Per pixel only the frame, the shadow and the highlight remain.
in vec3 v_world_position;
in vec2 v_face_position;
in vec4 v_light_clip;
flat in vec3 v_world_normal;
flat in vec2 v_face_half_size;
flat in float v_frame_width;
flat in vec3 v_ambient;
flat in vec3 v_diffuse;
flat in vec3 v_specular;
flat in vec4 v_occluders;  // the bodies that darken this box: their indices + 1, 0 none

#ifdef RECEIVE_BODY_OCCLUSION
// Four texels a body (render/occluders.hpp): (centre, reach; negative for a ball) and the
// rotation's columns, each with the half edge along it; kOccludersPerRow bodies a row.
uniform sampler2D u_occluders;
const int kOccludersPerRow = 256;
uniform float u_occlusion_strength;  // [render] ambient_occlusion

// What the bodies beside it leave of the fill light at a point of this box: the product of
// 1 - strength × occlusion over them (form_factor.glsl).
float fill_left(vec3 point, vec3 normal) {
  float left = 1.0;
  for (int k = 0; k < 4; ++k) {
    int index = int(v_occluders[k]) - 1;
    if (index < 0) break;
    ivec2 at = ivec2(4 * (index % kOccludersPerRow), index / kOccludersPerRow);
    vec4 center = texelFetch(u_occluders, at, 0);
    vec4 x = texelFetch(u_occluders, at + ivec2(1, 0), 0);
    vec4 y = texelFetch(u_occluders, at + ivec2(2, 0), 0);
    vec4 z = texelFetch(u_occluders, at + ivec2(3, 0), 0);
    left *= 1.0 - u_occlusion_strength *
                      occlusion_by(point, normal, center.xyz, mat3(x.xyz, y.xyz, z.xyz),
                                   vec3(x.w, y.w, z.w), center.w < 0.0, abs(center.w));
  }
  return left;
}
#endif

out vec4 out_color;

// x^48 (Blinn-Phong shininess 48) by squaring: five products instead of pow's exp2(48 log2 x).
float power_48(float x) {
  float x2 = x * x;
  float x4 = x2 * x2;
  float x8 = x4 * x4;
  float x16 = x8 * x8;
  return x16 * x16 * x16;
}

void main() {
  // Distance (m) to the nearest edge of this face.
  vec2 to_edge = v_face_half_size - abs(v_face_position);
  float d = min(to_edge.x, to_edge.y);
  float blur = fwidth(d);
  float edge = 1.0 - smoothstep(v_frame_width - blur, v_frame_width + blur, d);
  float frame = mix(1.0, 0.18, edge);  // the albedo darkened on the frame

  float visibility = key_light_visibility(v_light_clip, v_world_normal);
  vec3 to_eye = normalize(u_camera_position - v_world_position);
  vec3 halfway = normalize(to_eye - u_light_direction);
  float highlight = power_48(max(dot(v_world_normal, halfway), 0.0));
#ifdef RECEIVE_BODY_OCCLUSION
  vec3 ambient = v_ambient * fill_left(v_world_position, v_world_normal);
#else
  vec3 ambient = v_ambient;
#endif
  vec3 color = frame * ambient + visibility * (frame * v_diffuse + highlight * v_specular);
  out_color = vec4(encode_srgb(color), 1.0);
}
