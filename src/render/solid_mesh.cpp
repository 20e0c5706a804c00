#include "render/solid_mesh.hpp"

#include <algorithm>

#include "render/geometry.hpp"

namespace tumble::render {
namespace {

// A unit mesh (in the unit box) stretched to `size`: the normals of a surface scaled by S turn by
// S⁻¹ (the inverse transpose of a diagonal matrix), then are made unit again.
SolidMesh scaled(const std::vector<CubeVertex>& vertices, const std::vector<std::uint16_t>& indices,
                 const Vec3& size) {
  SolidMesh out;
  const Eigen::Vector3f scale = size.cast<float>();
  for (const CubeVertex& vertex : vertices) {
    out.positions.push_back(Eigen::Vector3f(vertex.position).cwiseProduct(scale));
    out.normals.push_back(Eigen::Vector3f(vertex.normal).cwiseQuotient(scale).normalized());
  }
  out.triangles.assign(indices.begin(), indices.end());
  return out;
}

// capsule_vertices as capsule.glsl places them: the sphere's point times the diameter, moved
// along y by the half length to its half's side; its normal the sphere's (the vertex's `normal`
// slot holds its half's way along y instead).
SolidMesh capsule(const Vec3& size) {
  std::vector<std::uint16_t> indices;
  const std::vector<CubeVertex> vertices = capsule_vertices(kBallDivisions, indices);
  const float radius = 0.5f * static_cast<float>(size.x());
  const float half_length = std::max(0.5f * static_cast<float>(size.y()) - radius, 0.0f);
  SolidMesh out;
  for (const CubeVertex& vertex : vertices) {
    const Eigen::Vector3f on_sphere(vertex.position);
    out.positions.push_back(2.0f * radius * on_sphere +
                            Eigen::Vector3f(0.0f, vertex.normal[1] * half_length, 0.0f));
    out.normals.push_back(on_sphere.normalized());
  }
  out.triangles.assign(indices.begin(), indices.end());
  return out;
}

// hull_vertices: positions in the unit box scaled back to the hull's corners, each face's own
// normal (already of the hull at its size).
SolidMesh hull(const HullMesh& mesh, const Vec3& size) {
  std::vector<std::uint16_t> indices;
  const std::vector<HullVertex> vertices = hull_vertices(mesh, size, indices);
  SolidMesh out;
  const Eigen::Vector3f scale = size.cast<float>();
  for (const HullVertex& vertex : vertices) {
    out.positions.push_back(Eigen::Vector3f(vertex.position).cwiseProduct(scale));
    out.normals.push_back(Eigen::Vector3f(vertex.normal).normalized());
  }
  out.triangles.assign(indices.begin(), indices.end());
  return out;
}

}  // namespace

SolidMesh solid_mesh(Solid solid, const Vec3& size, const HullMesh* hull_mesh) {
  std::vector<std::uint16_t> indices;
  switch (solid) {
    case Solid::ball: {
      const std::vector<CubeVertex> vertices = sphere_vertices(kBallDivisions, indices);
      return scaled(vertices, indices, size);
    }
    case Solid::capsule:
      return capsule(size);
    case Solid::cylinder: {
      const std::vector<CubeVertex> vertices = cylinder_vertices(kCylinderSides, indices);
      return scaled(vertices, indices, size);
    }
    case Solid::hull:
      if (hull_mesh) return hull(*hull_mesh, size);
      break;
    case Solid::box:
      break;
  }
  return scaled(cube_vertices(), cube_indices(), size);
}

SolidMesh quad_mesh(double width, double depth) {
  SolidMesh out;
  const Eigen::Vector3f half(static_cast<float>(0.5 * width), 1.0f,
                             static_cast<float>(0.5 * depth));
  for (const auto& corner : kUnitSquare) {
    out.positions.push_back(Eigen::Vector3f(corner).cwiseProduct(half));
    out.normals.push_back(Eigen::Vector3f::UnitY());
  }
  // kUnitSquare is a triangle strip: (0, 2, 1) and (1, 2, 3) turn counter-clockwise seen from +y.
  out.triangles = {0, 2, 1, 1, 2, 3};
  return out;
}

}  // namespace tumble::render
