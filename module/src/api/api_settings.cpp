// Settings, camera and the GL-free kernel API: validation and bookkeeping, no GL calls.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <vector>

#include "../math/kernel_fits.hpp"
#include "context.hpp"
#include "validation.hpp"

namespace {

using sss::api::fail;

sss::math::FilterSettings to_filter_settings(const sss_settings& s) {
  sss::math::FilterSettings f;
  f.world_units_per_mm = s.world_units_per_mm;
  f.scale = s.scale;
  f.separable_scale = s.separable_scale;
  f.strength = {s.strength[0], s.strength[1], s.strength[2]};
  f.falloff = {s.falloff[0], s.falloff[1], s.falloff[2]};
  f.samples = s.samples;
  f.follow_surface = (s.flags & SSS_FOLLOW_SURFACE) != 0;
  f.cross_bilateral = s.mode == SSS_MODE_CROSS_BILATERAL;
  f.cbf_taps = s.cbf_taps;
  f.cbf_r_max_mm = s.cbf_r_max_mm;
  f.cbf_profile = s.cbf_profile;
  f.kernel = sss::api::to_kernel_request(s.kernel);
  f.jitter = s.jitter;
  f.path = s.path;
  return f;
}

void from_filter_settings(const sss::math::FilterSettings& f, sss_settings* s) {
  s->world_units_per_mm = f.world_units_per_mm;
  s->scale = f.scale;
  s->separable_scale = f.separable_scale;
  for (int c = 0; c < 3; ++c) {
    s->strength[c] = f.strength[static_cast<std::size_t>(c)];
    s->falloff[c] = f.falloff[static_cast<std::size_t>(c)];
  }
  s->samples = f.samples;
  s->flags = f.follow_surface ? SSS_FOLLOW_SURFACE : 0u;
  s->mode = f.cross_bilateral ? SSS_MODE_CROSS_BILATERAL : SSS_MODE_SEPARABLE;
  s->cbf_taps = f.cbf_taps;
  s->cbf_r_max_mm = f.cbf_r_max_mm;
  s->cbf_profile = f.cbf_profile;
  s->jitter = f.jitter;
  s->path = f.path;
}

// A family that normalises by the profile's energy needs some in every channel (as sss_kernel_plan).
sss_result check_profile_energy(sss_context* ctx, const sss::math::KernelRequest& k) {
  if (k.family == sss::math::KernelFamily::separable || k.family == sss::math::KernelFamily::artist) return SSS_OK;
  const auto total = sss::math::make_profile(k.profile)->integral();
  for (std::size_t c = 0; c < 3; ++c) {
    if (!(total[c] > 0.0)) {
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT,
                  "settings->kernel.profile: channel %d integrates to %g; a kernel needs a positive integral",
                  static_cast<int>(c), total[c]);
    }
  }
  return SSS_OK;
}

static_assert(sss::math::kMikkelsenProfileId == SSS_PROFILE_MIKKELSEN_2010, "one value in sss_kernels.h and the math");
static_assert(sss::math::kKernelProfileId == SSS_PROFILE_KERNEL, "one value in sss_kernels.h and the math");
static_assert(sss::math::kFittedGaussians == SSS_PROFILE_FIT_GAUSSIANS, "one value in sss_kernels.h and the math");
static_assert(sss::math::kMaterialCount == SSS_MATERIAL_WHOLEMILK, "materials 1..11 follow SSS_MATERIAL_SKIN");

// The body of both transmittance-term entry points: `make` builds the cross-bilateral profile.
template <typename Make>
sss_result write_transmittance_terms(Make make, const char* what, float* out_terms, int32_t capacity, int32_t* count) {
  if (out_terms == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_terms is NULL");
  if (count == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "count is NULL");
  std::vector<sss::math::GaussianTerm> terms;
  try {
    terms = sss::math::transmittance_terms(make());
  } catch (const std::bad_alloc&) {
    return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "transmittance terms of %s: out of memory", what);
  } catch (const sss::math::OptimiserUnavailable& e) {
    return fail(nullptr, SSS_ERROR_UNSUPPORTED, "transmittance terms of %s: %s", what, e.what());
  } catch (const std::exception& e) {  // the checks before should leave nothing for the math layer to refuse
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "transmittance terms of %s: %s", what, e.what());
  }
  *count = static_cast<int32_t>(terms.size());
  if (capacity < *count) {
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "capacity = %d: %s has %d terms", capacity, what, *count);
  }
  for (std::size_t i = 0; i < terms.size(); ++i) {
    out_terms[i * 4 + 0] = static_cast<float>(terms[i].variance_mm2);
    for (std::size_t c = 0; c < 3; ++c) out_terms[i * 4 + 1 + c] = static_cast<float>(terms[i].weight[c]);
  }
  return SSS_OK;
}

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
  if (next.cbf_profile == SSS_PROFILE_KERNEL) inputs.request = sss::api::to_request(s.kernel.profile);
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
    } catch (const std::bad_alloc&) {
      return fail(ctx, SSS_ERROR_OUT_OF_MEMORY, "settings->cbf_profile = %u: out of memory building its kernel",
                  next.cbf_profile);
    } catch (const sss::math::OptimiserUnavailable& e) {
      return fail(ctx, SSS_ERROR_UNSUPPORTED, "settings->cbf_profile = %u: %s", next.cbf_profile, e.what());
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

// The separable mode's kernel, rebuilt only when what it is built from changes, and taken from
// ctx->recent_kernels when it was built lately (a fitted family runs an optimiser).
sss_result update_pass_kernel(sss_context* ctx, const sss::math::FilterSettings& next, const sss_settings& s) {
  if (sss::math::same_pass_kernel_inputs(next, ctx->settings)) return SSS_OK;
  if (const sss::math::PassKernel* kept = ctx->recent_kernels.find(next)) {
    ctx->kernel = *kept;
    sss::api::log(ctx, SSS_LOG_DEBUG, "sss_set_settings: the kernel was kept from earlier settings");
  } else {
    const auto start = std::chrono::steady_clock::now();
    try {
      const sss_result r = check_profile_energy(ctx, next.kernel);
      if (r != SSS_OK) return r;
      ctx->kernel = sss::math::build_pass_kernel(next);
      ctx->recent_kernels.keep(next, ctx->kernel);
    } catch (const std::bad_alloc&) {
      return fail(ctx, SSS_ERROR_OUT_OF_MEMORY, "settings->kernel: out of memory building the kernel (family %d)",
                  s.kernel.family);
    } catch (const sss::math::OptimiserUnavailable& e) {
      return fail(ctx, SSS_ERROR_UNSUPPORTED, "settings->kernel (family %d): %s", s.kernel.family, e.what());
    } catch (const std::exception& e) {  // validation should leave nothing for the math layer to refuse
      return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "settings->kernel (family %d): %s", s.kernel.family, e.what());
    }
    char note[160];
    std::snprintf(note, sizeof note, "sss_set_settings: built the kernel (family %d, %d taps) in %.1f ms",
                  s.kernel.family, next.samples, milliseconds_since(start));
    sss::api::log(ctx, SSS_LOG_DEBUG, note);
  }
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
  sss_default_kernel_desc(&s->kernel);
}

SSS_API float sss_world_units_per_mm_from_legacy_width(float width) { return width * (2.0f / 3.0f); }

SSS_API void sss_settings_separable_table1(sss_settings* s) {
  if (s == nullptr) return;
  for (std::size_t c = 0; c < 3; ++c) {
    s->strength[c] = sss::math::kTable1Strength[c];
    s->falloff[c] = sss::math::kTable1Falloff[c];
  }
  s->separable_scale = sss::math::kTable1SeparableScale;
}

SSS_API sss_result sss_set_settings(sss_context* ctx, const sss_settings* s) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  sss_result r = sss::api::check_settings(ctx, s);
  if (r != SSS_OK) return r;
  const sss::math::FilterSettings next = to_filter_settings(*s);
  // Both kernels before anything is replaced: a fit that fails keeps the old settings.
  r = update_cbf_kernel(ctx, next, *s);
  if (r == SSS_OK) r = update_pass_kernel(ctx, next, *s);
  if (r != SSS_OK) return r;
  ctx->settings = next;
  // What sss_get_settings gives back: the desc as given, its table pointing at the context's copy.
  ctx->kernel_desc = s->kernel;
  const sss_profile_desc& profile = s->kernel.profile;
  if (profile.material == SSS_MATERIAL_TABULATED) {
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
  if (s == nullptr) return fail(const_cast<sss_context*>(ctx), SSS_ERROR_INVALID_ARGUMENT, "settings is NULL");
  if (s->struct_size != sizeof(sss_settings)) {
    return fail(const_cast<sss_context*>(ctx), SSS_ERROR_INVALID_ARGUMENT,
                "settings->struct_size = %u: expected sizeof(sss_settings) = %u", s->struct_size,
                static_cast<unsigned>(sizeof(sss_settings)));
  }
  from_filter_settings(ctx->settings, s);
  s->kernel = ctx->kernel_desc;
  return SSS_OK;
}

SSS_API sss_result sss_set_camera(sss_context* ctx, const float projection[16]) {
  if (ctx == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  if (projection == nullptr) return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, "projection is NULL");
  sss::math::Matrix4 m;
  std::memcpy(m.data(), projection, sizeof m);
  std::string why;
  switch (sss::math::check_projection(m, &why)) {
    case sss::math::ProjectionCheck::ok: break;
    case sss::math::ProjectionCheck::invalid: return fail(ctx, SSS_ERROR_INVALID_ARGUMENT, why);
    case sss::math::ProjectionCheck::unsupported: return fail(ctx, SSS_ERROR_UNSUPPORTED, why);
  }
  ctx->projection = m;
  ctx->has_camera = true;
  return SSS_OK;
}

SSS_API sss_result sss_kernel_separable(int32_t samples, const float strength[3], const float falloff[3],
                                        float* out_rgba) {
  sss_result r = sss::api::check_samples(nullptr, samples);
  if (r == SSS_OK) r = sss::api::check_unit_range(nullptr, "strength", strength);
  if (r == SSS_OK) r = sss::api::check_unit_range(nullptr, "falloff", falloff);
  if (r != SSS_OK) return r;
  if (out_rgba == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_rgba is NULL");
  const auto kernel = sss::math::separable_kernel(samples, {strength[0], strength[1], strength[2]},
                                                  {falloff[0], falloff[1], falloff[2]});
  for (std::size_t i = 0; i < kernel.size(); ++i) {
    out_rgba[i * 4 + 0] = kernel[i].weight[0];
    out_rgba[i * 4 + 1] = kernel[i].weight[1];
    out_rgba[i * 4 + 2] = kernel[i].weight[2];
    out_rgba[i * 4 + 3] = kernel[i].offset_mm;
  }
  return SSS_OK;
}

SSS_API sss_result sss_profile_transmittance_terms(uint32_t profile, float* out_terms, int32_t capacity,
                                                   int32_t* count) {
  if (!sss::math::is_spike_gaussian_profile_id(profile)) {
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT,
                "profile = %u: must be SSS_PROFILE_MIKKELSEN_2010 (0x%x) or an sss_material in [%d, %d] (a profile "
                "desc, SSS_PROFILE_KERNEL's, goes to sss_profile_desc_transmittance_terms)",
                profile, SSS_PROFILE_MIKKELSEN_2010, SSS_MATERIAL_SKIN, SSS_MATERIAL_WHOLEMILK);
  }
  char what[48];
  std::snprintf(what, sizeof what, "profile %u", profile);
  return write_transmittance_terms([profile] { return sss::math::spike_gaussian_profile(profile); }, what, out_terms,
                                   capacity, count);
}

SSS_API sss_result sss_profile_desc_transmittance_terms(const sss_profile_desc* profile, float* out_terms,
                                                        int32_t capacity, int32_t* count) {
  const sss_result r = sss::api::check_profile(nullptr, profile, "profile");
  if (r != SSS_OK) return r;
  const sss::math::ProfileRequest request = sss::api::to_request(*profile);
  return write_transmittance_terms(
      [&request] { return sss::math::cbf_profile(sss::math::kKernelProfileId, request); }, "the profile", out_terms,
      capacity, count);
}

}  // extern "C"
