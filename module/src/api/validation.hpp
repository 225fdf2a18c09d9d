// Argument checks shared by the entry points. Each returns SSS_OK or fails through api::fail with a
// message naming the argument and its value. None calls GL.
#pragma once

#include <array>

#include "../math/kernel_request.hpp"
#include "context.hpp"
#include "sss/sss_lut.h"
#include "sss/sss_tools.h"

namespace sss::api {

sss_result check_settings(sss_context* ctx, const sss_settings* s);
sss_result check_frame(sss_context* ctx, const sss_frame* frame);
// A projection as sss_set_camera and sss_frame.projection take it: NULL and invalid matrices
// SSS_ERROR_INVALID_ARGUMENT, unsupported ones SSS_ERROR_UNSUPPORTED, the message naming the element
// as `owner` + "projection[i]" ("", "frame->", "query->"); else *out.
sss_result take_projection(sss_context* ctx, const float* projection, const char* owner, sss::math::Matrix4* out);
// The optional texture description of sss_frame (formats in their lists, sizes both 0 or both > 0).
sss_result check_frame_description(sss_context* ctx, const sss_frame& frame);
// The frame describes its textures (sss.h, sss_frame): the size, and the format of every texture
// it names, as OpenGL ES 3.0 requires. The one definition of "described": a described frame can be
// steady (steady_frame.hpp) and is never asked about host texture parameters (host_texture_params.hpp).
bool frame_described(const sss_frame& frame);

// Shared by both libraries (kernel_desc.cpp): taps odd in [SSS_MIN_TAPS, SSS_MAX_TAPS], three values
// in [0, 1], the default descs (what sss_default_profile_desc / sss_default_kernel_desc give).
sss_result check_taps(sss_context* ctx, const char* name, int32_t taps);
sss_result check_unit_range(sss_context* ctx, const char* name, const float values[3]);
void default_profile_desc(sss_profile_desc* p);
void default_kernel_desc(sss_kernel_desc* d);

// sss_profile_desc and sss_kernel_desc (kernel_desc.cpp). `name` is how the fields are reached in
// messages: check_profile's the struct itself ("profile"), check_kernel_desc's a prefix ("desc->",
// "settings->kernel->"). in_settings: the desc embedded in sss_settings, whose taps, strength and
// falloff are not read (the settings' own are).
sss_result check_profile(sss_context* ctx, const sss_profile_desc* p, const char* name);
sss_result check_kernel_desc(sss_context* ctx, const sss_kernel_desc* d, const char* name, bool in_settings);
sss::math::ProfileRequest to_request(const sss_profile_desc& p);
// The burley fields of *p from the math's parameters.
void set_burley(const sss::math::BurleyParameters& b, sss_profile_desc* p);

// A desc of this release or of 0.1-0.3 (legacy_structs.hpp: without the burley fields, which then
// take their defaults) as today's, into *out. Refuses NULL and any other struct_size, named as
// `name` ("profile", "desc", "settings->kernel"). Every entry point that takes a desc reads it so.
sss_result profile_desc_from_caller(sss_context* ctx, const sss_profile_desc* in, const char* name,
                                    sss_profile_desc* out);
sss_result kernel_desc_from_caller(sss_context* ctx, const sss_kernel_desc* in, const char* name,
                                   sss_kernel_desc* out);
sss::math::KernelRequest to_kernel_request(const sss_kernel_desc& d);

// Which fields of an sss_lut_desc a call uses: the diffuse or the shadow ones, and the format.
struct LutUse {
  bool diffuse = true;
  bool texture = false;
};
sss_result check_lut_desc(sss_context* ctx, const sss_lut_desc* desc, LutUse use);

// The frame's viewport (0 width: the whole colour texture) and the host's region inside it, into
// run->viewport, draw_rect and region (the colour's size known).
sss_result frame_rectangles(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run);

}  // namespace sss::api
