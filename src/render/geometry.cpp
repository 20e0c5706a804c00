#include "render/geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace tumble::render {

Eigen::Vector3f linear_from_srgb(const Color& srgb) {
  Eigen::Vector3f out;
  for (int i = 0; i < 3; ++i) {
    const double c = std::clamp(srgb[i], 0.0, 1.0);
    out[i] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
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

}  // namespace tumble::render
