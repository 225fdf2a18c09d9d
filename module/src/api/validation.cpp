#include "validation.hpp"

#include <cmath>
#include <cstring>
#include <string>

#include "../gl/texture_query.hpp"
#include "../math/spike_gaussian_profile.hpp"

namespace sss::api {

sss_result check_settings(sss_context* ctx, const sss_settings* s) {
  if (s == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings is NULL");
  // Earlier releases' layouts are converted before (versioned_structs.cpp): this is the current one.
  if (s->struct_size != sizeof(sss_settings)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->struct_size = %u: expected sizeof(sss_settings) = %u",
                s->struct_size, static_cast<unsigned>(sizeof(sss_settings)));
  }
  if (!(s->world_units_per_mm >= 0.0f && s->world_units_per_mm <= 1e6f)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->world_units_per_mm = %g: must be finite and in [0, 1e6]",
                static_cast<double>(s->world_units_per_mm));
  }
  if (!(s->scale >= 0.0f && s->scale <= 1e3f)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->scale = %g: must be finite and in [0, 1000]",
                static_cast<double>(s->scale));
  }
  if (!(s->separable_scale > 0.0f && s->separable_scale <= 100.0f)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->separable_scale = %g: must be finite and in (0, 100]",
                static_cast<double>(s->separable_scale));
  }
  sss_result r = check_unit_range(ctx, "settings->strength", s->strength);
  if (r == SSS_OK) r = check_unit_range(ctx, "settings->falloff", s->falloff);
  if (r == SSS_OK) r = check_taps(ctx, "settings->taps", s->taps);
  if (r != SSS_OK) return r;
  if ((s->flags & ~SSS_SETTINGS_ALL_FLAGS) != 0) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->flags = 0x%x has unknown bits 0x%x", s->flags,
                s->flags & ~SSS_SETTINGS_ALL_FLAGS);
  }
  if (s->mode != SSS_MODE_SEPARABLE && s->mode != SSS_MODE_CROSS_BILATERAL) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "settings->mode = %u: must be SSS_MODE_SEPARABLE (0) or SSS_MODE_CROSS_BILATERAL (1)", s->mode);
  }
  if (r == SSS_OK) r = check_taps(ctx, "settings->cbf_taps", s->cbf_taps);
  if (r != SSS_OK) return r;
  if (!(s->cbf_r_max_mm > 0.0f && s->cbf_r_max_mm <= sss::math::kCbfMaxRMaxMm)) {  // also rejects NaN
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->cbf_r_max_mm = %g: must be finite and in (0, %g]",
                static_cast<double>(s->cbf_r_max_mm), static_cast<double>(sss::math::kCbfMaxRMaxMm));
  }
  if (!sss::math::is_cbf_profile_id(s->cbf_profile)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "settings->cbf_profile = %u: must be an sss_profile in [SSS_PROFILE_SKIN_DEON (0), "
                "SSS_PROFILE_WHOLEMILK (%d)], SSS_PROFILE_MIKKELSEN_2010 (%d) or SSS_PROFILE_KERNEL (%d)",
                s->cbf_profile, SSS_PROFILE_WHOLEMILK, SSS_PROFILE_MIKKELSEN_2010, SSS_PROFILE_KERNEL);
  }
  if (!(s->jitter >= 0.0f && s->jitter <= 1.0f)) {  // also rejects NaN
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->jitter = %g: must be finite and in [0, 1]",
                static_cast<double>(s->jitter));
  }
  if (s->path > SSS_PATH_HALF_RESOLUTION) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "settings->path = %u: must be SSS_PATH_FRAGMENT (0), SSS_PATH_COMPUTE (1), SSS_PATH_AUTO (2), "
                "SSS_PATH_FRAGMENT_MASKED (3) or SSS_PATH_HALF_RESOLUTION (4)",
                s->path);
  }
  if (s->texturing > SSS_TEXTURING_PRE_AND_POST_SCATTER) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "settings->texturing = %u: must be SSS_TEXTURING_PRE_SCATTER (0), SSS_TEXTURING_POST_SCATTER (1) or "
                "SSS_TEXTURING_PRE_AND_POST_SCATTER (2)",
                s->texturing);
  }
  // NULL: eq. (1) from the fields above. A kernel desc is checked whole, whatever its family.
  if (s->kernel == nullptr) return SSS_OK;
  return check_kernel_desc(ctx, s->kernel, "settings->kernel->", true);
}

sss_result take_projection(sss_context* ctx, const float* projection, const char* owner, sss::math::Matrix4* out) {
  if (projection == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "%sprojection is NULL", owner);
  sss::math::Matrix4 m;
  std::memcpy(m.data(), projection, sizeof m);
  std::string why;  // "projection[3] = nan is not finite", "projection is singular: ..."
  switch (sss::math::check_projection(m, &why)) {
    case sss::math::ProjectionCheck::ok: break;
    case sss::math::ProjectionCheck::invalid: return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, std::string(owner) + why);
    case sss::math::ProjectionCheck::unsupported: return fail(ctx, SSS_ERROR_UNSUPPORTED, std::string(owner) + why);
  }
  *out = m;
  return SSS_OK;
}

sss_result check_frame(sss_context* ctx, const sss_frame* frame) {
  if (frame == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame is NULL");
  if (frame->struct_size != sizeof(sss_frame)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->struct_size = %u: expected sizeof(sss_frame) = %u",
                frame->struct_size, static_cast<unsigned>(sizeof(sss_frame)));
  }
  if ((frame->flags & ~SSS_FRAME_ALL_FLAGS) != 0) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->flags = 0x%x has unknown bits 0x%x", frame->flags,
                frame->flags & ~SSS_FRAME_ALL_FLAGS);
  }
  const int32_t* vp = frame->viewport;
  const bool whole = vp[0] == 0 && vp[1] == 0 && vp[2] == 0 && vp[3] == 0;
  if (!whole && (vp[0] < 0 || vp[1] < 0 || vp[2] <= 0 || vp[3] <= 0)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->viewport = {%d, %d, %d, %d}: x, y must be >= 0 and width, height > 0 (or all 0)", vp[0],
                vp[1], vp[2], vp[3]);
  }
  const int32_t* rg = frame->region;
  if ((frame->flags & SSS_FRAME_REGION) != 0 && (rg[0] < 0 || rg[1] < 0 || rg[2] < 0 || rg[3] < 0)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->region = {%d, %d, %d, %d}: x, y, width and height must be >= 0 (SSS_FRAME_REGION is set)", rg[0],
                rg[1], rg[2], rg[3]);
  }
  if (frame->debug_view > SSS_DEBUG_VIEW_LAST) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->debug_view = %u: must be an sss_debug_view (0..%u)",
                frame->debug_view, SSS_DEBUG_VIEW_LAST);
  }
  if (frame->debug_view != 0 && frame->output_texture == 0) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->debug_view = %u needs an output_texture (a view never replaces the colour)", frame->debug_view);
  }
  if (frame->debug_view != 0 && (frame->flags & SSS_FRAME_REGION) != 0) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->debug_view = %u with SSS_FRAME_REGION: a view covers the whole viewport", frame->debug_view);
  }
  if (frame->debug_view == SSS_DEBUG_VIEW_TILES && frame->stencil != nullptr) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED,
                "frame->debug_view = %u (SSS_DEBUG_VIEW_TILES) with a stencil: the masked path draws no tiles "
                "where the stencil culls", frame->debug_view);
  }
  if (frame->msaa_depth_resolve > SSS_MSAA_DEPTH_MAX) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->msaa_depth_resolve = %u: must be SSS_MSAA_DEPTH_AVERAGE, _SAMPLE0, _MIN or _MAX (0..3)",
                frame->msaa_depth_resolve);
  }
  if (frame->output_texture != 0 && frame->output_texture == frame->color_texture) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->output_texture = %u is the colour texture: pass 0 to write back in place",
                frame->output_texture);
  }
  if (frame->strength_texture != 0 && frame->strength_texture == frame->color_texture) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->strength_texture = %u is the colour texture: pass 0 to read the strength from its alpha",
                frame->strength_texture);
  }
  if (frame->profile_texture != 0 && frame->profile_texture == frame->color_texture) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->profile_texture = %u is the colour texture",
                frame->profile_texture);
  }
  if (frame->stencil != nullptr && (frame->stencil->ref > 255u || frame->stencil->mask > 255u)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "stencil ref = %u, mask = %u: both must be in [0, 255]",
                frame->stencil->ref, frame->stencil->mask);
  }
  return check_frame_description(ctx, *frame);
}

bool frame_described(const sss_frame& frame) {
  return frame.texture_width != 0 && frame.color_format != 0 && frame.depth_format != 0 &&
         (frame.output_texture == 0 || frame.output_format != 0) &&
         (frame.stencil == nullptr || frame.stencil_format != 0) &&
         (frame.normal_texture == 0 || frame.normal_format != 0) &&
         (frame.strength_texture == 0 || frame.strength_format != 0) &&
         (frame.profile_texture == 0 || frame.profile_format != 0) &&
         (frame.albedo_texture == 0 || frame.albedo_format != 0);
}

sss_result check_frame_description(sss_context* ctx, const sss_frame& frame) {
  const bool no_size = frame.texture_width == 0 && frame.texture_height == 0;
  if (!no_size && (frame.texture_width <= 0 || frame.texture_height <= 0)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->texture_width = %d, texture_height = %d: both must be > 0 (or both 0: not given)",
                frame.texture_width, frame.texture_height);
  }
  namespace gl = sss::gl;
  const auto format = [](std::uint32_t f) { return static_cast<gl::GLint>(f); };
  const auto bad = [ctx](const char* field, std::uint32_t value, const char* expected) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->%s = 0x%04X (%s): expected 0 or %s", field, value,
                gl::format_name(static_cast<gl::GLint>(value)).c_str(), expected);
  };
  if (frame.color_format != 0 && !gl::is_color_format(format(frame.color_format)) &&
      !gl::is_alpha_free_color_format(format(frame.color_format))) {
    return bad("color_format", frame.color_format,
               "GL_RGBA16F (0x881A), GL_RGBA32F (0x8814) or, with strength_texture, GL_R11F_G11F_B10F (0x8C3A)");
  }
  if (frame.profile_format != 0 && !gl::is_profile_format(format(frame.profile_format))) {
    return bad("profile_format", frame.profile_format, "GL_R8UI (0x8232) or GL_R16UI (0x8234)");
  }
  if (frame.albedo_format != 0 && !gl::is_albedo_format(format(frame.albedo_format))) {
    return bad("albedo_format", frame.albedo_format,
               "GL_SRGB8_ALPHA8 (0x8C43), GL_RGBA8 (0x8058) or GL_RGBA16F (0x881A)");
  }
  if (frame.strength_format != 0 && !gl::is_strength_format(format(frame.strength_format))) {
    return bad("strength_format", frame.strength_format, "GL_R8 (0x8229), GL_R16F (0x822D) or GL_R32F (0x822E)");
  }
  if (frame.depth_format != 0 && !gl::is_hardware_depth_format(format(frame.depth_format)) &&
      !gl::is_linear_depth_format(format(frame.depth_format))) {
    return bad("depth_format", frame.depth_format,
               "a GL_DEPTH_COMPONENT* or GL_DEPTH*_STENCIL8 format, or GL_R16F/GL_R32F");
  }
  if (frame.output_format != 0 && !gl::is_color_format(format(frame.output_format))) {
    return bad("output_format", frame.output_format, "GL_RGBA16F (0x881A) or GL_RGBA32F (0x8814)");
  }
  if (frame.normal_format != 0 && !gl::is_color_format(format(frame.normal_format))) {
    return bad("normal_format", frame.normal_format, "GL_RGBA16F (0x881A) or GL_RGBA32F (0x8814)");
  }
  if (frame.stencil_format != 0 && !gl::is_depth_stencil_format(format(frame.stencil_format))) {
    return bad("stencil_format", frame.stencil_format, "GL_DEPTH24_STENCIL8 (0x88F0) or GL_DEPTH32F_STENCIL8 (0x8CAD)");
  }
  if (frame.depth_stencil_mode != 0 && frame.depth_stencil_mode != gl::DEPTH_COMPONENT &&
      frame.depth_stencil_mode != gl::STENCIL_INDEX) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "frame->depth_stencil_mode = 0x%04X: expected 0, GL_DEPTH_COMPONENT (0x1902) or GL_STENCIL_INDEX (0x1901)",
                frame.depth_stencil_mode);
  }
  return SSS_OK;
}

}  // namespace sss::api

namespace sss::api {

namespace {

sss_result check_float(sss_context* ctx, const char* name, float v, float lo, float hi, bool lo_open) {
  const bool ok = lo_open ? (v > lo && v <= hi) : (v >= lo && v <= hi);  // false for NaN
  if (!ok) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->%s = %g: must be finite and in %c%g, %g]", name,
                static_cast<double>(v), lo_open ? '(' : '[', static_cast<double>(lo), static_cast<double>(hi));
  }
  return SSS_OK;
}

}  // namespace

sss_result check_lut_desc(sss_context* ctx, const sss_lut_desc* desc, LutUse use) {
  if (desc == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc is NULL");
  if (desc->struct_size != sizeof(sss_lut_desc)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->struct_size = %u: expected sizeof(sss_lut_desc) = %u",
                desc->struct_size, static_cast<unsigned>(sizeof(sss_lut_desc)));
  }
  for (const auto& [name, v] : {std::pair<const char*, int32_t>{"width", desc->width}, {"height", desc->height}}) {
    if (v < SSS_LUT_MIN_SIZE || v > SSS_LUT_MAX_SIZE) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->%s = %d: must be in [%d, %d]", name, v, SSS_LUT_MIN_SIZE,
                  SSS_LUT_MAX_SIZE);
    }
  }
  if (desc->profile < SSS_PROFILE_SKIN_DEON || desc->profile > SSS_PROFILE_WHOLEMILK) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                "desc->profile = %d: must be an sss_profile in [SSS_PROFILE_SKIN_DEON (0), SSS_PROFILE_WHOLEMILK (%d)]",
                desc->profile, SSS_PROFILE_WHOLEMILK);
  }
  if (desc->threads < 0 || desc->threads > 256) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->threads = %d: must be in [0, 256]", desc->threads);
  }
  if ((desc->flags & ~SSS_LUT_ALL_FLAGS) != 0) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->flags = 0x%x has unknown bits 0x%x", desc->flags,
                desc->flags & ~SSS_LUT_ALL_FLAGS);
  }
  if (use.texture && (desc->format < SSS_LUT_FORMAT_RGBA16F || desc->format > SSS_LUT_FORMAT_RGBA8)) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->format = %d: must be an SSS_LUT_FORMAT_* in [0, 2]",
                desc->format);
  }
  sss_result r = SSS_OK;
  if (use.diffuse) {
    r = check_float(ctx, "curvature_min", desc->curvature_min, 0.0f, 1000.0f, false);
    if (r == SSS_OK) r = check_float(ctx, "curvature_max", desc->curvature_max, 0.0f, 1000.0f, false);
    if (r == SSS_OK && !(desc->curvature_min < desc->curvature_max)) {
      r = fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->curvature_min = %g is not below desc->curvature_max = %g",
               static_cast<double>(desc->curvature_min), static_cast<double>(desc->curvature_max));
    }
  } else {
    r = check_float(ctx, "penumbra_min", desc->penumbra_min, 0.0f, 1e6f, true);
    if (r == SSS_OK) r = check_float(ctx, "penumbra_max", desc->penumbra_max, 0.0f, 1e6f, true);
    if (r == SSS_OK && !(desc->penumbra_min < desc->penumbra_max)) {
      r = fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->penumbra_min = %g is not below desc->penumbra_max = %g",
               static_cast<double>(desc->penumbra_min), static_cast<double>(desc->penumbra_max));
    }
    if (r == SSS_OK) r = check_float(ctx, "world_units_per_mm", desc->world_units_per_mm, 0.0f, 1e6f, true);
    if (r == SSS_OK) r = check_float(ctx, "new_penumbra", desc->new_penumbra, 0.0f, 1.0f, true);
    if (r == SSS_OK && desc->shadow_filter != SSS_LUT_SHADOW_BOX && desc->shadow_filter != SSS_LUT_SHADOW_GAUSSIAN) {
      r = fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "desc->shadow_filter = %d: must be SSS_LUT_SHADOW_BOX (0) or "
               "SSS_LUT_SHADOW_GAUSSIAN (1)", desc->shadow_filter);
    }
  }
  return r;
}

// The viewport (0 width: the whole colour texture) and the host's region inside it.
sss_result frame_rectangles(sss_context* ctx, const sss_frame& frame, gl::FilterRun* run) {
  const int32_t* vp = frame.viewport;
  if (vp[2] == 0) {
    run->viewport = {0, 0, run->color.width, run->color.height};
  } else if (vp[0] + vp[2] > run->color.width || vp[1] + vp[3] > run->color.height) {
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "frame->viewport = {%d, %d, %d, %d} reaches outside the %dx%d colour texture",
                vp[0], vp[1], vp[2], vp[3], run->color.width, run->color.height);
  } else {
    run->viewport = {vp[0], vp[1], vp[2], vp[3]};
  }
  run->draw_rect = run->viewport;
  if ((frame.flags & SSS_FRAME_REGION) != 0) {
    const int32_t* rg = frame.region;
    const std::array<int, 4>& v = run->viewport;
    // In 64 bits: x + width of two large int32 values must not wrap into range.
    const auto end = [](int32_t a, int32_t b) { return static_cast<int64_t>(a) + static_cast<int64_t>(b); };
    if (rg[0] < v[0] || rg[1] < v[1] || end(rg[0], rg[2]) > end(v[0], v[2]) || end(rg[1], rg[3]) > end(v[1], v[3])) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                  "frame->region = {%d, %d, %d, %d} reaches outside the viewport {%d, %d, %d, %d}", rg[0], rg[1], rg[2],
                  rg[3], v[0], v[1], v[2], v[3]);
    }
    run->draw_rect = {rg[0], rg[1], rg[2], rg[3]};
    run->region = true;
  }
  return SSS_OK;
}

}  // namespace sss::api
