// The GL-free kernel and profile API (sss_tools.h; the tools library): argument checks, then the
// math layer's build_kernel_plan / profiles. No GL calls, no context: messages go to the thread's
// sss_last_error. Every entry point registers the fitters first (sss_tools_init).
#include <cmath>
#include <cstring>
#include <exception>
#include <new>

#include "../math/burley_profile.hpp"
#include "../math/fitters.hpp"
#include "../math/kernel_request.hpp"
#include "../math/materials.hpp"
#include "context.hpp"
#include "sss/sss_tools.h"
#include "validation.hpp"

namespace {

using sss::api::fail;
using sss::api::check_kernel_desc;
using sss::api::check_profile;
using sss::api::to_request;

bool finite_in(float v, float lo, float hi) { return std::isfinite(v) && v >= lo && v <= hi; }

}  // namespace

extern "C" {

SSS_API void sss_default_profile_desc(sss_profile_desc* p) {
  sss_tools_init();
  if (p != nullptr) sss::api::default_profile_desc(p);
}

SSS_API void sss_default_kernel_desc(sss_kernel_desc* d) {
  sss_tools_init();  // a host that fills its settings.kernel here gets the fitted families registered
  if (d != nullptr) sss::api::default_kernel_desc(d);
}

SSS_API const char* sss_profile_name(int32_t profile) {
  switch (profile) {
    case SSS_PROFILE_SKIN_DEON: return "skin";
    case SSS_PROFILE_TABULATED: return "tabulated";
    case SSS_PROFILE_MIKKELSEN_2010: return "mikkelsen-2010";
    case SSS_PROFILE_KERNEL: return "kernel";
    case SSS_PROFILE_BURLEY: return "burley";
    default: break;
  }
  if (profile < SSS_PROFILE_APPLE || profile > SSS_PROFILE_WHOLEMILK) return nullptr;
  return sss::math::measured_materials()[static_cast<std::size_t>(profile - SSS_PROFILE_APPLE)].name;
}

SSS_API sss_result sss_profile_burley_from_measured(int32_t material, sss_profile_desc* out) {
  sss_tools_init();
  if (out == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out is NULL");
  if (material < SSS_PROFILE_APPLE || material > SSS_PROFILE_WHOLEMILK) {
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT,
                "material = %d: must be a measured material in [SSS_PROFILE_APPLE (%d), SSS_PROFILE_WHOLEMILK (%d)]",
                material, SSS_PROFILE_APPLE, SSS_PROFILE_WHOLEMILK);
  }
  sss::api::default_profile_desc(out);
  out->profile = SSS_PROFILE_BURLEY;
  sss::api::set_burley(
      sss::math::burley_from_material(sss::math::measured_materials()[static_cast<std::size_t>(material - SSS_PROFILE_APPLE)]),
      out);
  return SSS_OK;
}

SSS_API sss_result sss_profile_evaluate(const sss_profile_desc* given, int32_t count, const float* radius_mm,
                                        float* out_rgb) {
  sss_tools_init();
  sss_profile_desc current;
  sss_result r = sss::api::profile_desc_from_caller(nullptr, given, "profile", &current);
  const sss_profile_desc* profile = &current;
  if (r == SSS_OK) r = check_profile(nullptr, profile, "profile");
  if (r != SSS_OK) return r;
  if (count < 1 || count > 100000000) {
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "count = %d: must be in [1, 1e8]", count);
  }
  if (radius_mm == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "radius_mm is NULL");
  if (out_rgb == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_rgb is NULL");
  for (int32_t i = 0; i < count; ++i) {
    if (!finite_in(radius_mm[i], 0.0f, 3.4e38f)) {
      return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "radius_mm[%d] = %g: must be finite and >= 0", i,
                  static_cast<double>(radius_mm[i]));
    }
  }
  try {
    const auto p = sss::math::make_profile(to_request(*profile));
    for (int32_t i = 0; i < count; ++i) {
      const auto v = p->evaluate(radius_mm[i]);
      for (int c = 0; c < 3; ++c) out_rgb[i * 3 + c] = static_cast<float>(v[static_cast<std::size_t>(c)]);
    }
  } catch (const std::bad_alloc&) {
    return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "sss_profile_evaluate: out of memory");
  } catch (const sss::math::FittersMissing& e) {  // a fit in a tools build without NLopt
    return fail(nullptr, SSS_ERROR_UNSUPPORTED, "sss_profile_evaluate: %s", e.what());
  } catch (const std::exception& e) {  // the checks above should leave nothing for the math layer to refuse
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "sss_profile_evaluate: %s", e.what());
  }
  return SSS_OK;
}

SSS_API sss_result sss_profile_integral(const sss_profile_desc* given, float out_rgb[3]) {
  sss_tools_init();
  sss_profile_desc current;
  sss_result r = sss::api::profile_desc_from_caller(nullptr, given, "profile", &current);
  const sss_profile_desc* profile = &current;
  if (r == SSS_OK) r = check_profile(nullptr, profile, "profile");
  if (r != SSS_OK) return r;
  if (out_rgb == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_rgb is NULL");
  try {
    const auto v = sss::math::make_profile(to_request(*profile))->integral();
    for (int c = 0; c < 3; ++c) out_rgb[c] = static_cast<float>(v[static_cast<std::size_t>(c)]);
  } catch (const std::bad_alloc&) {
    return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "sss_profile_integral: out of memory");
  } catch (const sss::math::FittersMissing& e) {  // a fit in a tools build without NLopt
    return fail(nullptr, SSS_ERROR_UNSUPPORTED, "sss_profile_integral: %s", e.what());
  } catch (const std::exception& e) {  // the checks above should leave nothing for the math layer to refuse
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "sss_profile_integral: %s", e.what());
  }
  return SSS_OK;
}

SSS_API sss_result sss_kernel_plan(const sss_kernel_desc* given, int32_t max_terms, float* out_taps,
                                   float* out_depth_variance_mm2, int32_t* out_terms, float* out_reach_mm) {
  sss_tools_init();
  sss_kernel_desc current;
  sss_result r = sss::api::kernel_desc_from_caller(nullptr, given, "desc", &current);
  const sss_kernel_desc* desc = &current;
  if (r == SSS_OK) r = check_kernel_desc(nullptr, desc, "desc->", false);
  if (r != SSS_OK) return r;
  if (out_taps == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_taps is NULL");
  if (out_terms == nullptr) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "out_terms is NULL");
  if (max_terms < 1) return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "max_terms = %d: must be >= 1", max_terms);
  sss::math::KernelPlan plan;
  try {
    sss::math::KernelRequest q = sss::api::to_kernel_request(*desc);
    if (sss::math::builds_from_profile(q.family)) {
      // A kernel normalises each channel by the profile's energy: none there, no kernel.
      const auto total = sss::math::make_profile(q.profile)->integral();
      for (int c = 0; c < 3; ++c) {
        if (!(total[static_cast<std::size_t>(c)] > 0.0)) {
          return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT,
                      "desc->profile: channel %d integrates to %g; a kernel needs a positive integral", c,
                      total[static_cast<std::size_t>(c)]);
        }
      }
    }
    plan = sss::math::build_kernel_plan(q);
  } catch (const std::bad_alloc&) {
    return fail(nullptr, SSS_ERROR_OUT_OF_MEMORY, "sss_kernel_plan: out of memory");
  } catch (const sss::math::FittersMissing& e) {  // a fit in a tools build without NLopt
    return fail(nullptr, SSS_ERROR_UNSUPPORTED, "sss_kernel_plan: %s", e.what());
  } catch (const std::exception& e) {  // the checks above should leave nothing for the math layer to refuse
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "sss_kernel_plan: %s", e.what());
  }
  const auto terms = static_cast<int32_t>(plan.terms.size());
  if (terms > max_terms) {
    *out_terms = terms;
    return fail(nullptr, SSS_ERROR_INVALID_ARGUMENT, "max_terms = %d: this plan has %d terms", max_terms, terms);
  }
  const auto taps = static_cast<std::size_t>(desc->taps);
  for (std::size_t t = 0; t < plan.terms.size(); ++t) {
    const auto& term = plan.terms[t];
    for (std::size_t pass = 0; pass < 2; ++pass) {
      const auto& list = pass == 0 ? term.horizontal : term.vertical;
      for (std::size_t i = 0; i < taps; ++i) {
        float* o = out_taps + ((t * 2 + pass) * taps + i) * 4;
        o[0] = list[i].weight[0];
        o[1] = list[i].weight[1];
        o[2] = list[i].weight[2];
        o[3] = list[i].offset_mm;
      }
    }
    if (out_depth_variance_mm2 != nullptr) out_depth_variance_mm2[t] = term.depth_variance_mm2;
  }
  *out_terms = terms;
  if (out_reach_mm != nullptr) *out_reach_mm = plan.reach_mm;
  return SSS_OK;
}

}  // extern "C"
