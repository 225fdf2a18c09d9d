// The GL-free LUT API: defaults, validation, filling the caller's float array.
#include <array>
#include <cstring>
#include <memory>
#include <system_error>
#include <vector>

#include "context.hpp"
#include "lut_inputs.hpp"
#include "../math/kernel_request.hpp"
#include "../math/lut_cache.hpp"
#include "../math/materials.hpp"
#include "../math/preintegrated_lut.hpp"
#include "validation.hpp"

namespace sss::api {

static_assert(SSS_PROFILE_SKIN_DEON == 0 && SSS_PROFILE_WHOLEMILK - SSS_PROFILE_APPLE + 1 == sss::math::kMaterialCount,
              "sss_lut_desc.profile takes the sss_profile values from d'Eon's skin to the last measured material");

const sss::math::RadialProfile& lut_profile(const sss_lut_desc& desc) {
  // desc.profile is validated: SSS_PROFILE_SKIN_DEON (the six Gaussians) or a measured material's
  // dipole, built once each (thread-safe static) and kept for the program's life.
  static const auto dipoles = [] {
    std::array<std::unique_ptr<sss::math::RadialProfile>, sss::math::kMaterialCount> all;
    for (int m = 0; m < sss::math::kMaterialCount; ++m) {
      sss::math::ProfileRequest r;
      r.material = m;
      all[static_cast<std::size_t>(m)] = sss::math::make_profile(r);
    }
    return all;
  }();
  if (desc.profile <= SSS_PROFILE_SKIN_DEON || desc.profile > SSS_PROFILE_WHOLEMILK) return sss::math::deon_skin_profile();
  return *dipoles[static_cast<std::size_t>(desc.profile - SSS_PROFILE_APPLE)];
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

// The fill functions' LUTs, kept by the full text of their inputs (not the thread count, which
// changes nothing in the values): a second fill with the same description copies instead of
// generating. Process-wide, since these calls have no context; thread-safe (LutCache's lock).
sss::math::LutCache& fill_cache() {
  static sss::math::LutCache cache(8);
  return cache;
}

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
    const sss::math::LutCache::Data data = fill_cache().get(generate.key(*desc), [&] {
      std::vector<float> values(needed);
      generate(*desc, values.data());
      return values;
    });
    std::memcpy(out_rgba, data->data(), needed * sizeof(float));
  } catch (const std::system_error& e) {  // std::thread could not start
    return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "starting a generator thread failed: %s", e.what());
  } catch (const std::bad_alloc&) {
    return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "allocation failed while generating the LUT");
  }
  return SSS_OK;
}

struct DiffuseGenerator {
  std::string key(const sss_lut_desc& d) const {
    return sss::math::diffuse_lut_key(sss::api::lut_profile(d), sss::api::diffuse_lut_desc(d));
  }
  void operator()(const sss_lut_desc& d, float* out) const {
    sss::math::generate_diffuse_lut(sss::api::lut_profile(d), sss::api::diffuse_lut_desc(d), d.threads, out);
  }
};

struct ShadowGenerator {
  std::string key(const sss_lut_desc& d) const {
    return sss::math::shadow_lut_key(sss::api::lut_profile(d), sss::api::shadow_lut_desc(d));
  }
  void operator()(const sss_lut_desc& d, float* out) const {
    sss::math::generate_shadow_lut(sss::api::lut_profile(d), sss::api::shadow_lut_desc(d), d.threads, out);
  }
};

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
  return fill(desc, out_rgba, out_floats, true, DiffuseGenerator{});
}

SSS_API sss_result sss_lut_shadow_fill(const sss_lut_desc* desc, float* out_rgba, size_t out_floats) {
  return fill(desc, out_rgba, out_floats, false, ShadowGenerator{});
}

SSS_API uint64_t sss_lut_fill_generation_count(void) { return fill_cache().generations(); }

SSS_API uint64_t sss_lut_generation_count(const sss_context* ctx) {
  return ctx == nullptr ? 0u : ctx->lut_gpu_generations + ctx->lut_data.generations();
}

}  // extern "C"
