#include "render/geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

namespace tumble::render {

double linear_from_srgb(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double srgb_from_linear(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

Eigen::Vector3f linear_from_srgb(const Color& srgb) {
  Eigen::Vector3f out;
  for (int i = 0; i < 3; ++i) {
    out[i] = static_cast<float>(linear_from_srgb(std::clamp(srgb[i], 0.0, 1.0)));
  }
  return out;
}

Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3 forward = (target - eye).normalized();
  Vec3 side = forward.cross(up);
  // Looking along `up`: any perpendicular will do.
  if (side.squaredNorm() < 1e-12) side = forward.cross(forward.unitOrthogonal());
  side.normalize();
  const Vec3 true_up = side.cross(forward);
  Mat4 view = Mat4::Identity();
  view.row(0).head<3>() = side;
  view.row(1).head<3>() = true_up;
  view.row(2).head<3>() = -forward;
  view(0, 3) = -side.dot(eye);
  view(1, 3) = -true_up.dot(eye);
  view(2, 3) = forward.dot(eye);
  return view;
}

Quat camera_rotation(const Camera& camera) {
  const Mat4 view = look_at(camera.position, camera.look_at, camera.up);
  return Quat(Eigen::Matrix3d(view.topLeftCorner<3, 3>().transpose())).normalized();
}

Mat4 perspective(double fov_y_radians, double aspect, double near, double far) {
  const double f = 1.0 / std::tan(fov_y_radians / 2.0);
  Mat4 m = Mat4::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far + near) / (near - far);
  m(2, 3) = 2.0 * far * near / (near - far);
  m(3, 2) = -1.0;
  return m;
}

Mat4 orthographic(double half_width, double near, double far) {
  Mat4 m = Mat4::Identity();
  m(0, 0) = 1.0 / half_width;
  m(1, 1) = 1.0 / half_width;
  m(2, 2) = -2.0 / (far - near);
  m(2, 3) = -(far + near) / (far - near);
  return m;
}

Mat4 model_matrix(const Box& box) {
  Mat4 m = Mat4::Identity();
  m.topLeftCorner<3, 3>() = box.orientation.normalized().toRotationMatrix() * box.size.asDiagonal();
  m.topRightCorner<3, 1>() = box.position;
  return m;
}

Mat4 model_matrix(const Quad& quad) {
  Mat4 m = Mat4::Identity();
  m.topLeftCorner<3, 3>() = quad.orientation.normalized().toRotationMatrix() *
                            Vec3(0.5 * quad.width, 1.0, 0.5 * quad.depth).asDiagonal();
  m.topRightCorner<3, 1>() = quad.center;
  return m;
}

Vec3 front_normal(const Quad& quad) {
  return quad.orientation.normalized() * Vec3::UnitY();
}

bool seen_from_back(const Quad& quad, const Vec3& eye) {
  return (eye - quad.center).dot(front_normal(quad)) < 0.0;
}

std::array<Vec3, 4> corners(const Quad& quad) {
  const Mat4 model = model_matrix(quad);
  std::array<Vec3, 4> out;
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector3f& square = Eigen::Map<const Eigen::Vector3f>(kUnitSquare[i]);
    out[i] = (model * square.cast<double>().homogeneous()).head<3>();
  }
  return out;
}

std::vector<CubeVertex> cube_vertices() {
  std::vector<CubeVertex> out;
  for (int axis = 0; axis < 3; ++axis) {
    for (const float sign : {1.0f, -1.0f}) {
      const int u = (axis + 1) % 3;
      const int v = (axis + 2) % 3;
      // Corners counter-clockwise seen from outside: (u, v) = (-,-), (+,-), (+,+), (-,+),
      // mirrored on the negative face to keep the winding.
      const float us[4] = {-0.5f, 0.5f, 0.5f, -0.5f};
      const float vs[4] = {-0.5f, -0.5f, 0.5f, 0.5f};
      for (int corner = 0; corner < 4; ++corner) {
        CubeVertex vertex{};
        vertex.position[axis] = 0.5f * sign;
        vertex.position[u] = us[corner] * sign;
        vertex.position[v] = vs[corner];
        vertex.normal[axis] = sign;
        out.push_back(vertex);
      }
    }
  }
  return out;
}

std::vector<std::uint16_t> cube_indices() {
  std::vector<std::uint16_t> indices;
  for (std::uint16_t face = 0; face < 6; ++face) {
    const auto base = static_cast<std::uint16_t>(face * 4);
    for (const std::uint16_t corner : {0, 1, 2, 0, 2, 3}) {
      indices.push_back(static_cast<std::uint16_t>(base + corner));
    }
  }
  return indices;
}

std::vector<CubeVertex> sphere_vertices(int divisions, std::vector<std::uint16_t>& indices) {
  std::vector<CubeVertex> out;
  indices.clear();
  const int side = divisions + 1;  // vertices along a face's edge
  for (const CubeVertex& face : [] {
         std::vector<CubeVertex> centres;  // one per face: its centre and normal
         const std::vector<CubeVertex> cube = cube_vertices();
         for (std::size_t f = 0; f < 6; ++f) centres.push_back(cube[4 * f]);
         return centres;
       }()) {
    int axis = 0;
    while (face.normal[axis] == 0.0f) ++axis;
    const float sign = face.normal[axis];
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const auto base = static_cast<std::uint16_t>(out.size());
    for (int j = 0; j < side; ++j) {
      for (int i = 0; i < side; ++i) {
        // On the cube's face, as cube_vertices winds it (u mirrored on the negative face).
        Eigen::Vector3f p = Eigen::Vector3f::Zero();
        p[axis] = sign;
        p[u] = sign * (-1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(divisions));
        p[v] = -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(divisions);
        const Eigen::Vector3f n = p.normalized();
        CubeVertex vertex{};
        for (int k = 0; k < 3; ++k) {
          vertex.position[k] = 0.5f * n[k];
          vertex.normal[k] = n[k];
        }
        out.push_back(vertex);
      }
    }
    for (int j = 0; j < divisions; ++j) {
      for (int i = 0; i < divisions; ++i) {
        const auto at = [&](int di, int dj) {
          return static_cast<std::uint16_t>(base + (j + dj) * side + i + di);
        };
        for (const std::uint16_t k : {at(0, 0), at(1, 0), at(1, 1), at(0, 0), at(1, 1), at(0, 1)}) {
          indices.push_back(k);
        }
      }
    }
  }
  return out;
}

std::vector<CubeVertex> capsule_vertices(int divisions, std::vector<std::uint16_t>& indices) {
  std::vector<std::uint16_t> sphere_indices;
  const std::vector<CubeVertex> sphere = sphere_vertices(divisions, sphere_indices);
  std::vector<CubeVertex> out;
  indices.clear();
  // The copy of sphere vertex i in the half of sign `half` (0: below, 1: above), made once.
  std::vector<std::array<int, 2>> copy(sphere.size(), {-1, -1});
  const auto in_half = [&](std::uint16_t i, int half) {
    int& at = copy[i][static_cast<std::size_t>(half)];
    if (at < 0) {
      CubeVertex v = sphere[i];
      v.normal[0] = 0.0f;
      v.normal[1] = half == 1 ? 1.0f : -1.0f;
      v.normal[2] = 0.0f;
      at = static_cast<int>(out.size());
      out.push_back(v);
    }
    return static_cast<std::uint16_t>(at);
  };
  for (std::size_t t = 0; t < sphere_indices.size(); t += 3) {
    const std::uint16_t k[3] = {sphere_indices[t], sphere_indices[t + 1], sphere_indices[t + 2]};
    float y = 0.0f;
    for (const std::uint16_t i : k) y += sphere[i].position[1];
    const int half = y > 0.0f ? 1 : 0;  // no cell crosses the equator: its vertices lie on it
    for (const std::uint16_t i : k) indices.push_back(in_half(i, half));
    if (half == 0) continue;
    // An edge of the upper half on the equator: the band below it, wound as the cell across it.
    for (int e = 0; e < 3; ++e) {
      const std::uint16_t a = k[e], b = k[(e + 1) % 3];
      if (sphere[a].position[1] != 0.0f || sphere[b].position[1] != 0.0f) continue;
      for (const std::uint16_t i : {in_half(b, 1), in_half(a, 1), in_half(a, 0), in_half(b, 1),
                                    in_half(a, 0), in_half(b, 0)}) {
        indices.push_back(i);
      }
    }
  }
  return out;
}

std::vector<HullVertex> hull_vertices(const HullMesh& mesh, const Vec3& size,
                                      std::vector<std::uint16_t>& indices) {
  std::vector<HullVertex> out;
  indices.clear();
  constexpr float kInside = 1e3f;  // never near 0: a side inside the face is no edge
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<std::uint32_t>& face = mesh.faces[f];
    const Vec3& n = mesh.normals[f];
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      // The fan's triangle (0, k, k + 1): its side opposite corner 0 (k to k + 1) is the face's
      // edge; the side opposite k + 1 (0 to k) is one when k = 1, opposite k (0 to k + 1) when
      // k + 1 is the last corner.
      const std::uint32_t corners[3] = {face[0], face[k], face[k + 1]};
      const bool edge[3] = {true, k + 1 == face.size() - 1, k == 1};
      for (int c = 0; c < 3; ++c) {
        HullVertex v{};
        const Vec3 p = mesh.corners[corners[c]].cwiseQuotient(size);
        for (int i = 0; i < 3; ++i) {
          v.position[i] = static_cast<float>(p[i]);
          v.normal[i] = static_cast<float>(n[i]);
          v.edge[i] = i == c ? 1.0f : 0.0f;
          if (!edge[i]) v.edge[i] = kInside;
        }
        indices.push_back(static_cast<std::uint16_t>(out.size()));
        out.push_back(v);
      }
    }
  }
  return out;
}

std::vector<CubeVertex> cylinder_vertices(int sides, std::vector<std::uint16_t>& indices) {
  std::vector<CubeVertex> out;
  indices.clear();
  const auto vertex = [&](float x, float y, float z, float nx, float ny, float nz) {
    out.push_back(CubeVertex{{x, y, z}, {nx, ny, nz}});
    return static_cast<std::uint16_t>(out.size() - 1);
  };
  const auto ring = [&](int k) {
    const double angle = 2.0 * 3.14159265358979323846 * k / sides;
    return std::array<float, 2>{static_cast<float>(std::cos(angle)),
                                static_cast<float>(std::sin(angle))};
  };
  // The side: a quad per face, its edges' normals along the radius.
  for (int k = 0; k < sides; ++k) {
    const auto [c0, s0] = ring(k);
    const auto [c1, s1] = ring(k + 1);
    const std::uint16_t b0 = vertex(0.5f * c0, -0.5f, 0.5f * s0, c0, 0.0f, s0);
    const std::uint16_t t0 = vertex(0.5f * c0, 0.5f, 0.5f * s0, c0, 0.0f, s0);
    const std::uint16_t b1 = vertex(0.5f * c1, -0.5f, 0.5f * s1, c1, 0.0f, s1);
    const std::uint16_t t1 = vertex(0.5f * c1, 0.5f, 0.5f * s1, c1, 0.0f, s1);
    // Going round from +x towards +z is clockwise seen from outside (from +x looking in, +z is on
    // the left): wind b0, t0, t1 and b0, t1, b1.
    for (const std::uint16_t i : {b0, t0, t1, b0, t1, b1}) indices.push_back(i);
  }
  // The caps: a fan about each centre.
  for (const float side : {-1.0f, 1.0f}) {
    const std::uint16_t centre = vertex(0.0f, 0.5f * side, 0.0f, 0.0f, side, 0.0f);
    for (int k = 0; k < sides; ++k) {
      const auto [c0, s0] = ring(k);
      const auto [c1, s1] = ring(k + 1);
      const std::uint16_t a = vertex(0.5f * c0, 0.5f * side, 0.5f * s0, 0.0f, side, 0.0f);
      const std::uint16_t b = vertex(0.5f * c1, 0.5f * side, 0.5f * s1, 0.0f, side, 0.0f);
      // Seen from above (+y), +x towards +z turns clockwise: the top winds centre, b, a.
      for (const std::uint16_t i : side > 0.0f ? std::array<std::uint16_t, 3>{centre, b, a}
                                               : std::array<std::uint16_t, 3>{centre, a, b}) {
        indices.push_back(i);
      }
    }
  }
  return out;
}

}  // namespace tumble::render
