// sss_apply and sss_apply_frame: validate everything (arguments first, then the textures as the GL
// describes them) before the first draw, so that a failure leaves the host's textures untouched.
#include <cstdio>

#include "../gl/debug_label.hpp"
#include "../gl/state_guard.hpp"
#include "../gl/texture_query.hpp"
#include "context.hpp"
#include "gl_session.hpp"
#include "validation.hpp"

namespace {

using sss::api::fail;
namespace gl = sss::gl;

sss_result query(sss_context* ctx, gl::GLuint name, const char* role, gl::TextureInfo* info) {
  std::string message;
  const sss_result r = gl::query_texture(ctx->gl, name, role, info, &message);
  return r == SSS_OK ? r : fail(ctx, r, message);
}

sss_result wrong_format(sss_context* ctx, const char* role, const gl::TextureInfo& t, const char* expected) {
  return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "%s = %u has format %s: expected %s", role, t.name,
              gl::format_name(t.internal_format).c_str(), expected);
}

sss_result same_size(sss_context* ctx, const char* role, const gl::TextureInfo& t, const gl::TextureInfo& color) {
  if (t.width == color.width && t.height == color.height) return SSS_OK;
  return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "%s = %u is %dx%d but the colour texture is %dx%d", role, t.name,
              t.width, t.height, color.width, color.height);
}

// Colour, depth and stencil must agree in target and sample count (an MSAA path needs every
// sample of every input; a mix has no meaning).
sss_result same_samples(sss_context* ctx, const char* role, const gl::TextureInfo& t, const gl::TextureInfo& color) {
  if (t.multisampled() == color.multisampled() && t.samples == color.samples) return SSS_OK;
  return fail(ctx, SSS_ERROR_INVALID_TEXTURE, "%s = %u is %s but color_texture = %u is %s: both must have the same "
              "target and sample count", role, t.name, gl::describe_target(t).c_str(), color.name,
              gl::describe_target(color).c_str());
}

// A multisampled texture's count against the module's limit (one 32-bit sample mask word) and the
// context's limits.
sss_result supported_samples(sss_context* ctx, const char* role, const gl::TextureInfo& t, gl::GLenum limit,
                             const char* limit_name) {
  if (!t.multisampled()) return SSS_OK;
  gl::GLint max_samples = 0;
  ctx->gl.GetIntegerv(limit, &max_samples);
  if (t.samples <= 32 && t.samples <= max_samples) return SSS_OK;
  return fail(ctx, SSS_ERROR_UNSUPPORTED, "%s = %u has %d samples: this context supports at most %d (%s), the "
              "module at most 32", role, t.name, t.samples, max_samples, limit_name);
}

// The textures, as the GL describes them, against the lists in sss.h.
sss_result query_textures(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run, gl::StencilInput* stencil) {
  sss_result r = query(ctx, frame.color_texture, "color_texture", &run->color);
  if (r != SSS_OK) return r;
  if (!gl::is_color_format(run->color.internal_format)) {
    return wrong_format(ctx, "color_texture", run->color, "GL_RGBA16F or GL_RGBA32F");
  }
  r = supported_samples(ctx, "color_texture", run->color, gl::MAX_COLOR_TEXTURE_SAMPLES,
                        "GL_MAX_COLOR_TEXTURE_SAMPLES");
  if (r != SSS_OK) return r;
  r = query(ctx, frame.depth_texture, "depth_texture", &run->depth);
  if (r != SSS_OK) return r;
  if (!gl::is_hardware_depth_format(run->depth.internal_format) && !gl::is_linear_depth_format(run->depth.internal_format)) {
    return wrong_format(ctx, "depth_texture", run->depth, "a GL_DEPTH_COMPONENT* or GL_DEPTH*_STENCIL8 format, or GL_R16F/GL_R32F");
  }
  r = same_size(ctx, "depth_texture", run->depth, run->color);
  if (r == SSS_OK) r = same_samples(ctx, "depth_texture", run->depth, run->color);
  if (r == SSS_OK) {
    // Linear depth (R16F/R32F) is a colour format to the GL.
    const bool linear = gl::is_linear_depth_format(run->depth.internal_format);
    r = supported_samples(ctx, "depth_texture", run->depth,
                          linear ? gl::MAX_COLOR_TEXTURE_SAMPLES : gl::MAX_DEPTH_TEXTURE_SAMPLES,
                          linear ? "GL_MAX_COLOR_TEXTURE_SAMPLES" : "GL_MAX_DEPTH_TEXTURE_SAMPLES");
  }
  if (r != SSS_OK) return r;
  if (frame.output_texture != 0) {
    r = query(ctx, frame.output_texture, "output_texture", &run->output);
    if (r != SSS_OK) return r;
    if (!gl::is_color_format(run->output.internal_format)) {
      return wrong_format(ctx, "output_texture", run->output, "GL_RGBA16F or GL_RGBA32F");
    }
    if (run->output.multisampled()) {
      return fail(ctx, SSS_ERROR_INVALID_TEXTURE,
                  "output_texture = %u is %s: the output is single-sample (pass 0 to write back into the "
                  "multisampled colour)", run->output.name, gl::describe_target(run->output).c_str());
    }
    r = same_size(ctx, "output_texture", run->output, run->color);
    if (r != SSS_OK) return r;
  }
  if (frame.stencil != nullptr) {
    r = query(ctx, frame.stencil->depth_stencil_texture, "stencil->depth_stencil_texture", &stencil->texture);
    if (r != SSS_OK) return r;
    if (!gl::is_depth_stencil_format(stencil->texture.internal_format)) {
      return wrong_format(ctx, "stencil->depth_stencil_texture", stencil->texture,
                          "GL_DEPTH24_STENCIL8 or GL_DEPTH32F_STENCIL8");
    }
    r = same_size(ctx, "stencil->depth_stencil_texture", stencil->texture, run->color);
    if (r == SSS_OK) r = same_samples(ctx, "stencil->depth_stencil_texture", stencil->texture, run->color);
    if (r != SSS_OK) return r;
    stencil->ref = frame.stencil->ref;
    stencil->mask = frame.stencil->mask;
    run->stencil = stencil;
  }
  const int32_t* vp = frame.viewport;
  if (vp[2] == 0) {
    run->viewport = {0, 0, run->color.width, run->color.height};
  } else if (vp[0] + vp[2] > run->color.width || vp[1] + vp[3] > run->color.height) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->viewport = {%d, %d, %d, %d} reaches outside the %dx%d colour texture",
                vp[0], vp[1], vp[2], vp[3], run->color.width, run->color.height);
  } else {
    run->viewport = {vp[0], vp[1], vp[2], vp[3]};
  }
  return SSS_OK;
}

sss::math::DepthEncoding depth_encoding(const gl::TextureInfo& depth, std::uint32_t frame_flags) {
  if (gl::is_linear_depth_format(depth.internal_format)) return sss::math::DepthEncoding::linear_distance;
  return (frame_flags & SSS_FRAME_DEPTH_ZERO_TO_ONE) != 0 ? sss::math::DepthEncoding::hardware_zero_to_one
                                                          : sss::math::DepthEncoding::hardware_minus_one_to_one;
}

// Width 0 or no strength in any channel: the filter is the identity, so nothing is drawn unless a
// separate output must receive the colour.
bool is_identity(const sss::math::FilterSettings& s) {
  return s.width == 0.0f || (s.strength[0] == 0.0f && s.strength[1] == 0.0f && s.strength[2] == 0.0f);
}

}  // namespace

extern "C" {

SSS_API sss_result sss_apply(sss_context* ctx, uint32_t color_texture, uint32_t depth_texture,
                             const sss_stencil* stencil) {
  sss_frame frame = {};
  frame.struct_size = sizeof frame;
  frame.color_texture = color_texture;
  frame.depth_texture = depth_texture;
  frame.stencil = stencil;
  return sss_apply_frame(ctx, &frame);
}

SSS_API sss_result sss_apply_frame(sss_context* ctx, const sss_frame* frame) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  sss_result r = sss::api::check_frame(ctx, frame);
  if (r != SSS_OK) return r;
  if (!ctx->has_camera) return fail(ctx, SSS_ERROR_INVALID_OPERATION, "no camera: call sss_set_camera before applying");
  const gl::Functions& f = ctx->gl;
  r = sss::api::require_current_context(ctx, f);
  if (r != SSS_OK) return r;

  sss::api::drain_host_errors(ctx, f);
  gl::StateGuard guard(f, (ctx->create_flags & SSS_CREATE_NO_STATE_RESTORE) == 0);
  gl::DebugGroup group(f, (ctx->create_flags & SSS_CREATE_NO_DEBUG_LABELS) == 0, "sss_apply");

  r = sss::api::require_module_objects(ctx);
  if (r != SSS_OK) return r;

  gl::FilterRun run;
  gl::StencilInput stencil;
  r = query_textures(ctx, *frame, &run, &stencil);
  if (r != SSS_OK) {
    sss::api::drain_host_errors(nullptr, f);  // a failed query may have raised one
    return r;
  }
  sss::math::FrameGeometry geometry;
  geometry.texture_width = run.color.width;
  geometry.texture_height = run.color.height;
  geometry.viewport = run.viewport;
  geometry.depth = depth_encoding(run.depth, frame->flags);
  if (run.color.multisampled()) {
    // The resolve reads the host's encoding; the passes read the resolved linear distance.
    run.resolve_constants = sss::math::compute_pass_constants(ctx->settings, ctx->projection, geometry);
    geometry.depth = sss::math::DepthEncoding::linear_distance;
    run.depth_resolve = static_cast<gl::DepthResolve>(frame->msaa_depth_resolve);
  }
  run.constants = sss::math::compute_pass_constants(ctx->settings, ctx->projection, geometry);
  run.kernel = &ctx->kernel;
  run.kernel_revision = ctx->kernel_revision;
  run.follow_surface = ctx->settings.follow_surface;
  run.identity = is_identity(ctx->settings);

  std::string message;
  r = ctx->filter.run(run, &message);
  if (r != SSS_OK) {
    sss::api::drain_host_errors(nullptr, f);
    return fail(ctx, r, message);
  }
  return sss::api::check_gl_errors(ctx, f, "the separable passes");
}

}  // extern "C"
