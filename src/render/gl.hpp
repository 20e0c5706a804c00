// The OpenGL 3.3 core API as the renderer calls it: the types and enums of Khronos' glcorearb.h,
// and each entry point as a pointer in this namespace, loaded from whichever off-screen back end
// made the context (OSMesaGetProcAddress, eglGetProcAddress). OSMesa's and EGL's libraries both
// export the GL functions under the same names, so a binary that can use either must not call
// them by name; and since glcorearb.h declares no prototypes here, a function missing from the
// list below does not compile. Include this header, not GL/gl.h (glcorearb.h must not meet it).
#pragma once

#include <GL/glcorearb.h>

// GL_MESA_pack_invert (Mesa's; not a core enum): glReadPixels gives rows top first.
#define GL_PACK_INVERT_MESA 0x8758

namespace tumble::render {

// Every entry point the renderer uses (add one here before calling it).
#define TUMBLE_GL_FUNCTIONS(X)                                                 \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                                   \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                     \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                         \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                               \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                             \
  X(PFNGLBINDSAMPLERPROC, glBindSampler)                                       \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                                       \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                               \
  X(PFNGLBLENDEQUATIONPROC, glBlendEquation)                                   \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                           \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)                           \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                               \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                         \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                                   \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)                 \
  X(PFNGLCLEARPROC, glClear)                                                   \
  X(PFNGLCLEARCOLORPROC, glClearColor)                                         \
  X(PFNGLCOLORMASKPROC, glColorMask)                                           \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                                   \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                   \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                     \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                         \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                   \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                       \
  X(PFNGLDELETESAMPLERSPROC, glDeleteSamplers)                                 \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                     \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                         \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                           \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                           \
  X(PFNGLDISABLEPROC, glDisable)                                               \
  X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, glDisableVertexAttribArray)             \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                         \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, glDrawArraysInstanced)                       \
  X(PFNGLDRAWBUFFERPROC, glDrawBuffer)                                         \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                                     \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, glDrawElementsInstanced)                   \
  X(PFNGLENABLEPROC, glEnable)                                                 \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)               \
  X(PFNGLFINISHPROC, glFinish)                                                 \
  X(PFNGLFLUSHPROC, glFlush)                                                   \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)               \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)                     \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                         \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                               \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                             \
  X(PFNGLGENSAMPLERSPROC, glGenSamplers)                                       \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                                       \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                               \
  X(PFNGLGETERRORPROC, glGetError)                                             \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                           \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                     \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                             \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                       \
  X(PFNGLGETSTRINGPROC, glGetString)                                           \
  X(PFNGLGETSTRINGIPROC, glGetStringi)                                         \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                         \
  X(PFNGLLINEWIDTHPROC, glLineWidth)                                           \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                       \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                       \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                                   \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                                         \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                         \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)                       \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, glRenderbufferStorageMultisample) \
  X(PFNGLSAMPLERPARAMETERIPROC, glSamplerParameteri)                           \
  X(PFNGLSCISSORPROC, glScissor)                                               \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                     \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                                         \
  X(PFNGLTEXPARAMETERFPROC, glTexParameterf)                                   \
  X(PFNGLTEXPARAMETERFVPROC, glTexParameterfv)                                 \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                                   \
  X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                                   \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                                           \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                           \
  X(PFNGLUNIFORM2FPROC, glUniform2f)                                           \
  X(PFNGLUNIFORM2FVPROC, glUniform2fv)                                         \
  X(PFNGLUNIFORM3FPROC, glUniform3f)                                           \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                         \
  X(PFNGLUNIFORM4FPROC, glUniform4f)                                           \
  X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                         \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                             \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                         \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor)                       \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                       \
  X(PFNGLVIEWPORTPROC, glViewport)

#define TUMBLE_GL_DECLARE(type, name) extern type name;
TUMBLE_GL_FUNCTIONS(TUMBLE_GL_DECLARE)
#undef TUMBLE_GL_DECLARE

}  // namespace tumble::render

#include "render/gl_loader.hpp"
