#include "pixel_count.hpp"

#include "host_gl_util.hpp"

namespace demo {

namespace {

const char *const kMarkedShader = R"(#version 330 core
out vec4 o_color;
void main() { o_color = vec4(0.0); }
)";

const char *const kTouchedShader = R"(#version 330 core
uniform sampler2D u_before;
uniform sampler2D u_after;
out vec4 o_color;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (all(equal(texelFetch(u_before, p, 0), texelFetch(u_after, p, 0)))) discard;
  o_color = vec4(0.0);
}
)";

std::uint64_t counted_draw(const PixelCountPass &pass) {
  glBeginQuery(GL_SAMPLES_PASSED, pass.query);
  glBindVertexArray(pass.vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 samples = 0;
  glGetQueryObjectui64v(pass.query, GL_QUERY_RESULT, &samples);
  return samples;
}

}  // namespace

bool create_pixel_count_pass(PixelCountPass *pass) {
  pass->marked_program = build_program("count marked", kFullscreenVertexShader, kMarkedShader);
  pass->touched_program = build_program("count touched", kFullscreenVertexShader, kTouchedShader);
  if (pass->marked_program == 0 || pass->touched_program == 0) return false;
  glUseProgram(pass->touched_program);
  glUniform1i(glGetUniformLocation(pass->touched_program, "u_before"), 0);
  glUniform1i(glGetUniformLocation(pass->touched_program, "u_after"), 1);
  glUseProgram(0);
  glGenVertexArrays(1, &pass->vao);
  glGenQueries(1, &pass->query);
  return check_gl("pixel count setup");
}

PixelCounts count_pixels(const PixelCountPass &pass, const FrameTargets &targets, GLuint before, GLuint after) {
  PixelCounts counts;
  counts.total = static_cast<std::uint64_t>(targets.width) * static_cast<std::uint64_t>(targets.height);
  glViewport(0, 0, targets.width, targets.height);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDisable(GL_DEPTH_TEST);

  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.lighting_framebuffer);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glUseProgram(pass.marked_program);
  counts.marked = counted_draw(pass);
  glDisable(GL_STENCIL_TEST);

  if (after != before) {
    // The output framebuffer: neither texture is attached to it.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.output_framebuffer);
    glUseProgram(pass.touched_program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, before);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, after);
    counts.touched = counted_draw(pass);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glUseProgram(0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  return counts;
}

void destroy_pixel_count_pass(PixelCountPass *pass) {
  glDeleteProgram(pass->marked_program);
  glDeleteProgram(pass->touched_program);
  glDeleteVertexArrays(1, &pass->vao);
  glDeleteQueries(1, &pass->query);
  *pass = PixelCountPass{};
}

}  // namespace demo
