// Argument checks shared by the entry points. Each returns SSS_OK or fails through api::fail with a
// message naming the argument and its value. None calls GL.
#pragma once

#include <array>

#include "context.hpp"

namespace sss::api {

sss_result check_samples(sss_context* ctx, int32_t samples);
sss_result check_unit_range(sss_context* ctx, const char* name, const float values[3]);
sss_result check_settings(sss_context* ctx, const sss_settings* s);
sss_result check_frame(sss_context* ctx, const sss_frame* frame);
// The optional texture description of sss_frame (formats in their lists, sizes both 0 or both > 0).
sss_result check_frame_description(sss_context* ctx, const sss_frame& frame);

}  // namespace sss::api
