#version 330 core
// The fraction of the fill light one body leaves a point of the ground (normal +y), written for
// blending by multiplication: the ground's occlusion buffer ends as the product over the bodies
// near it (render/occlusion_layer.hpp). The occlusion is the body's form factor seen from the
// point, in closed form (Quilez, "box occlusion" and "sphere ambient occlusion"): exact while the
// body is above the ground, as a body resting on it is.
in vec3 v_point;
flat in vec3 v_center;
flat in mat3 v_rotation;
flat in vec3 v_half_size;
flat in vec2 v_kind_reach;

uniform float u_strength;  // [render] ambient_occlusion

out vec4 out_visibility;

// One edge's term of Lambert's formula for a polygon's form factor: the angle the edge subtends
// times the normal's component along the normal of the plane through the point and the edge.
float edge_term(vec3 a, vec3 b, vec3 normal) {
  vec3 c = cross(a, b);
  float length_c = length(c);
  if (length_c < 1e-9) return 0.0;
  return acos(clamp(dot(a, b), -1.0, 1.0)) * dot(normal, c) / length_c;
}

// The form factor of a box (centred at the origin, half edges h) from the point q with unit
// normal n, both in the box's frame: the sum over the faces the point sees (at most three).
float box_form_factor(vec3 q, vec3 n, vec3 h) {
  float total = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (abs(q[axis]) <= h[axis]) continue;  // this axis's faces are edge-on or turned away
    int u = (axis + 1) % 3;
    int v = (axis + 2) % 3;
    vec3 corner[4];
    for (int k = 0; k < 4; ++k) {
      vec3 c;
      c[axis] = sign(q[axis]) * h[axis];
      c[u] = (k == 1 || k == 2) ? h[u] : -h[u];
      c[v] = (k >= 2) ? h[v] : -h[v];
      corner[k] = normalize(c - q);
    }
    float face = edge_term(corner[0], corner[1], n) + edge_term(corner[1], corner[2], n) +
                 edge_term(corner[2], corner[3], n) + edge_term(corner[3], corner[0], n);
    total += abs(face);
  }
  return total / 6.28318531;
}

void main() {
  vec3 to_center = v_center - v_point;
  vec3 q = transpose(v_rotation) * -to_center;  // the point in the body's frame
  float reach = v_kind_reach.y;
  float occlusion, distance;  // distance: from the point to the body's surface (m)
  if (v_kind_reach.x < 0.5 && all(lessThanEqual(abs(q), v_half_size * 1.0001))) {
    occlusion = 1.0;  // under a box that rests on the ground: nothing of the sky is seen
    distance = 0.0;
  } else if (v_kind_reach.x > 0.5) {
    // A sphere of radius r at distance d: cos(angle from the normal) (r / d)^2.
    float d = length(to_center);
    float r = v_half_size.x;
    occlusion = max(to_center.y / d, 0.0) * (r * r) / (d * d);
    distance = max(d - r, 0.0);
  } else {
    distance = length(max(abs(q) - v_half_size, 0.0));
    if (distance >= reach) discard;  // no occlusion counted: the buffer keeps its value
    occlusion = box_form_factor(q, transpose(v_rotation) * vec3(0.0, 1.0, 0.0), v_half_size);
  }
  // Counted in full out to half the reach from the body, fading to none at the reach.
  occlusion *= 1.0 - smoothstep(0.5 * reach, reach, distance);
  out_visibility = vec4(1.0 - u_strength * clamp(occlusion, 0.0, 1.0));
}
