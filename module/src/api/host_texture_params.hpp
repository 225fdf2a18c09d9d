// The host texture parameters the passes depend on but cannot override with their own sampler
// objects (gl/host_texture_state.hpp): the depth texture's GL_DEPTH_STENCIL_TEXTURE_MODE and
// whether the compute path's target is complete. Taken from the frame where it states them; asked
// of the GL only for a frame that does not describe its textures (frame_described, validation.hpp:
// a described frame's steady state makes no GL query), and otherwise taken at the GL's default for
// a new texture.
#pragma once

#include "../gl/filter_run.hpp"
#include "context.hpp"

namespace sss::api {

// Sets run->target_complete and *depth_mode (the depth texture's GL_DEPTH_STENCIL_TEXTURE_MODE:
// GL_DEPTH_COMPONENT or GL_STENCIL_INDEX). Call once the run's textures, path and identity are
// known. SSS_ERROR_INVALID_ARGUMENT (with the message) for a frame stating GL_STENCIL_INDEX on a GL
// that has no such parameter.
sss_result host_texture_params(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run, gl::GLenum* depth_mode);

}  // namespace sss::api
