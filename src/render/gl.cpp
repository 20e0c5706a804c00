#include "render/gl.hpp"

namespace tumble::render {

#define TUMBLE_GL_DEFINE(type, name) type name = nullptr;
TUMBLE_GL_FUNCTIONS(TUMBLE_GL_DEFINE)
#undef TUMBLE_GL_DEFINE

Result<void> load_gl_functions(GlProcLoader loader) {
#define TUMBLE_GL_LOAD(type, name)              \
  name = reinterpret_cast<type>(loader(#name)); \
  if (!name) return Error{#name};
  TUMBLE_GL_FUNCTIONS(TUMBLE_GL_LOAD)
#undef TUMBLE_GL_LOAD
  return Result<void>::success();
}

std::string gl_description() {
  const auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
  };
  return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

}  // namespace tumble::render
