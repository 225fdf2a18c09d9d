// GL entry points for the project's own host programs (tests, benchmark, demo), loaded at run time
// through any get_proc_address (sss_headless_get_proc_address, glfwGetProcAddress). Not part of the
// library, which has its own private table. Each pointer has the PFNGL...PROC type of
// <GL/glcorearb.h> and lives in namespace host_gl, so it cannot clash with a GL library's symbols.
#pragma once

#include <GL/glcorearb.h>

#include <string>

// X(type, name): every GL function the host programs call.
#define HOST_GL_FUNCTIONS(X)                                     \
  X(PFNGLGETSTRINGPROC, glGetString)                             \
  X(PFNGLGETSTRINGIPROC, glGetStringi)                           \
  X(PFNGLGETERRORPROC, glGetError)                               \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                         \
  X(PFNGLGETBOOLEANVPROC, glGetBooleanv)                         \
  X(PFNGLGETFLOATVPROC, glGetFloatv)                             \
  X(PFNGLISENABLEDPROC, glIsEnabled)                             \
  X(PFNGLFINISHPROC, glFinish)                                   \
  X(PFNGLFLUSHPROC, glFlush)                                     \
  X(PFNGLVIEWPORTPROC, glViewport)                               \
  X(PFNGLSCISSORPROC, glScissor)                                 \
  X(PFNGLCLEARPROC, glClear)                                     \
  X(PFNGLCLEARCOLORPROC, glClearColor)                           \
  X(PFNGLCLEARDEPTHPROC, glClearDepth)                           \
  X(PFNGLCLEARSTENCILPROC, glClearStencil)                       \
  X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                     \
  X(PFNGLCLEARBUFFERIVPROC, glClearBufferiv)                     \
  X(PFNGLCLEARBUFFERUIVPROC, glClearBufferuiv)                   \
  X(PFNGLENABLEPROC, glEnable)                                   \
  X(PFNGLDISABLEPROC, glDisable)                                 \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                             \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                             \
  X(PFNGLDEPTHRANGEFPROC, glDepthRangef)                         \
  X(PFNGLCOLORMASKPROC, glColorMask)                             \
  X(PFNGLCULLFACEPROC, glCullFace)                               \
  X(PFNGLFRONTFACEPROC, glFrontFace)                             \
  X(PFNGLPOLYGONMODEPROC, glPolygonMode)                         \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                     \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                             \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)             \
  X(PFNGLBLENDEQUATIONSEPARATEPROC, glBlendEquationSeparate)     \
  X(PFNGLSTENCILFUNCPROC, glStencilFunc)                         \
  X(PFNGLSTENCILOPPROC, glStencilOp)                             \
  X(PFNGLSTENCILMASKPROC, glStencilMask)                         \
  X(PFNGLSTENCILFUNCSEPARATEPROC, glStencilFuncSeparate)         \
  X(PFNGLSTENCILOPSEPARATEPROC, glStencilOpSeparate)             \
  X(PFNGLSTENCILMASKSEPARATEPROC, glStencilMaskSeparate)         \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                         \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                           \
  X(PFNGLREADPIXELSPROC, glReadPixels)                           \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                         \
  X(PFNGLCLAMPCOLORPROC, glClampColor)                           \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                         \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                   \
  X(PFNGLISTEXTUREPROC, glIsTexture)                             \
  X(PFNGLISBUFFERPROC, glIsBuffer)                               \
  X(PFNGLISFRAMEBUFFERPROC, glIsFramebuffer)                     \
  X(PFNGLISVERTEXARRAYPROC, glIsVertexArray)                     \
  X(PFNGLISPROGRAMPROC, glIsProgram)                             \
  X(PFNGLISSHADERPROC, glIsShader)                               \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                         \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                     \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                           \
  X(PFNGLTEXIMAGE2DMULTISAMPLEPROC, glTexImage2DMultisample)     \
  X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                     \
  X(PFNGLGETTEXIMAGEPROC, glGetTexImage)                         \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                     \
  X(PFNGLGENERATEMIPMAPPROC, glGenerateMipmap)                   \
  X(PFNGLGETTEXPARAMETERIVPROC, glGetTexParameteriv)             \
  X(PFNGLGENSAMPLERSPROC, glGenSamplers)                         \
  X(PFNGLDELETESAMPLERSPROC, glDeleteSamplers)                   \
  X(PFNGLBINDSAMPLERPROC, glBindSampler)                         \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                 \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)           \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                 \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)       \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)   \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                 \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)               \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)         \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)               \
  X(PFNGLISRENDERBUFFERPROC, glIsRenderbuffer)                   \
  X(PFNGLGETRENDERBUFFERPARAMETERIVPROC, glGetRenderbufferParameteriv) \
  X(PFNGLGETBUFFERPARAMETERIVPROC, glGetBufferParameteriv)       \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)           \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                 \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                           \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                     \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                           \
  X(PFNGLBUFFERDATAPROC, glBufferData)                           \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)         \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray) \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                           \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                       \
  X(PFNGLCREATESHADERPROC, glCreateShader)                       \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                     \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                         \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)               \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                       \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                     \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                       \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)             \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                     \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                           \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)           \
  X(PFNGLGETACTIVEUNIFORMPROC, glGetActiveUniform)               \
  X(PFNGLGETACTIVEUNIFORMSIVPROC, glGetActiveUniformsiv)         \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                             \
  X(PFNGLUNIFORM1UIPROC, glUniform1ui)                           \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                             \
  X(PFNGLUNIFORM2FPROC, glUniform2f)                             \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                           \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)              \
  X(PFNGLDEBUGMESSAGECALLBACKPROC, glDebugMessageCallback)      \
  X(PFNGLGETOBJECTLABELPROC, glGetObjectLabel)                  \
  X(PFNGLENABLEIPROC, glEnablei)                                 \
  X(PFNGLDISABLEIPROC, glDisablei)                               \
  X(PFNGLBLENDCOLORPROC, glBlendColor)                           \
  X(PFNGLBLENDEQUATIONPROC, glBlendEquation)                     \
  X(PFNGLUNIFORM4FPROC, glUniform4f)                             \
  X(PFNGLUNIFORM4FVPROC, glUniform4fv)                           \
  X(PFNGLUNIFORM1FVPROC, glUniform1fv)                           \
  X(PFNGLUNIFORM2FVPROC, glUniform2fv)                           \
  X(PFNGLUNIFORM2IPROC, glUniform2i)                             \
  X(PFNGLSAMPLERPARAMETERIPROC, glSamplerParameteri)             \
  X(PFNGLGENQUERIESPROC, glGenQueries)                           \
  X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                     \
  X(PFNGLBEGINQUERYPROC, glBeginQuery)                           \
  X(PFNGLENDQUERYPROC, glEndQuery)                               \
  X(PFNGLGETQUERYOBJECTUI64VPROC, glGetQueryObjectui64v)        \
  X(PFNGLGETQUERYOBJECTUIVPROC, glGetQueryObjectuiv)             \
  X(PFNGLGETQUERYIVPROC, glGetQueryiv)                           \
  X(PFNGLGETINTEGERI_VPROC, glGetIntegeri_v)                     \
  X(PFNGLGETINTEGER64I_VPROC, glGetInteger64i_v)                 \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                   \
  X(PFNGLBINDBUFFERRANGEPROC, glBindBufferRange)                 \
  X(PFNGLGETBOOLEANI_VPROC, glGetBooleani_v)                     \
  X(PFNGLBINDIMAGETEXTUREPROC, glBindImageTexture)               \
  X(PFNGLDISPATCHCOMPUTEPROC, glDispatchCompute)                 \
  X(PFNGLMEMORYBARRIERPROC, glMemoryBarrier)                     \
  X(PFNGLSAMPLEMASKIPROC, glSampleMaski)                         \
  X(PFNGLTEXSTORAGE2DMULTISAMPLEPROC, glTexStorage2DMultisample) \
  X(PFNGLGETTEXLEVELPARAMETERIVPROC, glGetTexLevelParameteriv)

namespace host_gl {

#define HOST_GL_DECLARE(type, name) extern type name;
HOST_GL_FUNCTIONS(HOST_GL_DECLARE)
#undef HOST_GL_DECLARE

// Loader callback with the signature of sss_headless_get_proc_address.
using GetProcAddressFn = void *(*)(const char *name, void *user);

// Loads every function of the list (call again after switching to another context's loader).
// Returns false and names the missing ones in *missing.
bool load(GetProcAddressFn get_proc_address, void *user, std::string *missing);

}  // namespace host_gl
