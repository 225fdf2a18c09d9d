// Settings and camera: validation and bookkeeping, no GL calls.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <vector>

#include "context.hpp"
#include "validation.hpp"
#include "versioned_structs.hpp"
#include "../math/fitters.hpp"
#include "profiles.hpp"

namespace sss::api {

sss::math::FilterSettings to_filter_settings(const sss_settings& s) {
  sss::math::FilterSettings f;
  f.world_units_per_mm = s.world_units_per_mm;
  f.scale = s.scale;
  f.separable_scale = s.separable_scale;
  f.strength = {s.strength[0], s.strength[1], s.strength[2]};
  f.falloff = {s.falloff[0], s.falloff[1], s.falloff[2]};
  f.samples = s.taps;
  f.follow_surface = (s.flags & SSS_FOLLOW_SURFACE) != 0;
  f.auto_half_resolution = (s.flags & SSS_AUTO_HALF_RESOLUTION) != 0;
  f.cross_bilateral = s.mode == SSS_MODE_CROSS_BILATERAL;
  f.cbf_taps = s.cbf_taps;
  f.cbf_r_max_mm = s.cbf_r_max_mm;
  f.cbf_profile = s.cbf_profile;
  if (s.kernel != nullptr) f.kernel = sss::api::to_kernel_request(*s.kernel);
  f.jitter = s.jitter;
  f.path = s.path;
  f.texturing = s.texturing;
  return f;
}

}  // namespace sss::api

namespace {

using sss::api::fail;
using sss::api::to_filter_settings;

void from_filter_settings(const sss::math::FilterSettings& f, sss_settings* s) {
  s->world_units_per_mm = f.world_units_per_mm;
  s->scale = f.scale;
  s->separable_scale = f.separable_scale;
  for (int c = 0; c < 3; ++c) {
    s->strength[c] = f.strength[static_cast<std::size_t>(c)];
    s->falloff[c] = f.falloff[static_cast<std::size_t>(c)];
  }
  s->taps = f.samples;
  s->flags = (f.follow_surface ? SSS_FOLLOW_SURFACE : 0u) | (f.auto_half_resolution ? SSS_AUTO_HALF_RESOLUTION : 0u);
  s->mode = f.cross_bilateral ? SSS_MODE_CROSS_BILATERAL : SSS_MODE_SEPARABLE;
  s->cbf_taps = f.cbf_taps;
  s->cbf_r_max_mm = f.cbf_r_max_mm;
  s->cbf_profile = f.cbf_profile;
  s->jitter = f.jitter;
  s->path = f.path;
  s->texturing = f.texturing;
}

// A family that normalises by the profile's energy needs some in every channel (as sss_kernel_plan).
sss_result check_profile_energy(sss_context* ctx, const sss::math::KernelRequest& k) {
  if (!sss::math::builds_from_profile(k.family)) return SSS_OK;
  const auto total = sss::math::make_profile(k.profile)->integral();
  for (std::size_t c = 0; c < 3; ++c) {
    if (!(total[c] > 0.0)) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                  "settings->kernel->profile: channel %d integrates to %g; a kernel needs a positive integral",
                  static_cast<int>(c), total[c]);
    }
  }
  return SSS_OK;
}

static_assert(sss::math::kMikkelsenProfileId == SSS_PROFILE_MIKKELSEN_2010, "one value in sss.h and the math");
static_assert(sss::math::kKernelProfileId == SSS_PROFILE_KERNEL, "one value in sss.h and the math");
static_assert(sss::math::kMaterialCount == SSS_PROFILE_WHOLEMILK, "materials 1..11 follow SSS_PROFILE_SKIN_DEON");

// How long building a kernel took, for the DEBUG note (the fits are what sss_prepare cannot hide).
double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The cross-bilateral kernel, built lazily (only in that mode) and compared with what it was built
// from, not with the previous settings: the cbf fields may change while the separable mode is
// selected. A measured material's or a table's profile is fitted (kept in ctx->recent_kernels).
sss_result update_cbf_kernel(sss_context* ctx, const sss::math::FilterSettings& next, const sss_settings& s) {
  if (!next.cross_bilateral) return SSS_OK;
  sss::math::CbfKernelInputs inputs;
  inputs.profile = next.cbf_profile;
  if (next.cbf_profile == SSS_PROFILE_KERNEL && s.kernel != nullptr) inputs.request = sss::api::to_request(s.kernel->profile);
  inputs.taps = next.cbf_taps;
  inputs.r_max_mm = next.cbf_r_max_mm;
  if (sss::math::same_cbf_kernel_inputs(inputs, ctx->cbf_kernel_inputs)) return SSS_OK;
  if (const sss::math::CbfKernel* kept = ctx->recent_kernels.find(inputs)) {
    ctx->cbf_kernel = *kept;
    sss::api::log(ctx, SSS_LOG_DEBUG, "sss_set_settings: the cross-bilateral kernel was kept from earlier settings");
  } else {
    const auto start = std::chrono::steady_clock::now();
    try {
      ctx->cbf_kernel = sss::math::cbf_kernel(sss::math::cbf_profile(inputs.profile, inputs.request), inputs.taps,
                                              inputs.r_max_mm);
      ctx->recent_kernels.keep(inputs, ctx->cbf_kernel);
    } catch (const sss::math::FittersMissing& e) {
      return fail(ctx, SSS_ERROR_UNSUPPORTED, "settings->cbf_profile = %u: %s", next.cbf_profile, e.what());
    } catch (const std::bad_alloc&) {
      return fail(ctx, SSS_ERROR_OUT_OF_MEMORY, "settings->cbf_profile = %u: out of memory building its kernel",
                  next.cbf_profile);
    } catch (const std::exception& e) {  // validation should leave nothing for the math layer to refuse
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->cbf_profile = %u: %s", next.cbf_profile, e.what());
    }
    char note[160];
    std::snprintf(note, sizeof note, "sss_set_settings: built the cross-bilateral kernel (profile 0x%x) in %.1f ms",
                  next.cbf_profile, milliseconds_since(start));
    sss::api::log(ctx, SSS_LOG_DEBUG, note);
  }
  ctx->cbf_kernel_inputs = inputs;
  ++ctx->cbf_kernel_revision;
  return SSS_OK;
}

}  // namespace

namespace sss::api {

sss_result build_pass_kernel(sss_context* ctx, const sss::math::FilterSettings& next, sss::math::PassKernel* out) {
  const int family = static_cast<int>(next.kernel.family);
  if (const sss::math::PassKernel* kept = ctx->recent_kernels.find(next)) {
    *out = *kept;
    log(ctx, SSS_LOG_DEBUG, "sss_set_settings: the kernel was kept from earlier settings");
    return SSS_OK;
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    const sss_result r = check_profile_energy(ctx, next.kernel);
    if (r != SSS_OK) return r;
    *out = sss::math::build_pass_kernel(next);
    ctx->recent_kernels.keep(next, *out);
  } catch (const sss::math::FittersMissing& e) {
    return fail(ctx, SSS_ERROR_UNSUPPORTED, "settings->kernel->family = %d: %s", family, e.what());
  } catch (const std::bad_alloc&) {
    return fail(ctx, SSS_ERROR_OUT_OF_MEMORY, "settings->kernel: out of memory building the kernel (family %d)",
                family);
  } catch (const std::exception& e) {  // validation should leave nothing for the math layer to refuse
    return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->kernel (family %d): %s", family, e.what());
  }
  char note[160];
  std::snprintf(note, sizeof note, "sss_set_settings: built the kernel (family %d, %d taps) in %.1f ms", family,
                next.samples, milliseconds_since(start));
  log(ctx, SSS_LOG_DEBUG, note);
  return SSS_OK;
}

}  // namespace sss::api

namespace {

// The separable mode's kernel, rebuilt only when what it is built from changes, and taken from
// ctx->recent_kernels when it was built lately (a fitted family runs an optimiser).
sss_result update_pass_kernel(sss_context* ctx, const sss::math::FilterSettings& next) {
  if (sss::math::same_pass_kernel_inputs(next, ctx->settings)) return SSS_OK;
  sss::math::PassKernel built;
  const sss_result r = sss::api::build_pass_kernel(ctx, next, &built);
  if (r != SSS_OK) return r;
  ctx->kernel = std::move(built);
  ++ctx->kernel_revision;
  return SSS_OK;
}

}  // namespace

extern "C" {

SSS_API void sss_default_settings(sss_settings* s) {
  if (s == nullptr) return;
  const sss::math::FilterSettings d;
  std::memset(s, 0, sizeof *s);
  s->struct_size = sizeof *s;
  from_filter_settings(d, s);
  s->kernel = nullptr;  // eq. (1) from the calibrated strength, falloff and separable_scale
}

SSS_API sss_result sss_set_settings(sss_context* ctx, const sss_settings* given) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  // An earlier release's layout is converted first (versioned_structs.cpp), then checked as today's.
  sss::api::CurrentSettings current;
  sss_result r = sss::api::settings_from_caller(ctx, given, &current);
  if (r != SSS_OK) return r;
  const sss_settings* s = &current.settings;
  r = sss::api::check_settings(ctx, s);
  if (r != SSS_OK) return r;
  const sss::math::FilterSettings next = to_filter_settings(*s);
  // Both kernels before anything is replaced: a fit that fails keeps the old settings.
  r = update_cbf_kernel(ctx, next, *s);
  if (r == SSS_OK) r = update_pass_kernel(ctx, next);
  if (r != SSS_OK) return r;
  ctx->settings = next;
  ctx->extra_profiles.clear();  // one profile: sss_set_profiles(s, 1)
  ++ctx->profiles_revision;
  // What sss_get_settings gives back: the desc as given, its table pointing at the context's copy.
  ctx->has_kernel_desc = s->kernel != nullptr;
  if (s->kernel != nullptr) ctx->kernel_desc = *s->kernel;
  const sss_profile_desc& profile = ctx->kernel_desc.profile;
  if (ctx->has_kernel_desc && profile.profile == SSS_PROFILE_TABULATED) {
    ctx->table_radius_mm.assign(profile.table_radius_mm, profile.table_radius_mm + profile.table_size);
    ctx->table_rgb.assign(profile.table_rgb, profile.table_rgb + 3 * static_cast<std::size_t>(profile.table_size));
    ctx->kernel_desc.profile.table_radius_mm = ctx->table_radius_mm.data();
    ctx->kernel_desc.profile.table_rgb = ctx->table_rgb.data();
  } else {
    ctx->table_radius_mm.clear();
    ctx->table_rgb.clear();
  }
  return SSS_OK;
}

SSS_API sss_result sss_get_settings(const sss_context* ctx, sss_settings* s) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  auto* mutable_ctx = const_cast<sss_context*>(ctx);
  if (s == nullptr) return fail(mutable_ctx, SSS_ERROR_INVALID_ARGUMENT, "settings is NULL");
  sss_settings current;
  std::memset(&current, 0, sizeof current);
  current.struct_size = sizeof current;
  from_filter_settings(ctx->settings, &current);
  current.kernel = ctx->has_kernel_desc ? &ctx->kernel_desc : nullptr;
  return sss::api::settings_to_caller(mutable_ctx, current, s);
}

SSS_API sss_result sss_set_camera(sss_context* ctx, const float projection[16]) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  sss::math::Matrix4 m;
  const sss_result r = sss::api::take_projection(ctx, projection, "", &m);
  if (r != SSS_OK) return r;
  ctx->projection = m;
  ctx->has_camera = true;
  return SSS_OK;
}

SSS_API sss_result sss_get_projection_info(const sss_context* ctx, const sss_projection_query* query,
                                           sss_projection_info* info) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  auto* mutable_ctx = const_cast<sss_context*>(ctx);  // only for the error message
  if (query == nullptr) return fail(mutable_ctx, SSS_ERROR_INVALID_ARGUMENT, "query is NULL");
  if (info == nullptr) return fail(mutable_ctx, SSS_ERROR_INVALID_ARGUMENT, "info is NULL");
  sss_result r = sss::api::check_struct_size(mutable_ctx, "query->struct_size", "sss_projection_query",
                                             query->struct_size,
                                             {{"0.5", static_cast<uint32_t>(sizeof(sss_projection_query))}});
  if (r != SSS_OK) return r;
  r = sss::api::check_struct_size(mutable_ctx, "info->struct_size", "sss_projection_info", info->struct_size,
                                  {{"0.5", static_cast<uint32_t>(sizeof(sss_projection_info))}});
  if (r != SSS_OK) return r;
  if ((query->frame_flags & ~static_cast<uint32_t>(SSS_FRAME_DEPTH_ZERO_TO_ONE)) != 0) {
    return fail(mutable_ctx, SSS_ERROR_INVALID_ARGUMENT,
                "query->frame_flags = 0x%x: only SSS_FRAME_DEPTH_ZERO_TO_ONE (0x1) applies", query->frame_flags);
  }
  if (query->width <= 0 || query->height <= 0) {
    return fail(mutable_ctx, SSS_ERROR_INVALID_ARGUMENT, "query->width = %d, height = %d: both must be > 0",
                query->width, query->height);
  }
  if (!(query->view_distance > 0.0f) || !std::isfinite(query->view_distance)) {
    return fail(mutable_ctx, SSS_ERROR_INVALID_ARGUMENT, "query->view_distance = %g: must be finite and > 0",
                static_cast<double>(query->view_distance));
  }
  sss::math::Matrix4 m = ctx->projection;
  if (query->projection != nullptr) {
    r = sss::api::take_projection(mutable_ctx, query->projection, "query->", &m);
    if (r != SSS_OK) return r;
  } else if (!ctx->has_camera) {
    return fail(mutable_ctx, SSS_ERROR_INVALID_OPERATION,
                "query->projection is NULL and no camera is set: call sss_set_camera or give a projection");
  }
  const sss::math::ProjectionReading reading =
      sss::math::read_projection(m, (query->frame_flags & SSS_FRAME_DEPTH_ZERO_TO_ONE) != 0);
  sss_projection_info out = {};
  out.struct_size = sizeof out;
  out.kind = reading.orthographic ? SSS_PROJECTION_ORTHOGRAPHIC : SSS_PROJECTION_PERSPECTIVE;
  out.flags = (reading.reversed ? SSS_PROJECTION_REVERSED_Z : 0u) | (reading.infinite_far ? SSS_PROJECTION_INFINITE_FAR : 0u);
  out.near_distance = static_cast<float>(reading.near_distance);
  out.far_distance = reading.infinite_far ? INFINITY : static_cast<float>(reading.far_distance);
  const int pixels[2] = {query->width, query->height};
  for (int axis = 0; axis < 2; ++axis) {
    // Millimetres of surface: the world span over the scene's world units per millimetre (0: no
    // millimetre is a world length, so a pixel spans infinitely many).
    const double world = sss::math::world_per_pixel(m, axis, pixels[axis], query->view_distance);
    const double per_mm = ctx->settings.world_units_per_mm;
    out.mm_per_pixel[axis] = per_mm > 0.0 ? static_cast<float>(world / per_mm) : INFINITY;
  }
  *info = out;
  return SSS_OK;
}

}  // extern "C"
