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
  vec3 ambient = v_ambient * fill_left(v_world_position, v_world_normal, v_occluders);
#else
  vec3 ambient = v_ambient;
#endif
  vec3 color = frame * ambient + visibility * (frame * v_diffuse + highlight * v_specular);
  out_color = vec4(encode_srgb(color), 1.0);
}
