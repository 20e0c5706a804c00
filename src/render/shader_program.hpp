// GLSL programs built from files in shaders/.
#pragma once

#include <string>
#include <vector>

#include "common/result.hpp"
#include "render/gl.hpp"

namespace tumble::render {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  // Compiles and links. Each stage is the concatenation of its files, in order (so a shared
  // file can come first). An error gives the file names and the compiler's or linker's log.
  static Result<ShaderProgram> build(const std::string& directory,
                                     const std::vector<std::string>& vertex_files,
                                     const std::vector<std::string>& fragment_files);

  GLuint id() const { return id_; }
  bool valid() const { return id_ != 0; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  explicit ShaderProgram(GLuint id) : id_(id) {}
  GLuint id_ = 0;
};

}  // namespace tumble::render
