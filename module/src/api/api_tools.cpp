// The tools API beside the kernels (sss_tools.h; the tools library): sss_tools_init, the
// transmittance terms, the eq. (1) taps and the legacy conversions. No GL.
#include <cstdio>
#include <exception>
#include <new>
#include <vector>

#include "../math/default_kernel_fit.hpp"
#include "../math/fitters.hpp"
#include "../math/separable_kernel.hpp"
#include "../math/spike_gaussian_profile.hpp"
#include "context.hpp"
#include "internal_exports.hpp"
#include "sss/sss_tools.h"
#include "validation.hpp"

namespace {

using sss::api::fail;

static_assert(sss::math::kFittedGaussians == SSS_PROFILE_FIT_GAUSSIANS, "one value in sss_tools.h and the math");

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
  } catch (const sss::math::FittersMissing& e) {  // a fit in a tools build without NLopt
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

}  // namespace

extern "C" {

SSS_API void sss_tools_init(void) {
  // Both copies of the registry: the runtime library's (through its exported entry point) and, in
  // a shared build, this library's own copy of the math layer (which transmittance terms use).
  sss::math::set_fitters(&sss::math::tool_fitters());
  sss_internal_register_fitters(&sss::math::tool_fitters());
}

SSS_API float sss_world_units_per_mm_from_legacy_width(float width) { return width * (2.0f / 3.0f); }

SSS_API void sss_settings_separable_table1(sss_settings* s) {
  sss_tools_init();
  if (s == nullptr) return;
  for (std::size_t c = 0; c < 3; ++c) {
    s->strength[c] = sss::math::kTable1Strength[c];
    s->falloff[c] = sss::math::kTable1Falloff[c];
  }
  s->separable_scale = sss::math::kTable1SeparableScale;
}

SSS_API sss_result sss_kernel_separable(int32_t taps, const float strength[3], const float falloff[3],
                                        float* out_rgba) {
  sss_tools_init();
  sss_result r = sss::api::check_taps(nullptr, "taps", taps);
  if (r == SSS_OK) r = sss::api::check_unit_range(nullptr, "strength", strength);
  if (r == SSS_OK) r = sss::api::check_unit_range(nullptr, "falloff", falloff);
  if (r != SSS_OK) return r;
  if (out_rgba == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_rgba is NULL");
  const auto kernel = sss::math::separable_kernel(taps, {strength[0], strength[1], strength[2]},
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
  sss_tools_init();
  if (!sss::math::is_spike_gaussian_profile_id(profile)) {
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT,
                "profile = %u: must be SSS_PROFILE_MIKKELSEN_2010 (%d) or an sss_profile in [%d, %d] (a profile "
                "desc, SSS_PROFILE_KERNEL's, goes to sss_profile_desc_transmittance_terms)",
                profile, SSS_PROFILE_MIKKELSEN_2010, SSS_PROFILE_SKIN_DEON, SSS_PROFILE_WHOLEMILK);
  }
  char what[48];
  std::snprintf(what, sizeof what, "profile %u", profile);
  return write_transmittance_terms([profile] { return sss::math::spike_gaussian_profile(profile); }, what, out_terms,
                                   capacity, count);
}

SSS_API sss_result sss_profile_desc_transmittance_terms(const sss_profile_desc* given, float* out_terms,
                                                        int32_t capacity, int32_t* count) {
  sss_tools_init();
  sss_profile_desc current;
  sss_result r = sss::api::profile_desc_from_caller(nullptr, given, "profile", &current);
  const sss_profile_desc* profile = &current;
  if (r == SSS_OK) r = sss::api::check_profile(nullptr, profile, "profile");
  if (r != SSS_OK) return r;
  const sss::math::ProfileRequest request = sss::api::to_request(*profile);
  return write_transmittance_terms(
      [&request] { return sss::math::cbf_profile(sss::math::kKernelProfileId, request); }, "the profile", out_terms,
      capacity, count);
}

}  // extern "C"
