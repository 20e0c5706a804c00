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

// The files read and concatenated, or the one that cannot be read.
Result<std::string> read_sources(const std::string& directory,
                                 const std::vector<std::string>& files) {
  std::string source;
  for (const std::string& name : files) {
    const std::string path = directory + "/" + name;
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{path + ": cannot open shader file"};
    std::ostringstream text;
    text << in.rdbuf();
    source += text.str();
    source += '\n';
  }
  return source;
}

Result<GLuint> compile(GLenum stage, const std::string& source, const std::string& label) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(shader, false);
    glDeleteShader(shader);
    return Error{label + ": shader compilation failed:\n" + log};
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

Result<ShaderProgram> ShaderProgram::build(const std::string& directory,
                                           const std::vector<std::string>& vertex_files,
                                           const std::vector<std::string>& fragment_files) {
  const Result<std::string> vertex_source = read_sources(directory, vertex_files);
  if (!vertex_source) return Error{vertex_source.error()};
  const Result<std::string> fragment_source = read_sources(directory, fragment_files);
  if (!fragment_source) return Error{fragment_source.error()};
  const std::string vertex_label = directory + "/" + join(vertex_files);
  const std::string fragment_label = directory + "/" + join(fragment_files);
  const Result<GLuint> vertex = compile(GL_VERTEX_SHADER, *vertex_source, vertex_label);
  if (!vertex) return Error{vertex.error()};
  const Result<GLuint> fragment = compile(GL_FRAGMENT_SHADER, *fragment_source, fragment_label);
  if (!fragment) {
    glDeleteShader(*vertex);
    return Error{fragment.error()};
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, *vertex);
  glAttachShader(program, *fragment);
  glLinkProgram(program);
  glDeleteShader(*vertex);
  glDeleteShader(*fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(program, true);
    glDeleteProgram(program);
    return Error{vertex_label + ", " + fragment_label + ": shader link failed:\n" + log};
  }
  return ShaderProgram(program);
}

}  // namespace tumble::render
