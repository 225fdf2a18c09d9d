// The GL-free LUT API: defaults, validation, filling the caller's float array.
#include <cstring>
#include <system_error>
#include <vector>

#include "context.hpp"
#include "lut_inputs.hpp"
#include "validation.hpp"

namespace sss::api {

const sss::math::RadialProfile& lut_profile(const sss_lut_desc& /*desc*/) {
  // SSS_PROFILE_SKIN_DEON is the only profile so far; validation rejects the others.
  return sss::math::deon_skin_profile();
}

sss::math::DiffuseLutDesc diffuse_lut_desc(const sss_lut_desc& desc) {
  sss::math::DiffuseLutDesc d;
  d.width = desc.width;
  d.height = desc.height;
  d.curvature_min_per_mm = desc.curvature_min;
  d.curvature_max_per_mm = desc.curvature_max;
  return d;
}

sss::math::ShadowLutDesc shadow_lut_desc(const sss_lut_desc& desc) {
  sss::math::ShadowLutDesc d;
  d.width = desc.width;
  d.height = desc.height;
  d.penumbra_min = desc.penumbra_min;
  d.penumbra_max = desc.penumbra_max;
  d.world_units_per_mm = desc.world_units_per_mm;
  d.new_penumbra = desc.new_penumbra;
  d.filter = desc.shadow_filter == SSS_LUT_SHADOW_GAUSSIAN ? sss::math::ShadowFilter::gaussian
                                                           : sss::math::ShadowFilter::box;
  return d;
}

}  // namespace sss::api

namespace {

using sss::api::fail;

template <typename Generate>
sss_result fill(const sss_lut_desc* desc, float* out_rgba, size_t out_floats, bool diffuse, Generate generate) {
  sss::api::LutUse use;
  use.diffuse = diffuse;
  const sss_result r = sss::api::check_lut_desc(nullptr, desc, use);
  if (r != SSS_OK) return r;
  if (out_rgba == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_rgba is NULL");
  const size_t needed = 4u * static_cast<size_t>(desc->width) * static_cast<size_t>(desc->height);
  if (out_floats < needed) {
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_floats = %zu: the %dx%d LUT needs %zu floats", out_floats,
                desc->width, desc->height, needed);
  }
  try {
    generate(*desc, out_rgba);
  } catch (const std::system_error& e) {  // std::thread could not start
    return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "starting a generator thread failed: %s", e.what());
  } catch (const std::bad_alloc&) {
    return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "allocation failed while generating the LUT");
  }
  return SSS_OK;
}

}  // namespace

extern "C" {

SSS_API void sss_lut_default_desc(sss_lut_desc* desc) {
  if (desc == nullptr) return;
  std::memset(desc, 0, sizeof *desc);
  const sss::math::DiffuseLutDesc d;
  const sss::math::ShadowLutDesc s;
  desc->struct_size = sizeof *desc;
  desc->width = d.width;
  desc->height = d.height;
  desc->profile = SSS_PROFILE_SKIN_DEON;
  desc->curvature_min = static_cast<float>(d.curvature_min_per_mm);
  desc->curvature_max = static_cast<float>(d.curvature_max_per_mm);
  desc->penumbra_min = static_cast<float>(s.penumbra_min);
  desc->penumbra_max = static_cast<float>(s.penumbra_max);
  desc->world_units_per_mm = static_cast<float>(s.world_units_per_mm);
  desc->new_penumbra = static_cast<float>(s.new_penumbra);
  desc->shadow_filter = SSS_LUT_SHADOW_BOX;
  desc->format = SSS_LUT_FORMAT_RGBA16F;
  desc->threads = 0;
  desc->flags = 0;
}

SSS_API sss_result sss_lut_diffuse_fill(const sss_lut_desc* desc, float* out_rgba, size_t out_floats) {
  return fill(desc, out_rgba, out_floats, true, [](const sss_lut_desc& d, float* out) {
    sss::math::generate_diffuse_lut(sss::api::lut_profile(d), sss::api::diffuse_lut_desc(d), d.threads, out);
  });
}

SSS_API sss_result sss_lut_shadow_fill(const sss_lut_desc* desc, float* out_rgba, size_t out_floats) {
  return fill(desc, out_rgba, out_floats, false, [](const sss_lut_desc& d, float* out) {
    sss::math::generate_shadow_lut(sss::api::lut_profile(d), sss::api::shadow_lut_desc(d), d.threads, out);
  });
}

SSS_API uint64_t sss_lut_generation_count(const sss_context* ctx) {
  return ctx == nullptr ? 0u : ctx->lut_gpu_generations + ctx->lut_data.generations();
}

}  // extern "C"
