#include "render/shader_program.hpp"

#include <fstream>
#include <sstream>
#include <utility>

namespace tumble::render {
namespace {

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  if (is_program) {
    glGetProgramInfoLog(object, length, nullptr, log.data());
  } else {
    glGetShaderInfoLog(object, length, nullptr, log.data());
  }
  return log.c_str();
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : " + ") + name;
  return out;
}

// Reads and concatenates the files; returns false and sets `error` if one cannot be read.
bool read_sources(const std::string& directory, const std::vector<std::string>& files,
                  std::string& source, std::string& error) {
  for (const std::string& name : files) {
    const std::string path = directory + "/" + name;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      error = path + ": cannot open shader file";
      return false;
    }
    std::ostringstream text;
    text << in.rdbuf();
    source += text.str();
    source += '\n';
  }
  return true;
}

GLuint compile(GLenum stage, const std::string& source, const std::string& label,
               std::string& error) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    error = label + ": shader compilation failed:\n" + info_log(shader, false);
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

ShaderProgram::~ShaderProgram() {
  if (id_) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

ShaderProgram ShaderProgram::build(const std::string& directory,
                                   const std::vector<std::string>& vertex_files,
                                   const std::vector<std::string>& fragment_files,
                                   std::string& error) {
  std::string vertex_source;
  std::string fragment_source;
  if (!read_sources(directory, vertex_files, vertex_source, error) ||
      !read_sources(directory, fragment_files, fragment_source, error)) {
    return {};
  }
  const std::string vertex_label = directory + "/" + join(vertex_files);
  const std::string fragment_label = directory + "/" + join(fragment_files);
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source, vertex_label, error);
  if (!vertex) return {};
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_source, fragment_label, error);
  if (!fragment) {
    glDeleteShader(vertex);
    return {};
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    error =
        vertex_label + ", " + fragment_label + ": shader link failed:\n" + info_log(program, true);
    glDeleteProgram(program);
    return {};
  }
  return ShaderProgram(program);
}

}  // namespace tumble::render
