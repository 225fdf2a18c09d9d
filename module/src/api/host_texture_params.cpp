#include "host_texture_params.hpp"

#include "../gl/host_texture_state.hpp"
#include "../gl/frame_plan.hpp"
#include "validation.hpp"

namespace sss::api {

namespace gl = sss::gl;

namespace {
// GL_DEPTH_STENCIL_TEXTURE_MODE of a depth-stencil depth texture: the frame's word, the GL's answer
// for an undescribed frame, else the default (GL_DEPTH_COMPONENT, also the only mode before
// GL 4.3 / ES 3.1).
sss_result depth_stencil_mode(sss_context* ctx, const sss_frame& frame, const gl::TextureInfo& depth, bool described,
                              gl::GLenum* mode) {
  const gl::Functions& f = ctx->gl;
  *mode = gl::DEPTH_COMPONENT;
  if (!gl::is_depth_stencil_format(depth.internal_format)) return SSS_OK;
  if (frame.depth_stencil_mode == gl::STENCIL_INDEX && !gl::has_depth_stencil_mode(f)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->depth_stencil_mode = 0x%04X (GL_STENCIL_INDEX): this GL (%s %d.%d) has no "
                "GL_DEPTH_STENCIL_TEXTURE_MODE (OpenGL 4.3+, OpenGL ES 3.1+), so depth_texture = %u samples depth",
                frame.depth_stencil_mode, f.api.es ? "OpenGL ES" : "OpenGL", f.api.major, f.api.minor, depth.name);
  }
  if (frame.depth_stencil_mode != 0) {
    *mode = frame.depth_stencil_mode;
  } else if (!described && gl::has_depth_stencil_mode(f)) {
    *mode = gl::query_depth_stencil_mode(f, depth);
  }
  return SSS_OK;
}
}  // namespace

sss_result host_texture_params(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run, gl::GLenum* depth_mode) {
  const bool described = frame_described(frame);
  const sss_result r = depth_stencil_mode(ctx, frame, run->depth, described, depth_mode);
  if (r != SSS_OK) return r;
  if ((frame.flags & SSS_FRAME_TARGET_COMPLETE) != 0) {
    run->target_complete = true;
    run->color_complete = run->writes_back();  // in place, the target is the colour
    return SSS_OK;
  }
  // Asked only where completeness is all that keeps the frame off the compute path.
  const bool wants_compute = run->path == SSS_PATH_COMPUTE || run->path == SSS_PATH_AUTO;
  run->target_complete = true;
  const bool only_completeness = wants_compute && !run->identity &&
                                 *gl::path_unavailable(*run, ctx->filter.capabilities(), SSS_PATH_COMPUTE) == '\0';
  run->target_complete = only_completeness && !described && gl::query_image_complete(ctx->gl, run->target());
  // The colour, where the passes' inputs could read it through an image unit (one answer serves
  // both in place, when the target's was asked).
  if (!described && gl::may_read_color_image(ctx->filter.capabilities(), *run)) {
    run->color_complete = run->writes_back() && only_completeness ? run->target_complete
                                                                   : gl::query_image_complete(ctx->gl, run->color);
  }
  return SSS_OK;
}

}  // namespace sss::api
