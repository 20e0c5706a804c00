// Every box of a frame that is one Solid as one instanced draw: the solid's mesh (the unit cube,
// or the round solid inside it), set up once, and one record per box (box_instances.hpp) uploaded
// in one buffer per frame. Both passes that draw them (the shadow map and the lit solids) draw the
// same upload. Internal to src/render/; needs a current GL context from create() to destruction.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <utility>
#include <vector>

#include "render/frame.hpp"
#include "render/gl.hpp"
#include "render/gl_name.hpp"
#include "render/occluders.hpp"

namespace tumble::render {

class BoxBatch {
 public:
  BoxBatch() = default;  // no GL objects: for a renderer whose set-up failed
  static BoxBatch create(Solid solid);
  // The batch of the hull `mesh` (its index among RenderSettings::hulls), drawn in a box of
  // `size` (m).
  static BoxBatch create_hull(const HullMesh& mesh, const Vec3& size, std::uint32_t index);
  ~BoxBatch();
  BoxBatch(BoxBatch&& other) noexcept = default;
  BoxBatch& operator=(BoxBatch&& other) noexcept = default;
  BoxBatch(const BoxBatch&) = delete;
  BoxBatch& operator=(const BoxBatch&) = delete;

  // Replaces the boxes drawn by draw() with those of `boxes` that are this batch's solid, nearest
  // to `eye` (world frame, m) first, each with its occluders when given (box_instances()).
  void upload(const std::vector<Box>& boxes, const Vec3& eye,
              const std::vector<std::array<int, kOccludersPerBody>>* occluders = nullptr);
  // One draw of every uploaded box with the bound program, which reads body.vert's attribute
  // locations (or a subset of them, as box_shadow.vert).
  void draw() const;
  // One draw of the uploaded boxes that receive occlusion from others (`occluded`) or of those
  // that receive none: a program that computes occlusion costs every pixel it shades on a
  // software rasterizer, whether or not the box has anything near it.
  void draw_part(bool occluded) const;

 private:
  // The mesh's buffers and vertex layout, and the instance buffer, into a new vertex array.
  template <class Vertex>
  void set_up(const std::vector<Vertex>& vertices, const std::vector<GLushort>& indices,
              std::initializer_list<std::pair<GLuint, std::size_t>> attributes);

  GlName vao_, cube_vbo_, cube_ebo_, instance_vbo_;
  Solid solid_ = Solid::box;
  std::uint32_t mesh_ = 0;  // Solid::hull's
  GLsizei indices_ = 0;     // of the mesh
  GLsizei count_ = 0;       // boxes uploaded
  GLsizei unoccluded_ = 0;  // of them, first, those that receive no occlusion
};

}  // namespace tumble::render
