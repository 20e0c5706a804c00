#include "render/box_batch.hpp"

#include <algorithm>
#include <cstddef>

#include "render/box_instances.hpp"
#include "render/geometry.hpp"

namespace tumble::render {
namespace {

// Per box, advancing once per instance, at body.vert's locations, from instance `first` of the
// bound buffer on. A matrix takes one location per column.
void point_instance_attributes(GLsizei first = 0) {
  const auto attribute = [first](GLuint location, GLint components, std::size_t offset) {
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, sizeof(BoxInstance),
                          reinterpret_cast<const void*>(
                              static_cast<std::size_t>(first) * sizeof(BoxInstance) + offset));
    glVertexAttribDivisor(location, 1);
    glEnableVertexAttribArray(location);
  };
  for (GLuint column = 0; column < 4; ++column) {
    attribute(2 + column, 4, offsetof(BoxInstance, model) + column * 4 * sizeof(float));
  }
  for (GLuint column = 0; column < 3; ++column) {
    attribute(6 + column, 3, offsetof(BoxInstance, rotation) + column * 3 * sizeof(float));
  }
  attribute(9, 3, offsetof(BoxInstance, size));
  attribute(10, 3, offsetof(BoxInstance, albedo));
  attribute(12, 4, offsetof(BoxInstance, occluders));  // 11 is a hull vertex's edge
}

}  // namespace

BoxBatch BoxBatch::create(Solid solid) {
  BoxBatch out;
  out.solid_ = solid;
  // Positions and normals interleaved: the cube four vertices per face, or the round solid.
  std::vector<GLushort> indices;
  std::vector<CubeVertex> vertices;
  if (solid == Solid::ball) {
    vertices = sphere_vertices(kBallDivisions, indices);
  } else if (solid == Solid::capsule) {
    vertices = capsule_vertices(kBallDivisions, indices);
  } else if (solid == Solid::cylinder) {
    vertices = cylinder_vertices(kCylinderSides, indices);
  } else {
    vertices = cube_vertices();
    indices = cube_indices();
  }
  out.set_up(vertices, indices,
             {{0, offsetof(CubeVertex, position)}, {1, offsetof(CubeVertex, normal)}});
  return out;
}

BoxBatch BoxBatch::create_hull(const HullMesh& mesh, const Vec3& size, std::uint32_t index) {
  BoxBatch out;
  out.solid_ = Solid::hull;
  out.mesh_ = index;
  std::vector<GLushort> indices;
  const std::vector<HullVertex> vertices = hull_vertices(mesh, size, indices);
  // The edge attribute past the instance attributes (2 to 10).
  out.set_up(vertices, indices,
             {{0, offsetof(HullVertex, position)},
              {1, offsetof(HullVertex, normal)},
              {11, offsetof(HullVertex, edge)}});
  return out;
}

template <class Vertex>
void BoxBatch::set_up(const std::vector<Vertex>& vertices, const std::vector<GLushort>& indices,
                      std::initializer_list<std::pair<GLuint, std::size_t>> attributes) {
  indices_ = static_cast<GLsizei>(indices.size());
  glGenVertexArrays(1, vao_.out());
  glBindVertexArray(vao_.get());
  glGenBuffers(1, cube_vbo_.out());
  glBindBuffer(GL_ARRAY_BUFFER, cube_vbo_.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
  glGenBuffers(1, cube_ebo_.out());
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, cube_ebo_.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLushort)),
               indices.data(), GL_STATIC_DRAW);
  // Each per-vertex attribute: three floats at its offset in Vertex.
  for (const auto& [location, offset] : attributes) {
    glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offset));
    glEnableVertexAttribArray(location);
  }
  glGenBuffers(1, instance_vbo_.out());
  glBindBuffer(GL_ARRAY_BUFFER, instance_vbo_.get());
  point_instance_attributes();
  glBindVertexArray(0);
}

BoxBatch::~BoxBatch() {
  const GLuint vao = vao_.get();
  if (vao == 0) return;
  glDeleteVertexArrays(1, &vao);
  const GLuint buffers[] = {cube_vbo_.get(), cube_ebo_.get(), instance_vbo_.get()};
  glDeleteBuffers(3, buffers);
}

void BoxBatch::upload(const std::vector<Box>& boxes, const Vec3& eye,
                      const std::vector<std::array<int, kOccludersPerBody>>* occluders) {
  const std::vector<BoxInstance> instances = box_instances(boxes, eye, solid_, mesh_, occluders);
  count_ = static_cast<GLsizei>(instances.size());
  // box_instances() puts the boxes that receive no occlusion first.
  unoccluded_ = static_cast<GLsizei>(
      std::find_if(instances.begin(), instances.end(),
                   [](const BoxInstance& box) { return box.occluders[0] > 0.0f; }) -
      instances.begin());
  glBindBuffer(GL_ARRAY_BUFFER, instance_vbo_.get());
  // A fresh store each frame, so the driver need not wait for the last frame's draws.
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances.size() * sizeof(BoxInstance)),
               instances.data(), GL_STREAM_DRAW);
}

void BoxBatch::draw() const {
  if (count_ == 0) return;
  glBindVertexArray(vao_.get());
  glDrawElementsInstanced(GL_TRIANGLES, indices_, GL_UNSIGNED_SHORT, nullptr, count_);
}

void BoxBatch::draw_part(bool occluded) const {
  const GLsizei first = occluded ? unoccluded_ : 0;
  const GLsizei count = occluded ? count_ - unoccluded_ : unoccluded_;
  if (count == 0) return;
  glBindVertexArray(vao_.get());
  if (first != 0) {
    glBindBuffer(GL_ARRAY_BUFFER, instance_vbo_.get());
    point_instance_attributes(first);
  }
  glDrawElementsInstanced(GL_TRIANGLES, indices_, GL_UNSIGNED_SHORT, nullptr, count);
  if (first != 0) point_instance_attributes(0);
}

}  // namespace tumble::render
