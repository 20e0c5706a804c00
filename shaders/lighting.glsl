// Shared by the lit fragment shaders (prepended to them): Blinn-Phong with one directional key
// light, a sky/ground hemisphere fill and a percentage-closer-filtered shadow map, soft with the
// light's size. Everything is computed in linear light and encoded to sRGB once, at the end
// (docs/scene-reference.md, "Lighting", has the formula). After version.glsl, and after
// soft_shadows.glsl when the look's shadows are soft.

uniform vec3 u_light_direction;  // the way the light travels, world frame, unit
uniform vec3 u_light_color;      // linear, times the exposure
uniform float u_ambient;         // fraction of the key light
uniform float u_fill_low;        // the fill on a face turned down, of that on a face turned up
uniform vec3 u_camera_position;  // world frame
uniform bool u_shadows;
uniform sampler2DShadow u_shadow_map;
// The same map's depths, read as numbers (a sampler object without comparison): the blocker
// search of the soft shadows.
uniform sampler2D u_shadow_depth;
// The soft shadows' filter radius, in shadow-map units per unit of shadow-map depth between a
// blocker and the receiver: 2 tan(half the light's apparent diameter) (the map spans 2r across
// and 4r deep).
uniform float u_penumbra;
uniform vec3 u_light_right;  // the shadow map's x and y axes, world frame, unit
uniform vec3 u_light_up;

// The fill's hemisphere factor for a unit normal: 1 facing up (the sky), u_fill_low facing down.
float hemisphere(vec3 normal) { return mix(u_fill_low, 1.0, normal.y * 0.5 + 0.5); }

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

// The taps on a disk of radius 1: Vogel's golden-angle spiral, tap i of n at
// r = sqrt((i + 0.5) / n), angle = 2.39996 i (as constants: no trigonometry per pixel).
const int kBlockerTaps = 4;
const vec2 kBlockerTap[kBlockerTaps] = vec2[](vec2(0.353553, 0.000000), vec2(-0.451544, 0.413652),
                                               vec2(0.069116, -0.787542), vec2(0.569142, 0.742346));
const int kFilterTaps = 12;
const vec2 kFilterTap[kFilterTaps] = vec2[](
    vec2(0.204124, 0.000000), vec2(-0.260699, 0.238822), vec2(0.039904, -0.454688),
    vec2(0.328595, 0.428593), vec2(-0.603011, -0.106664), vec2(0.571225, -0.363367),
    vec2(-0.191064, 0.710747), vec2(-0.364379, -0.701590), vec2(0.790557, 0.288710),
    vec2(-0.822442, 0.339492), vec2(0.396472, -0.847237), vec2(0.292982, 0.934074));

// `tap` turned by the unit vector `turn` (cos, sin).
vec2 turned(vec2 tap, vec2 turn) {
  return vec2(tap.x * turn.x - tap.y * turn.y, tap.x * turn.y + tap.y * turn.x);
}

const float kMaxFilterTexels = 12.0;  // the widest penumbra's radius, in shadow-map texels

// 1 where the key light reaches the point, 0 in shadow. Points outside the map's square are lit;
// this also spares most of the ground the lookups, which are the costliest part of a software
// render. A face turned away from the light gets none of it whatever the map says (the caller
// multiplies by its diffuse factor, 0): 1 there.
float key_light_visibility(vec4 light_clip, vec3 normal) {
  if (!u_shadows) return 1.0;
  float facing = dot(normal, -u_light_direction);
  if (facing <= 0.0) return 1.0;
  vec3 p = light_clip.xyz / light_clip.w * 0.5 + 0.5;
  if (p.z > 1.0 || any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)))) {
    return 1.0;
  }
  float slope = 1.0 - facing;
  float bias = 0.0008 + 0.0025 * slope;  // against self-shadowing ("acne") on grazing faces
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  float z = p.z - bias;
#ifndef SOFT_SHADOWS
  // Hard: four bilinear comparisons (each a 2x2 percentage-closer filter) soften the edge.
  float lit = texture(u_shadow_map, vec3(p.xy + vec2(-0.5, -0.5) * texel, z)) +
              texture(u_shadow_map, vec3(p.xy + vec2(0.5, -0.5) * texel, z)) +
              texture(u_shadow_map, vec3(p.xy + vec2(-0.5, 0.5) * texel, z)) +
              texture(u_shadow_map, vec3(p.xy + vec2(0.5, 0.5) * texel, z));
  return 0.25 * lit;
#else
  // Soft: percentage-closer soft shadows (Fernando 2005). The taps are turned per pixel by
  // interleaved gradient noise of the pixel's position (Jimenez 2014): the same every run. The
  // turn is the unit vector towards a point the noise places on a square's edge (no
  // trigonometry): 0 to 1 walks once around it.
  float noise = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  float side = 4.0 * noise;
  float along = 2.0 * fract(side) - 1.0;
  vec2 edge = side < 1.0 ? vec2(1.0, along)
            : side < 2.0 ? vec2(-along, 1.0)
            : side < 3.0 ? vec2(-1.0, -along)
                         : vec2(along, -1.0);
  vec2 turn = normalize(edge);
  // A tap beside the point compares with the depth of the point's own tangent plane there (a
  // receiver-plane bias, from the normal: the map is orthographic), so that a wide filter does
  // not shadow a surface by itself: dz/du = (n · x_light) / (2 n · l), likewise for v.
  vec2 slope_uv = 0.5 * vec2(dot(normal, u_light_right), dot(normal, u_light_up)) /
                  max(facing, 0.1);
  // 1. The blockers' mean depth, searched over the widest penumbra a blocker this far in front
  // of the point could cast.
  float search = min(u_penumbra * z, kMaxFilterTexels * texel.x);
  float blocker_sum = 0.0;
  float blockers = 0.0;
  for (int i = 0; i < kBlockerTaps; ++i) {
    vec2 offset = search * turned(kBlockerTap[i], turn);
    float depth = textureLod(u_shadow_depth, p.xy + offset, 0.0).r;
    if (depth < z + dot(slope_uv, offset)) {
      blocker_sum += depth;
      blockers += 1.0;
    }
  }
  // 2. The penumbra there: its radius grows with the distance from the blockers to the point.
  float radius =
      clamp(u_penumbra * (z - blocker_sum / max(blockers, 1.0)), texel.x, kMaxFilterTexels * texel.x);
  // 3. Percentage-closer filtering over it: each tap one texel's depth compared (a bilinear
  // comparison of four costs a software rasterizer four times as much; the taps' per-pixel turn
  // smooths what one texel each leaves). Lit where no blocker was found.
  float lit = 0.0;
  for (int i = 0; i < kFilterTaps; ++i) {
    vec2 offset = radius * turned(kFilterTap[i], turn);
    float depth = textureLod(u_shadow_depth, p.xy + offset, 0.0).r;
    lit += step(z + dot(slope_uv, offset), depth);
  }
  return blockers > 0.0 ? lit / float(kFilterTaps) : 1.0;
#endif
}

// Blinn-Phong with the fill light times `fill`: what the bodies beside the point leave of it
// (receive_body_occlusion.glsl), 1 where nothing hides any.
vec3 shade_filled(vec3 albedo, vec3 position, vec3 normal, float visibility, float shininess,
                  float specular_strength, float fill) {
  vec3 to_light = -u_light_direction;
  vec3 to_eye = normalize(u_camera_position - position);
  float diffuse = max(dot(normal, to_light), 0.0);
  vec3 halfway = normalize(to_light + to_eye);
  float specular = diffuse > 0.0 ? pow(max(dot(normal, halfway), 0.0), shininess) : 0.0;
  vec3 ambient = u_ambient * hemisphere(normal) * u_light_color * albedo;
  vec3 key = visibility * u_light_color * (albedo * diffuse + specular_strength * specular);
  return ambient * fill + key;
}

vec3 shade(vec3 albedo, vec3 position, vec3 normal, float visibility, float shininess,
           float specular_strength) {
  return shade_filled(albedo, position, normal, visibility, shininess, specular_strength, 1.0);
}
