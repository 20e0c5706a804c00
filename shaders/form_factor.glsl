// The ambient occlusion of a point by one body, in closed form: the fraction of the fill light
// (a uniform sky over the point's hemisphere, cosine-weighted) that the body hides. Shared by the
// ground's occlusion buffer (occlusion.frag) and the solids that receive occlusion from the bodies
// beside them (receive_body_occlusion.glsl). A box hides its form factor seen from the point, Lambert's formula for
// the polygons of the faces the point sees, each clipped to the point's hemisphere; a ball
// cos(angle from the normal) (r / d)^2 (Quilez, "box occlusion" and "sphere ambient occlusion").
// After version.glsl.

// One edge's term of Lambert's formula for a polygon's form factor: the angle the edge subtends
// times the normal's component along the normal of the plane through the point and the edge.
float edge_term(vec3 a, vec3 b, vec3 normal) {
  vec3 c = cross(a, b);
  float length_c = length(c);
  if (length_c < 1e-9) return 0.0;
  return acos(clamp(dot(a, b), -1.0, 1.0)) * dot(normal, c) / length_c;
}

// Lambert's formula for the quadrilateral c0 c1 c2 c3 (seen from the origin, in order) cut to
// the part above the plane through the origin with unit normal n (Sutherland-Hodgman against
// one plane, written without arrays indexed per pixel, which a software renderer pays dearly
// for): each edge keeps its part above the plane, and the edge that leaves the plane is joined
// to the edge that comes back by a segment in it. Below the plane the polygon hides nothing.
// `cut` false: the whole quadrilateral is above the plane (a body above the ground seen from
// the ground), nothing to cut. Passed as a constant, the compiler drops the cut's code: llvmpipe
// runs both sides of a branch, so the ground's buffer would pay for it at every pixel.
float clipped_quad_term(vec3 c0, vec3 c1, vec3 c2, vec3 c3, vec3 n, bool cut) {
  vec3 c[4] = vec3[](c0, c1, c2, c3);
  if (!cut) {
    vec3 u0 = normalize(c0), u1 = normalize(c1), u2 = normalize(c2), u3 = normalize(c3);
    return edge_term(u0, u1, n) + edge_term(u1, u2, n) + edge_term(u2, u3, n) +
           edge_term(u3, u0, n);
  }
  float h[4] = float[](dot(n, c0), dot(n, c1), dot(n, c2), dot(n, c3));
  float total = 0.0;
  vec3 leaves = vec3(0.0), returns = vec3(0.0);
  bool left = false, returned = false;
  for (int k = 0; k < 4; ++k) {
    int j = (k + 1) % 4;
    bool up_k = h[k] >= 0.0, up_j = h[j] >= 0.0;
    float step = h[k] - h[j];
    vec3 crossing = normalize(c[k] + (c[j] - c[k]) * (step != 0.0 ? h[k] / step : 0.0));
    vec3 from = up_k ? normalize(c[k]) : crossing;
    vec3 to = up_j ? normalize(c[j]) : crossing;
    if (up_k || up_j) total += edge_term(from, to, n);
    if (up_k && !up_j) {
      leaves = crossing;
      left = true;
    }
    if (!up_k && up_j) {
      returns = crossing;
      returned = true;
    }
  }
  if (left && returned) total += edge_term(leaves, returns, n);
  return total;
}

// The form factor of a box (centred at the origin, half edges h) from the point q with unit
// normal n, both in the box's frame: the sum over the faces the point sees (at most three), each
// cut to the part above the point's tangent plane unless `cut` is false (see above).
float box_form_factor(vec3 q, vec3 n, vec3 h, bool cut) {
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
      corner[k] = c - q;
    }
    total += abs(clipped_quad_term(corner[0], corner[1], corner[2], corner[3], n, cut));
  }
  return total / 6.28318531;
}

// The occlusion by one body of the point `point` with unit normal `normal` (world frame): the
// body's centre, rotation (body to world) and half edges; a ball (`ball`) of radius half_size.x
// or else a box; counted in full out to half `reach` from the body's surface, fading to none at
// `reach`. 1 inside a box (the ground under a box resting on it sees nothing of the sky).
// `cut`: as box_form_factor's; false only where the body is known to be above the point's plane.
float occlusion_by(vec3 point, vec3 normal, vec3 center, mat3 rotation, vec3 half_size, bool ball,
                   float reach, bool cut) {
  vec3 to_center = center - point;
  float occlusion, distance;  // distance: from the point to the body's surface (m)
  if (ball) {
    float d = length(to_center);
    float r = half_size.x;
    occlusion = max(dot(normal, to_center) / d, 0.0) * (r * r) / (d * d);
    distance = max(d - r, 0.0);
  } else {
    vec3 q = transpose(rotation) * -to_center;  // the point in the body's frame
    if (all(lessThanEqual(abs(q), half_size * 1.0001))) return 1.0;
    distance = length(max(abs(q) - half_size, 0.0));
    if (distance >= reach) return 0.0;
    occlusion = box_form_factor(q, transpose(rotation) * normal, half_size, cut);
  }
  return clamp(occlusion * (1.0 - smoothstep(0.5 * reach, reach, distance)), 0.0, 1.0);
}
