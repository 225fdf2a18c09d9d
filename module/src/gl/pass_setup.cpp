#include "pass_setup.hpp"

#include <atomic>
#include <cstdio>

#include "debug_label.hpp"
#include "state_guard.hpp"
#include "texture_units.hpp"

namespace sss::gl {

namespace {
// A tag in [1025, 1025 + 2^20), exact in float, different for each create() in the process (modulo
// 2^20). It is stored as the sampler's GL_TEXTURE_MAX_LOD, which has no effect here: the sampler
// never reads mipmaps (GL_LINEAR/GL_NEAREST minification, texelFetch at level 0), and a maximum LOD
// above 0 does not change which of the two identical filters applies. Unlike the border colour
// (used before), the LOD range exists on OpenGL ES 3.0 too.
GLfloat next_sampler_tag() {
  static std::atomic<unsigned> counter{0};
  const unsigned n = counter.fetch_add(1, std::memory_order_relaxed) % (1u << 20);
  return 1025.0f + static_cast<GLfloat>(n);
}

void set_sampler(const Functions& f, GLuint sampler, GLenum filter) {
  f.SamplerParameteri(sampler, TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  f.SamplerParameteri(sampler, TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  f.SamplerParameteri(sampler, TEXTURE_WRAP_S, static_cast<GLint>(CLAMP_TO_EDGE));
  f.SamplerParameteri(sampler, TEXTURE_WRAP_T, static_cast<GLint>(CLAMP_TO_EDGE));
  f.SamplerParameteri(sampler, TEXTURE_COMPARE_MODE, static_cast<GLint>(NONE));
}
}  // namespace

void PassObjects::create(const Functions& f, bool labels) {
  f.GenVertexArrays(1, &vertex_array);
  f.BindVertexArray(vertex_array);  // a vertex array name becomes an object on first bind
  // Samplers override whatever parameters the host set on its own textures, which the module
  // never changes.
  GLuint samplers[3] = {0, 0, 0};
  f.GenSamplers(3, samplers);
  sampler = samplers[0];
  depth_sampler = samplers[1];
  nearest_sampler = samplers[2];
  set_sampler(f, sampler, LINEAR);
  set_sampler(f, depth_sampler, f.api.es ? NEAREST : LINEAR);
  set_sampler(f, nearest_sampler, NEAREST);
  sampler_tag = next_sampler_tag();
  f.SamplerParameterf(sampler, TEXTURE_MAX_LOD, sampler_tag);
  label_object(f, labels, VERTEX_ARRAY, vertex_array, "sss fullscreen triangle");
  label_object(f, labels, SAMPLER, sampler, "sss bilinear clamp");
  label_object(f, labels, SAMPLER, depth_sampler, "sss depth clamp");
  label_object(f, labels, SAMPLER, nearest_sampler, "sss nearest clamp");
}

void PassObjects::destroy(const Functions& f) {
  const GLuint samplers[3] = {sampler, depth_sampler, nearest_sampler};
  f.DeleteSamplers(3, samplers);
  if (vertex_array != 0) f.DeleteVertexArrays(1, &vertex_array);
  *this = PassObjects{};
}

bool PassObjects::present(const Functions& f) const {
  if (vertex_array == 0 || !f.IsVertexArray(vertex_array) || !f.IsSampler(sampler) || !f.IsSampler(depth_sampler) ||
      !f.IsSampler(nearest_sampler)) {
    return false;
  }
  GLfloat tag = -1.0f;
  f.GetSamplerParameterfv(sampler, TEXTURE_MAX_LOD, &tag);
  return tag == sampler_tag;
}

void begin_passes(PassContext& ctx, const std::array<int, 4>& rect) {
  set_pass_state(ctx.gl);
  ctx.gl.BindVertexArray(ctx.objects.vertex_array);
  ctx.gl.Viewport(rect[0], rect[1], rect[2], rect[3]);
}

sss_result check_framebuffer(const Functions& gl, const char* which, std::string* message) {
  const GLenum status = gl.CheckFramebufferStatus(DRAW_FRAMEBUFFER);
  if (status == FRAMEBUFFER_COMPLETE) return SSS_OK;
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "the %s framebuffer is incomplete (status 0x%04X)", which, status);
  *message = buffer;
  return SSS_ERROR_FRAMEBUFFER;
}

sss_result check_framebuffer(const PassContext& ctx, const char* which, std::string* message) {
  return ctx.check_framebuffers ? check_framebuffer(ctx.gl, which, message) : SSS_OK;
}

GLuint horizontal_framebuffer(const PassContext& ctx, const FilterRun& run) {
  const Targets& t = ctx.targets.names();
  return run.cross_bilateral ? t.intermediate_framebuffer : t.pass_intermediate_framebuffer;
}

sss_result copy_stencil(PassContext& ctx, const FilterRun& run, const StencilInput& stencil, std::string* message,
                        GLuint framebuffer) {
  const Functions& f = ctx.gl;
  const int width = run.color.width, height = run.color.height;
  sss_result r = ctx.targets.ensure_stencil_buffer(stencil.texture.internal_format, width, height, message);
  if (r != SSS_OK) return r;
  const Targets& t = ctx.targets.names();
  f.BindFramebuffer(READ_FRAMEBUFFER, t.stencil_source_framebuffer);
  // A multisampled depth-stencil is resolved by the blit: GL picks one sample's stencil per pixel.
  f.FramebufferTexture2D(READ_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, stencil.texture.target, stencil.texture.name, 0);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, framebuffer != 0 ? framebuffer : horizontal_framebuffer(ctx, run));
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, t.stencil_buffer);
  if (ctx.check_framebuffers && f.CheckFramebufferStatus(READ_FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) {
    *message = "the host's depth-stencil texture cannot be read as a framebuffer attachment";
    r = SSS_ERROR_FRAMEBUFFER;
  } else {
    r = check_framebuffer(ctx, "horizontal pass", message);
  }
  if (r == SSS_OK) f.BlitFramebuffer(0, 0, width, height, 0, 0, width, height, STENCIL_BUFFER_BIT, NEAREST);
  // Never keep a host texture attached: its storage would outlive the host's glDeleteTextures.
  f.FramebufferTexture2D(READ_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, TEXTURE_2D, 0, 0);
  return r;
}

void set_stencil_test(const Functions& f, const StencilInput* stencil, GLenum func) {
  if (stencil == nullptr) {
    f.Disable(STENCIL_TEST);
    return;
  }
  f.Enable(STENCIL_TEST);
  f.StencilFuncSeparate(FRONT_AND_BACK, func, static_cast<GLint>(stencil->ref), stencil->mask);
  f.StencilOpSeparate(FRONT_AND_BACK, KEEP, KEEP, KEEP);
  f.StencilMaskSeparate(FRONT_AND_BACK, 0);
}

sss_result attach_stencil(PassContext& ctx, GLuint framebuffer, GLuint stencil_buffer, std::string* message,
                          const char* which) {
  ctx.gl.BindFramebuffer(DRAW_FRAMEBUFFER, framebuffer);
  ctx.gl.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_buffer);
  return check_framebuffer(ctx, which, message);
}

sss_result attach_output(PassContext& ctx, const FilterRun& run, GLuint stencil_buffer, std::string* message) {
  const Functions& f = ctx.gl;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().output_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, run.target().name, 0);
  f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, stencil_buffer);
  const sss_result r = check_framebuffer(ctx, "vertical pass", message);
  if (r == SSS_OK && run.region && !run.keeps_untouched()) copy_outside_region(ctx, run);
  return r;
}

void detach_output(PassContext& ctx) {
  ctx.gl.BindFramebuffer(DRAW_FRAMEBUFFER, ctx.targets.names().output_framebuffer);
  ctx.gl.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 0, 0);
}

void bind_texture(PassContext& ctx, GLuint unit, GLuint texture, GLuint sampler) {
  ctx.gl.ActiveTexture(TEXTURE0 + unit);
  ctx.gl.BindTexture(TEXTURE_2D, texture);
  ctx.gl.BindSampler(unit, sampler);
}

void bind_original(PassContext& ctx, const FilterRun& run) {
  bind_texture(ctx, unit::original, run.keeps_untouched() ? 0 : run.untouched_colour(), ctx.objects.sampler);
}

void bind_albedo(PassContext& ctx, const FilterRun& run, int albedo, GLint texturing) {
  const Functions& f = ctx.gl;
  bind_texture(ctx, unit::albedo, run.albedo.name, ctx.objects.nearest_sampler);
  if (albedo != 3) return;
  bind_texture(ctx, unit::profile_ids, run.profile_ids.name, ctx.objects.nearest_sampler);
  float modes[SSS_MAX_PROFILES] = {};
  for (int i = 0; i < run.profile_count; ++i) modes[i] = run.texturing[static_cast<std::size_t>(i)];
  f.Uniform1fv(texturing, run.profile_count, modes);
}

void draw_copy(PassContext& ctx, GLuint source) {
  ctx.gl.UseProgram(ctx.programs.copy());
  bind_texture(ctx, unit::source, source, ctx.objects.sampler);
  ctx.gl.DrawArrays(TRIANGLES, 0, 3);
  ++ctx.draws;
}

void draw_cover(PassContext& ctx, GLint tile_grid) {
  if (ctx.tile_bands > 0) {
    ctx.gl.Uniform4fv(tile_grid, 1, ctx.tile_grid.data());
    ctx.gl.DrawArraysInstanced(TRIANGLE_STRIP, 3, 4, ctx.tile_bands);  // fullscreen.vert's vertices 3-6
  } else {
    ctx.gl.DrawArrays(TRIANGLES, 0, 3);
  }
  ++ctx.draws;
}

void copy_outside_region(PassContext& ctx, const FilterRun& run) {
  const Functions& f = ctx.gl;
  DebugGroup group(f, ctx.labels, "sss copy of the viewport outside the region");
  f.Disable(STENCIL_TEST);
  f.Disable(DEPTH_TEST);
  f.Viewport(run.viewport[0], run.viewport[1], run.viewport[2], run.viewport[3]);
  draw_copy(ctx, run.untouched_colour());
  f.Viewport(run.draw_rect[0], run.draw_rect[1], run.draw_rect[2], run.draw_rect[3]);
}

}  // namespace sss::gl
