#include "render/box_batch.hpp"

#include <cstddef>
#include <utility>

#include "render/box_instances.hpp"
#include "render/geometry.hpp"

namespace tumble::render {
namespace {

constexpr GLsizei kCubeIndices = 36;  // two triangles per face

// Per box, advancing once per instance, at body.vert's locations. A matrix takes one location
// per column.
void point_instance_attributes() {
  const auto attribute = [](GLuint location, GLint components, std::size_t offset) {
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, sizeof(BoxInstance),
                          reinterpret_cast<const void*>(offset));
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
}

}  // namespace

BoxBatch BoxBatch::create() {
  BoxBatch out;
  // Positions and normals interleaved, four vertices per face.
  const std::vector<CubeVertex> vertices = cube_vertices();
  std::vector<GLushort> indices;
  for (GLushort face = 0; face < 6; ++face) {
    const GLushort base = face * 4;
    for (const GLushort corner : {0, 1, 2, 0, 2, 3}) indices.push_back(base + corner);
  }
  glGenVertexArrays(1, &out.vao_);
  glBindVertexArray(out.vao_);
  glGenBuffers(1, &out.cube_vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, out.cube_vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(CubeVertex)),
               vertices.data(), GL_STATIC_DRAW);
  glGenBuffers(1, &out.cube_ebo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, out.cube_ebo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLushort)),
               indices.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(CubeVertex), nullptr);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(CubeVertex),
                        reinterpret_cast<const void*>(offsetof(CubeVertex, normal)));
  glEnableVertexAttribArray(1);
  glGenBuffers(1, &out.instance_vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, out.instance_vbo_);
  point_instance_attributes();
  glBindVertexArray(0);
  return out;
}

BoxBatch::~BoxBatch() {
  if (vao_ == 0) return;
  glDeleteVertexArrays(1, &vao_);
  const GLuint buffers[] = {cube_vbo_, cube_ebo_, instance_vbo_};
  glDeleteBuffers(3, buffers);
}

BoxBatch::BoxBatch(BoxBatch&& other) noexcept
    : vao_(std::exchange(other.vao_, 0)),
      cube_vbo_(std::exchange(other.cube_vbo_, 0)),
      cube_ebo_(std::exchange(other.cube_ebo_, 0)),
      instance_vbo_(std::exchange(other.instance_vbo_, 0)),
      count_(std::exchange(other.count_, 0)) {}

BoxBatch& BoxBatch::operator=(BoxBatch&& other) noexcept {
  std::swap(vao_, other.vao_);
  std::swap(cube_vbo_, other.cube_vbo_);
  std::swap(cube_ebo_, other.cube_ebo_);
  std::swap(instance_vbo_, other.instance_vbo_);
  std::swap(count_, other.count_);
  return *this;
}

void BoxBatch::upload(const std::vector<Box>& boxes, const Vec3& eye) {
  const std::vector<BoxInstance> instances = box_instances(boxes, eye);
  count_ = static_cast<GLsizei>(instances.size());
  glBindBuffer(GL_ARRAY_BUFFER, instance_vbo_);
  // A fresh store each frame, so the driver need not wait for the last frame's draws.
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances.size() * sizeof(BoxInstance)),
               instances.data(), GL_STREAM_DRAW);
}

void BoxBatch::draw() const {
  if (count_ == 0) return;
  glBindVertexArray(vao_);
  glDrawElementsInstanced(GL_TRIANGLES, kCubeIndices, GL_UNSIGNED_SHORT, nullptr, count_);
}

}  // namespace tumble::render
