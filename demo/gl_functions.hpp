// GL entry points used by the demo, loaded at run time through sss_headless_get_proc_address.
// No loader library: each pointer has the PFNGL...PROC type of <GL/glcorearb.h>. The pointers live
// in namespace demo so that their names cannot clash with the symbols of a GL library.
#pragma once

#include <GL/glcorearb.h>

#include <string>

// X(type, name): every GL function the demo calls.
#define DEMO_GL_FUNCTIONS(X)                                              \
  X(PFNGLGETSTRINGPROC, glGetString)                                      \
  X(PFNGLGETERRORPROC, glGetError)                                        \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                  \
  X(PFNGLFINISHPROC, glFinish)                                            \
  X(PFNGLVIEWPORTPROC, glViewport)                                        \
  X(PFNGLCLEARPROC, glClear)                                              \
  X(PFNGLCLEARCOLORPROC, glClearColor)                                    \
  X(PFNGLCLEARDEPTHPROC, glClearDepth)                                    \
  X(PFNGLCLEARSTENCILPROC, glClearStencil)                                \
  X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                              \
  X(PFNGLENABLEPROC, glEnable)                                            \
  X(PFNGLDISABLEPROC, glDisable)                                          \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                      \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                      \
  X(PFNGLCULLFACEPROC, glCullFace)                                        \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                              \
  X(PFNGLSTENCILFUNCPROC, glStencilFunc)                                  \
  X(PFNGLSTENCILOPPROC, glStencilOp)                                      \
  X(PFNGLSTENCILMASKPROC, glStencilMask)                                  \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                                  \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                                    \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                    \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                  \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                                  \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                            \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                                  \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                              \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                                    \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                              \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                          \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                    \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                          \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)                \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)            \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                          \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                          \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                    \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                          \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                    \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                              \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                    \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                    \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                  \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)          \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                    \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                                \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                              \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                  \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                        \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                              \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                  \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                      \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                              \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                    \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                    \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                      \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                                      \
  X(PFNGLUNIFORM2FPROC, glUniform2f)                                      \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                    \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)

namespace demo {

#define DEMO_GL_DECLARE(type, name) extern type name;
DEMO_GL_FUNCTIONS(DEMO_GL_DECLARE)
#undef DEMO_GL_DECLARE

// Loader callback with the signature of sss_headless_get_proc_address.
using GetProcAddressFn = void *(*)(const char *name, void *user);

// Loads every function of the list. Returns false and names the missing ones in *missing.
bool load_gl_functions(GetProcAddressFn get_proc_address, void *user, std::string *missing);

}  // namespace demo
