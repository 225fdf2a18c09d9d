#include "multisample_textures.hpp"

#include "host_gl_util.hpp"

using namespace host_gl;

namespace sss_test {

namespace {

bool is_depth(GLenum f) {
  return f == GL_DEPTH_COMPONENT16 || f == GL_DEPTH_COMPONENT24 || f == GL_DEPTH_COMPONENT32 ||
         f == GL_DEPTH_COMPONENT32F || f == GL_DEPTH24_STENCIL8 || f == GL_DEPTH32F_STENCIL8;
}

const char* const kFillShader = R"(#version 330 core
uniform sampler2D u_fine;
uniform int u_sample;
out vec4 o_color;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy) * 2 + ivec2(u_sample % 2, (u_sample / 2) % 2);
  vec4 v = texelFetch(u_fine, p, 0);
  o_color = v;
  gl_FragDepth = v.r;
}
)";

const char* const kReadShader = R"(#version 330 core
uniform sampler2DMS u_ms;
uniform int u_sample;
out vec4 o_color;
void main() { o_color = texelFetch(u_ms, ivec2(gl_FragCoord.xy), u_sample); }
)";

// Saves and restores what the helpers change (the tests snapshot state after making textures,
// but a helper must not surprise the code that calls it either).
struct Saved {
  GLint program = 0, vao = 0, draw_fb = 0, read_fb = 0, active = 0, tex2d = 0, tex_ms = 0, viewport[4] = {0, 0, 0, 0};
  GLint depth_func = 0;
  GLboolean depth_test = 0, sample_mask = 0, depth_mask = 1;
  Saved() {
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_fb);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fb);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &tex2d);
    glGetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &tex_ms);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DEPTH_FUNC, &depth_func);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
    depth_test = glIsEnabled(GL_DEPTH_TEST);
    sample_mask = glIsEnabled(GL_SAMPLE_MASK);
  }
  ~Saved() {
    glUseProgram(static_cast<GLuint>(program));
    glBindVertexArray(static_cast<GLuint>(vao));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_fb));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_fb));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(tex2d));
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, static_cast<GLuint>(tex_ms));
    glActiveTexture(static_cast<GLenum>(active));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glDepthFunc(static_cast<GLenum>(depth_func));
    glDepthMask(depth_mask);
    depth_test ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
    sample_mask ? glEnable(GL_SAMPLE_MASK) : glDisable(GL_SAMPLE_MASK);
    glSampleMaski(0, ~0u);
  }
};

}  // namespace

int texture_samples(GLuint texture) {
  GLint previous = 0, samples = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &previous);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, texture);
  glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &samples);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, static_cast<GLuint>(previous));
  return samples;
}

GLuint make_multisample_texture(GLenum internal_format, int width, int height, int samples,
                                const std::vector<float>& fine) {
  Saved saved;
  while (glGetError() != GL_NO_ERROR) {
  }
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, texture);
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internal_format, width, height, GL_TRUE);
  if (glGetError() != GL_NO_ERROR) return texture;  // no storage: the caller tests the refusal
  if (fine.empty()) return texture;

  const bool depth = is_depth(internal_format);
  GLuint source = 0;
  glGenTextures(1, &source);
  glBindTexture(GL_TEXTURE_2D, source);
  const bool one_channel = fine.size() == static_cast<std::size_t>(4 * width * height);
  glTexImage2D(GL_TEXTURE_2D, 0, one_channel ? GL_R32F : GL_RGBA32F, 2 * width, 2 * height, 0,
               one_channel ? GL_RED : GL_RGBA, GL_FLOAT, fine.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // one level: complete without mipmaps
  GLuint framebuffer = 0, vao = 0;
  glGenFramebuffers(1, &framebuffer);
  glGenVertexArrays(1, &vao);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  const bool stencil = internal_format == GL_DEPTH24_STENCIL8 || internal_format == GL_DEPTH32F_STENCIL8;
  const GLenum attachment = !depth ? GL_COLOR_ATTACHMENT0 : stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D_MULTISAMPLE, texture, 0);
  const GLenum none = GL_NONE, color0 = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, depth ? &none : &color0);
  const GLuint program = build_program("msaa fill", kFullscreenVertexShader, kFillShader);
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "u_fine"), 0);
  const GLint sample_location = glGetUniformLocation(program, "u_sample");
  glBindVertexArray(vao);
  glViewport(0, 0, width, height);
  if (depth) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glEnable(GL_SAMPLE_MASK);
  for (int i = 0; i < samples; ++i) {
    glSampleMaski(0, 1u << i);
    glUniform1i(sample_location, i);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDeleteProgram(program);
  glDeleteVertexArrays(1, &vao);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &source);
  return texture;
}

GLuint make_multisample_depth_stencil(int width, int height, int samples, const std::vector<float>& fine_depth,
                                      const std::vector<uint8_t>& fine_stencil) {
  const GLuint texture = make_multisample_texture(GL_DEPTH24_STENCIL8, width, height, samples, fine_depth);
  Saved saved;
  GLint stencil_func = 0, stencil_ref = 0, stencil_mask = 0, fail = 0, zfail = 0, zpass = 0, write_mask = 0;
  glGetIntegerv(GL_STENCIL_FUNC, &stencil_func);
  glGetIntegerv(GL_STENCIL_REF, &stencil_ref);
  glGetIntegerv(GL_STENCIL_VALUE_MASK, &stencil_mask);
  glGetIntegerv(GL_STENCIL_FAIL, &fail);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &zfail);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &zpass);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &write_mask);
  const GLboolean stencil_test = glIsEnabled(GL_STENCIL_TEST);
  // The stencil as a float image; fragments where it is 0 are discarded, the others REPLACE 1.
  std::vector<float> marks(fine_stencil.size());
  for (std::size_t i = 0; i < marks.size(); ++i) marks[i] = fine_stencil[i] != 0 ? 1.0f : 0.0f;
  GLuint source = 0, framebuffer = 0, vao = 0;
  glGenTextures(1, &source);
  glBindTexture(GL_TEXTURE_2D, source);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, 2 * width, 2 * height, 0, GL_RED, GL_FLOAT, marks.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glGenFramebuffers(1, &framebuffer);
  glGenVertexArrays(1, &vao);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D_MULTISAMPLE, texture, 0);
  const GLenum none = GL_NONE;
  glDrawBuffers(1, &none);
  glStencilMask(0xFF);
  const GLint zero = 0;
  glClearBufferiv(GL_STENCIL, 0, &zero);
  static const char* const kMarkShader = R"(#version 330 core
uniform sampler2D u_fine;
uniform int u_sample;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy) * 2 + ivec2(u_sample % 2, (u_sample / 2) % 2);
  if (texelFetch(u_fine, p, 0).r == 0.0) discard;
}
)";
  const GLuint program = build_program("msaa stencil", kFullscreenVertexShader, kMarkShader);
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "u_fine"), 0);
  const GLint sample_location = glGetUniformLocation(program, "u_sample");
  glBindVertexArray(vao);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glEnable(GL_SAMPLE_MASK);
  for (int i = 0; i < samples; ++i) {
    glSampleMaski(0, 1u << i);
    glUniform1i(sample_location, i);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDeleteProgram(program);
  glDeleteVertexArrays(1, &vao);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &source);
  glStencilFunc(static_cast<GLenum>(stencil_func), stencil_ref, static_cast<GLuint>(stencil_mask));
  glStencilOp(static_cast<GLenum>(fail), static_cast<GLenum>(zfail), static_cast<GLenum>(zpass));
  glStencilMask(static_cast<GLuint>(write_mask));
  stencil_test ? glEnable(GL_STENCIL_TEST) : glDisable(GL_STENCIL_TEST);
  return texture;
}

std::vector<std::vector<float>> read_samples(GLuint texture, int width, int height, int samples) {
  Saved saved;
  GLint pack_buffer = 0, alignment = 4;
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack_buffer);
  glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
  GLuint target = make_texture(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT);
  GLuint framebuffer = 0, vao = 0;
  glGenFramebuffers(1, &framebuffer);
  glGenVertexArrays(1, &vao);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
  const GLuint program = build_program("msaa read", kFullscreenVertexShader, kReadShader);
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "u_ms"), 0);
  const GLint sample_location = glGetUniformLocation(program, "u_sample");
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, texture);
  glBindVertexArray(vao);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SAMPLE_MASK);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::vector<float>> out(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) {
    glUniform1i(sample_location, i);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    out[static_cast<std::size_t>(i)].resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out[static_cast<std::size_t>(i)].data());
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer));
  glPixelStorei(GL_PACK_ALIGNMENT, alignment);
  glDeleteProgram(program);
  glDeleteVertexArrays(1, &vao);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &target);
  return out;
}

}  // namespace sss_test
