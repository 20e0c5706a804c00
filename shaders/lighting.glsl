#version 330 core
// Shared by the lit fragment shaders (prepended to them): Blinn-Phong with one directional key
// light, a hemisphere-tinted ambient term and a percentage-closer-filtered shadow map.
// Everything is computed in linear light and encoded to sRGB once, at the end.

uniform vec3 u_light_direction;  // the way the light travels, world frame, unit
uniform vec3 u_light_color;      // linear
uniform float u_ambient;         // fraction of the key light
uniform vec3 u_camera_position;  // world frame
uniform bool u_shadows;
uniform sampler2DShadow u_shadow_map;

// The sRGB transfer function (IEC 61966-2-1), per component. Above the linear toe, x^(1/2.4)
// is fitted by x^(1/2), x^(1/4) and x^(1/8) (three square roots, far cheaper than pow on a
// software renderer; after Ian Taylor's sRGB approximations): at most 0.25 of 255 off.
vec3 encode_srgb(vec3 linear) {
  linear = clamp(linear, 0.0, 1.0);
  vec3 low = linear * 12.92;
  vec3 root2 = sqrt(linear);
  vec3 root4 = sqrt(root2);
  vec3 root8 = sqrt(root4);
  vec3 high = 0.662002687 * root2 + 0.684122060 * root4 - 0.323583601 * root8 - 0.0225411470 * linear;
  return mix(high, low, vec3(lessThanEqual(linear, vec3(0.0031308))));
}

// 1 where the key light reaches the point, 0 in shadow. Four bilinear comparisons (each a 2x2
// percentage-closer filter) soften the edge. Points outside the map's square are lit; this also
// spares most of the ground the lookups, which are the costliest part of a software render.
float key_light_visibility(vec4 light_clip, vec3 normal) {
  if (!u_shadows) return 1.0;
  vec3 p = light_clip.xyz / light_clip.w * 0.5 + 0.5;
  if (p.z > 1.0 || any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)))) {
    return 1.0;
  }
  float slope = 1.0 - max(dot(normal, -u_light_direction), 0.0);
  float bias = 0.0008 + 0.0025 * slope;  // against self-shadowing ("acne") on grazing faces
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  float lit = texture(u_shadow_map, vec3(p.xy + vec2(-0.5, -0.5) * texel, p.z - bias)) +
              texture(u_shadow_map, vec3(p.xy + vec2(0.5, -0.5) * texel, p.z - bias)) +
              texture(u_shadow_map, vec3(p.xy + vec2(-0.5, 0.5) * texel, p.z - bias)) +
              texture(u_shadow_map, vec3(p.xy + vec2(0.5, 0.5) * texel, p.z - bias));
  return 0.25 * lit;
}

vec3 shade(vec3 albedo, vec3 position, vec3 normal, float visibility, float shininess,
           float specular_strength) {
  vec3 to_light = -u_light_direction;
  vec3 to_eye = normalize(u_camera_position - position);
  float diffuse = max(dot(normal, to_light), 0.0);
  vec3 halfway = normalize(to_light + to_eye);
  float specular = diffuse > 0.0 ? pow(max(dot(normal, halfway), 0.0), shininess) : 0.0;
  // Sky above, a darker bounce from below.
  float hemisphere = mix(0.55, 1.0, normal.y * 0.5 + 0.5);
  vec3 ambient = u_ambient * hemisphere * u_light_color * albedo;
  vec3 key = visibility * u_light_color * (albedo * diffuse + specular_strength * specular);
  return ambient + key;
}
