// Per-pixel profiles (sss_set_profiles, sss_frame.profile_texture) in the api layer: the settings
// conversion and kernel building they share with sss_set_settings (api_settings.cpp), and what a
// frame with a profile texture adds to sss_apply_frame (api_profiles.cpp).
#pragma once

#include "../gl/filter_run.hpp"
#include "../math/filter_constants.hpp"
#include "context.hpp"

namespace sss::api {

sss::math::FilterSettings to_filter_settings(const sss_settings& s);
// The pass kernel of `settings` (from ctx->recent_kernels when built lately), failing through fail().
sss_result build_pass_kernel(sss_context* ctx, const sss::math::FilterSettings& settings, sss::math::PassKernel* out);

// Width, scale or (eq. (1)) strength 0: the settings blur nothing.
bool is_identity_settings(const sss::math::FilterSettings& s);
// Every profile besides the first (sss_set_profiles) blurs nothing (true when there are none).
bool extra_profiles_are_identity(const sss_context& ctx);

// The profile texture as the GL (or the frame) described it, against sss.h: R8UI or R16UI,
// single-sample, the colour's size, and a frame the per-pixel passes can run (separable mode,
// single-sample colour).
sss_result check_profile_texture(sss_context* ctx, const gl::FilterRun& run);
// The profiles' kernels and per-frame constants into `run` (which has its constants from the first
// profile already), for a frame with a profile texture; geometry nullptr: the kernels alone
// (sss_prepare, before any camera).
// `projection`: the frame's camera (used with `geometry` only).
void fill_profiles(const sss_context& ctx, const sss::math::Matrix4& projection, const sss::math::FrameGeometry* geometry,
                   gl::FilterRun* run);
// SSS_CREATE_DEBUG_CHECKS: reads the indices back and refuses the frame (SSS_ERROR_INVALID_TEXTURE,
// before anything is drawn) where a pixel of the drawn rectangle names a profile that is not set.
sss_result check_profile_indices(sss_context* ctx, const gl::FilterRun& run);

}  // namespace sss::api
