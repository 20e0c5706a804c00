// The name of a GL object (0 for none) as a member of the class that owns the object: a move takes
// the name with it and leaves 0 behind, and a move assignment swaps, so that the names moved over
// are freed by the destructor of the object they came from. A class owning GL objects holds them
// as GlNames, defaults its moves and frees them in its destructor (BoxBatch, Framebuffer).
#pragma once

#include <utility>

#include "render/gl.hpp"

namespace tumble::render {

class GlName {
 public:
  GlName() = default;
  GlName(GlName&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlName& operator=(GlName&& other) noexcept {
    std::swap(name_, other.name_);
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;

  GLuint get() const { return name_; }
  GLuint* out() { return &name_; }  // for glGen*: where the new name goes

 private:
  GLuint name_ = 0;
};

}  // namespace tumble::render
