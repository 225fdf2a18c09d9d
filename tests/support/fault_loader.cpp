#include "fault_loader.hpp"

#include <GL/glcorearb.h>

#include <cstring>

#include "sss_headless.h"

namespace sss_test {

namespace {

Faults g_faults;
GLenum g_pending_error = GL_NO_ERROR;  // returned by the next glGetError before the driver's

// The driver's functions, as the last fault_get_proc_address call found them (one backend per
// process, and Mesa's entry points do not depend on the context).
PFNGLSHADERSOURCEPROC real_shader_source = nullptr;
PFNGLTEXIMAGE2DPROC real_tex_image_2d = nullptr;
PFNGLRENDERBUFFERSTORAGEPROC real_renderbuffer_storage = nullptr;
PFNGLGETERRORPROC real_get_error = nullptr;
PFNGLGETINTEGERVPROC real_get_integerv = nullptr;
PFNGLGETTEXLEVELPARAMETERIVPROC real_get_tex_level_parameteriv = nullptr;
PFNGLDRAWARRAYSPROC real_draw_arrays = nullptr;
PFNGLBINDIMAGETEXTUREPROC real_bind_image_texture = nullptr;
PFNGLDISPATCHCOMPUTEPROC real_dispatch_compute = nullptr;
PFNGLGETTEXPARAMETERIVPROC real_get_tex_parameteriv = nullptr;

const char* const kBrokenSource = "#version 330 core\nthis line is a fault injected by the test;\n";

void APIENTRY shader_source(GLuint shader, GLsizei count, const GLchar* const* strings, const GLint* lengths) {
  std::string text;
  for (GLsizei i = 0; i < count; ++i) {
    text += lengths != nullptr && lengths[i] >= 0 ? std::string(strings[i], static_cast<std::size_t>(lengths[i]))
                                                  : std::string(strings[i]);
  }
  bool broken = !g_faults.break_sources_with.empty() && text.find(g_faults.break_sources_with) != std::string::npos;
  if (g_faults.skip_shader_sources > 0) {
    --g_faults.skip_shader_sources;
  } else if (g_faults.break_shader_sources > 0) {
    --g_faults.break_shader_sources;
    broken = true;
  }
  if (broken) {
    ++g_faults.shader_sources_broken;
    g_faults.last_broken_source = text;
    real_shader_source(shader, 1, &kBrokenSource, nullptr);
    return;
  }
  real_shader_source(shader, count, strings, lengths);
}

void APIENTRY tex_image_2d(GLenum target, GLint level, GLint internal_format, GLsizei width, GLsizei height,
                           GLint border, GLenum format, GLenum type, const void* pixels) {
  const bool matches = g_faults.huge_intermediate_targets > 0 &&
                       internal_format == static_cast<GLint>(g_faults.huge_target_format) && pixels == nullptr;
  if (matches && g_faults.huge_target_skip > 0) {
    --g_faults.huge_target_skip;
  } else if (matches) {
    --g_faults.huge_intermediate_targets;
    GLint max_size = 0;
    real_get_integerv(GL_MAX_TEXTURE_SIZE, &max_size);
    for (int i = 0; i < 16 && real_get_error() != GL_NO_ERROR; ++i) {
    }
    real_tex_image_2d(target, level, internal_format, max_size, max_size, border, format, type, nullptr);
    const GLenum error = real_get_error();
    if (error == GL_OUT_OF_MEMORY) {
      ++g_faults.out_of_memory_from_driver;
    } else {
      // The driver found the memory: give the image the size asked for, and fail all the same.
      real_tex_image_2d(target, level, internal_format, width, height, border, format, type, nullptr);
      ++g_faults.out_of_memory_injected;
    }
    g_pending_error = GL_OUT_OF_MEMORY;
    return;
  }
  real_tex_image_2d(target, level, internal_format, width, height, border, format, type, pixels);
}

void APIENTRY renderbuffer_storage(GLenum target, GLenum internal_format, GLsizei width, GLsizei height) {
  real_renderbuffer_storage(target, internal_format, width, height);
  if (g_faults.fail_renderbuffer_storage > 0) {
    --g_faults.fail_renderbuffer_storage;
    ++g_faults.out_of_memory_injected;
    g_pending_error = GL_OUT_OF_MEMORY;
  }
}

void APIENTRY get_tex_level_parameteriv(GLenum target, GLint level, GLenum pname, GLint* params) {
  real_get_tex_level_parameteriv(target, level, pname, params);
  if (g_faults.fake_samples_texture != 0 && target == GL_TEXTURE_2D_MULTISAMPLE && pname == GL_TEXTURE_SAMPLES) {
    GLint bound = 0;
    real_get_integerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &bound);
    if (static_cast<unsigned>(bound) == g_faults.fake_samples_texture) *params = g_faults.fake_samples;
  }
}

void APIENTRY draw_arrays(GLenum mode, GLint first, GLsizei count) {
  real_draw_arrays(mode, first, count);
  ++g_faults.draws;
  if (g_faults.draw_error == 0) return;
  if (g_faults.skip_draws > 0) {
    --g_faults.skip_draws;
    return;
  }
  g_pending_error = static_cast<GLenum>(g_faults.draw_error);
  g_faults.draw_error = 0;
}

void APIENTRY dispatch_compute(GLuint x, GLuint y, GLuint z) {
  real_dispatch_compute(x, y, z);
  ++g_faults.draws;
}

void APIENTRY bind_image_texture(GLuint unit, GLuint texture, GLint level, GLboolean layered, GLint layer,
                                 GLenum access, GLenum format) {
  if (texture != 0 && texture == g_faults.watched_image_texture) ++g_faults.watched_image_bindings;
  real_bind_image_texture(unit, texture, level, layered, layer, access, format);
}

void APIENTRY get_tex_parameteriv(GLenum target, GLenum pname, GLint* params) {
  ++g_faults.texture_parameter_queries;
  real_get_tex_parameteriv(target, pname, params);
}

GLenum APIENTRY get_error() {
  if (g_pending_error != GL_NO_ERROR) {
    const GLenum error = g_pending_error;
    g_pending_error = GL_NO_ERROR;
    return error;
  }
  return real_get_error();
}

template <typename T>
void* as_address(T function) {
  void* address = nullptr;
  static_assert(sizeof address == sizeof function, "function pointers are data-pointer sized");
  std::memcpy(&address, &function, sizeof address);
  return address;
}

template <typename T>
void load(T* out, const char* name, void* headless) {
  void* address = sss_headless_get_proc_address(name, headless);
  std::memcpy(out, &address, sizeof *out);
}

}  // namespace

Faults& faults() { return g_faults; }

void reset_faults() {
  g_faults = Faults{};
  g_pending_error = GL_NO_ERROR;
}

void* fault_get_proc_address(const char* name, void* user) {
  load(&real_shader_source, "glShaderSource", user);
  load(&real_tex_image_2d, "glTexImage2D", user);
  load(&real_renderbuffer_storage, "glRenderbufferStorage", user);
  load(&real_get_error, "glGetError", user);
  load(&real_get_integerv, "glGetIntegerv", user);
  load(&real_get_tex_level_parameteriv, "glGetTexLevelParameteriv", user);
  load(&real_draw_arrays, "glDrawArrays", user);
  load(&real_dispatch_compute, "glDispatchCompute", user);
  load(&real_get_tex_parameteriv, "glGetTexParameteriv", user);
  load(&real_bind_image_texture, "glBindImageTexture", user);
  if (std::strcmp(name, "glShaderSource") == 0) return as_address(&shader_source);
  if (std::strcmp(name, "glTexImage2D") == 0) return as_address(&tex_image_2d);
  if (std::strcmp(name, "glRenderbufferStorage") == 0) return as_address(&renderbuffer_storage);
  if (std::strcmp(name, "glGetError") == 0) return as_address(&get_error);
  if (std::strcmp(name, "glGetTexLevelParameteriv") == 0) return as_address(&get_tex_level_parameteriv);
  if (std::strcmp(name, "glDrawArrays") == 0) return as_address(&draw_arrays);
  if (std::strcmp(name, "glDispatchCompute") == 0) return as_address(&dispatch_compute);
  if (std::strcmp(name, "glGetTexParameteriv") == 0) return as_address(&get_tex_parameteriv);
  if (std::strcmp(name, "glBindImageTexture") == 0 && real_bind_image_texture != nullptr) {
    return as_address(&bind_image_texture);
  }
  return sss_headless_get_proc_address(name, user);
}

}  // namespace sss_test
