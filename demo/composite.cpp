#include "composite.hpp"

#include "host_gl_util.hpp"

namespace demo {

namespace {

const char *const kVertexShader = R"(#version 330 core
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char *const kFragmentShader = R"(#version 330 core
uniform sampler2D u_diffuse;
uniform sampler2D u_specular;
uniform float u_exposure;
out vec4 o_color;

// Narkowicz's fit of the ACES filmic curve (with his 0.6 input scale).
vec3 aces_fit(vec3 x) {
  x *= 0.6;
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 srgb_encode(vec3 c) {
  vec3 low = c * 12.92;
  vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(low, high, step(vec3(0.0031308), c));
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 linear = texelFetch(u_diffuse, p, 0).rgb + texelFetch(u_specular, p, 0).rgb;
  o_color = vec4(srgb_encode(aces_fit(max(linear, vec3(0.0)) * u_exposure)), 1.0);
}
)";

}  // namespace

bool create_composite_pass(CompositePass *pass, GLsizei width, GLsizei height) {
  pass->width = width;
  pass->height = height;
  pass->program = build_program("composite", kVertexShader, kFragmentShader);
  if (pass->program == 0) return false;
  glUseProgram(pass->program);
  glUniform1i(glGetUniformLocation(pass->program, "u_diffuse"), 0);
  glUniform1i(glGetUniformLocation(pass->program, "u_specular"), 1);
  glUseProgram(0);

  pass->output_texture = make_texture(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE);
  glGenFramebuffers(1, &pass->framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pass->framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, pass->output_texture, 0);
  const GLenum buffer = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &buffer);
  const bool complete = check_framebuffer("composite");
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glGenVertexArrays(1, &pass->vao);
  return complete && check_gl("composite pass setup");
}

void run_composite_pass(const CompositePass &pass, GLuint diffuse, GLuint specular, float exposure) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pass.framebuffer);
  glViewport(0, 0, pass.width, pass.height);
  glUseProgram(pass.program);
  glUniform1f(glGetUniformLocation(pass.program, "u_exposure"), exposure);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, diffuse);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, specular);
  glBindVertexArray(pass.vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

std::vector<std::uint8_t> read_composite(const CompositePass &pass) {
  std::vector<std::uint8_t> pixels(static_cast<size_t>(pass.width) * static_cast<size_t>(pass.height) * 4u);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, pass.framebuffer);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, pass.width, pass.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return pixels;
}

void destroy_composite_pass(CompositePass *pass) {
  glDeleteProgram(pass->program);
  glDeleteFramebuffers(1, &pass->framebuffer);
  glDeleteTextures(1, &pass->output_texture);
  glDeleteVertexArrays(1, &pass->vao);
  *pass = CompositePass{};
}

}  // namespace demo
