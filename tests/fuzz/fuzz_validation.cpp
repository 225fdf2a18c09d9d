// libFuzzer target: parameter validation of the GL-free entry points. The input's first byte picks
// sss_set_settings, sss_set_camera or sss_kernel_separable; the rest are the argument bytes as the
// caller would pass them (a raw sss_settings, sixteen raw floats, or samples + two float[3]).
// Checked: the verdict matches the documented ranges (recomputed here, independently), a rejected
// call changes nothing and names the problem, an accepted one stores exactly what was given and a
// kernel whose channels sum to 1 with finite, non-negative weights.
//
// The context is the library's own struct built without GL (api/context.hpp): sss_set_settings
// and sss_set_camera never call GL, so nothing else is needed.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

#include "api/context.hpp"
#include "api/versioned_structs.hpp"
#include "fuzz_common.hpp"
#include "math/filter_constants.hpp"
#include "math/pass_kernel.hpp"
#include "sss/sss_tools.h"

namespace {

bool unit(float v) { return v >= 0.0f && v <= 1.0f; }

using sss::api::kSettingsSize05;  // 0.3's to 0.5's sss_settings: today's before texturing (0.6)

bool settings_valid(const sss_settings& s) {
  // 0.5's size: today's fields but texturing, which that release did not have (pre-scatter).
  if (s.struct_size != sizeof(sss_settings) && s.struct_size != kSettingsSize05) return false;
  if (s.struct_size == sizeof(sss_settings) && s.texturing > SSS_TEXTURING_PRE_AND_POST_SCATTER) return false;
  if (!(s.world_units_per_mm >= 0.0f && s.world_units_per_mm <= 1e6f)) return false;
  if (!(s.scale >= 0.0f && s.scale <= 1e3f)) return false;
  if (!(s.separable_scale > 0.0f && s.separable_scale <= 100.0f)) return false;
  for (int c = 0; c < 3; ++c) {
    if (!unit(s.strength[c]) || !unit(s.falloff[c])) return false;
  }
  if (s.taps < 3 || s.taps > 65 || s.taps % 2 == 0) return false;
  if ((s.flags & ~SSS_SETTINGS_ALL_FLAGS) != 0) return false;
  if (s.mode != SSS_MODE_SEPARABLE && s.mode != SSS_MODE_CROSS_BILATERAL) return false;
  if (s.cbf_taps < 3 || s.cbf_taps > 65 || s.cbf_taps % 2 == 0) return false;
  if (!(s.cbf_r_max_mm > 0.0f && s.cbf_r_max_mm <= 50.0f)) return false;
  if (!(s.cbf_profile == SSS_PROFILE_MIKKELSEN_2010 || s.cbf_profile == SSS_PROFILE_KERNEL ||
        s.cbf_profile <= SSS_PROFILE_WHOLEMILK)) {
    return false;
  }
  if (!unit(s.jitter)) return false;
  // SSS_PATH_FRAGMENT, _COMPUTE, _AUTO, _FRAGMENT_MASKED.
  if (s.path > SSS_PATH_HALF_RESOLUTION) return false;
  // The kernel desc: NULL, or every field but taps, strength and falloff, whatever the family.
  if (s.kernel == nullptr) return true;
  const sss_kernel_desc& k = *s.kernel;
  // 0.1-0.3's kernel desc (no burley fields, its profile desc 0.3's) is read as that prefix.
  const auto old_profile = static_cast<uint32_t>(offsetof(sss_profile_desc, burley_albedo));
  const bool old = k.struct_size == offsetof(sss_kernel_desc, profile) + old_profile;
  if (old && k.profile.struct_size != old_profile) return false;
  if ((!old && k.struct_size != sizeof(sss_kernel_desc)) || k.family < 0 || k.family >= SSS_KERNEL_FAMILY_COUNT) return false;
  if ((k.flags & ~SSS_KERNEL_ALL_FLAGS) != 0u) return false;
  for (int c = 0; c < 3; ++c) {
    auto positive = [](float v) { return v > 0.0f && v <= 1e4f; };
    if (!positive(k.near_variance_mm2[c]) || !positive(k.far_variance_mm2[c]) || !unit(k.near_weight[c])) return false;
  }
  if (k.rank < 1 || k.rank > 6 || !(k.guide_k >= 0.0f && k.guide_k <= 4.0f)) return false;
  if (!(k.radius_mm >= 0.0f && k.radius_mm <= 1e4f)) return false;
  const sss_profile_desc& p = k.profile;
  if (!old && p.struct_size != sizeof(sss_profile_desc)) return false;
  if ((p.profile < 0 || p.profile > SSS_PROFILE_TABULATED) && p.profile != SSS_PROFILE_BURLEY) return false;
  if (p.profile == SSS_PROFILE_SKIN_DEON && (p.gaussian_count < 1 || p.gaussian_count > 6)) return false;
  if (p.profile == SSS_PROFILE_BURLEY && !old) {  // an old desc's burley fields are the defaults
    for (int c = 0; c < 3; ++c) {
      if (!(p.burley_albedo[c] > 0.0f && p.burley_albedo[c] <= 1.0f)) return false;
      if (!(p.burley_dmfp_mm[c] >= SSS_BURLEY_MIN_DMFP_MM && p.burley_dmfp_mm[c] <= SSS_BURLEY_MAX_DMFP_MM)) return false;
    }
  }
  return p.profile != SSS_PROFILE_TABULATED;  // the fuzzer gives no table: NULL pointers are refused
}

// What sss_set_settings must leave alone when it refuses (FilterSettings holds vectors: no memcmp).
bool same_settings(const sss::math::FilterSettings& a, const sss::math::FilterSettings& b) {
  auto bits = [](float x, float y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  return bits(a.world_units_per_mm, b.world_units_per_mm) && bits(a.scale, b.scale) &&
         bits(a.separable_scale, b.separable_scale) && a.strength == b.strength && a.falloff == b.falloff && a.samples == b.samples &&
         a.follow_surface == b.follow_surface && a.cross_bilateral == b.cross_bilateral && a.cbf_taps == b.cbf_taps &&
         bits(a.cbf_r_max_mm, b.cbf_r_max_mm) && a.cbf_profile == b.cbf_profile && a.path == b.path &&
         a.auto_half_resolution == b.auto_half_resolution &&
         sss::math::same_pass_kernel_inputs(a, b);
}

void check_kernel(const float* taps, int n) {
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const float w = taps[i * 4 + c];
      SSS_FUZZ_CHECK(std::isfinite(w) && w >= 0.0f);
      sum += w;
    }
    SSS_FUZZ_CHECK(std::fabs(sum - 1.0) <= 1e-6);
  }
  SSS_FUZZ_CHECK(taps[3] == 0.0f);
}

void fuzz_settings(sss_context* ctx, sss_fuzz::Bytes& in) {
  sss_settings s = in.take<sss_settings>();
  if (in.take<uint8_t>() & 1) s.struct_size = sizeof s;  // half the time a well-formed header
  // Another release's size would have the library read that release's layout, longer than s.
  if (s.struct_size == 184u || s.struct_size == 192u) s.struct_size = 1u;
  // 0.5's size reads today's fields up to texturing, which then stays pre-scatter.
  if (s.struct_size == kSettingsSize05) s.texturing = SSS_TEXTURING_PRE_SCATTER;
  // The kernel desc settings.kernel points at: well-formed headers half the time; no table (a fuzzer
  // cannot invent memory for the pointers: a tabulated profile must then be refused for its NULL
  // table); and no fitted family (the guided fit and a measured material's Gaussian fit run an
  // optimiser, far too slow per input): those map to the SVD and to skin.
  sss_kernel_desc kernel = in.take<sss_kernel_desc>();
  s.kernel = (in.take<uint8_t>() & 3) == 0 ? nullptr : &kernel;
  if (in.take<uint8_t>() & 1) {
    kernel.struct_size = sizeof kernel;
    kernel.profile.struct_size = sizeof kernel.profile;
  }
  kernel.profile.table_radius_mm = nullptr;
  kernel.profile.table_rgb = nullptr;
  if (kernel.family == SSS_KERNEL_GUIDED) kernel.family = SSS_KERNEL_SVD;
  if (kernel.family == SSS_KERNEL_SUM_OF_GAUSSIANS && kernel.profile.profile != SSS_PROFILE_TABULATED) {
    kernel.profile.profile = SSS_PROFILE_SKIN_DEON;
  }
  const sss::math::FilterSettings before = ctx->settings;
  const sss_result r = sss_set_settings(ctx, &s);
  const bool valid = settings_valid(s);
  SSS_FUZZ_CHECK(r == (valid ? SSS_OK : SSS_ERROR_INVALID_ARGUMENT));
  if (!valid) {
    SSS_FUZZ_CHECK(same_settings(ctx->settings, before));
    SSS_FUZZ_CHECK(std::strstr(sss_last_error(ctx), "SSS_ERROR_INVALID_ARGUMENT") != nullptr);
    return;
  }
  sss_settings now;
  now.struct_size = sizeof now;
  SSS_FUZZ_CHECK(sss_get_settings(ctx, &now) == SSS_OK);
  SSS_FUZZ_CHECK(std::memcmp(&now.world_units_per_mm, &s.world_units_per_mm, sizeof(float)) == 0);
  SSS_FUZZ_CHECK(std::memcmp(&now.scale, &s.scale, sizeof(float)) == 0);
  SSS_FUZZ_CHECK(std::memcmp(&now.separable_scale, &s.separable_scale, sizeof(float)) == 0);
  SSS_FUZZ_CHECK(std::memcmp(now.strength, s.strength, sizeof s.strength) == 0);
  SSS_FUZZ_CHECK(std::memcmp(now.falloff, s.falloff, sizeof s.falloff) == 0);
  SSS_FUZZ_CHECK(now.taps == s.taps && now.flags == s.flags);
  SSS_FUZZ_CHECK(now.mode == s.mode && now.cbf_taps == s.cbf_taps && now.cbf_profile == s.cbf_profile);
  SSS_FUZZ_CHECK(std::memcmp(&now.cbf_r_max_mm, &s.cbf_r_max_mm, sizeof(float)) == 0);
  SSS_FUZZ_CHECK(now.texturing == s.texturing);
  if (s.mode == SSS_MODE_CROSS_BILATERAL) {
    SSS_FUZZ_CHECK(ctx->cbf_kernel.spacing.size() == static_cast<std::size_t>(s.cbf_taps / 2));  // taps a side
  }
  SSS_FUZZ_CHECK(std::memcmp(&now.jitter, &s.jitter, sizeof(float)) == 0 && (now.kernel == nullptr) == (s.kernel == nullptr) &&
                 (s.kernel == nullptr || now.kernel->family == s.kernel->family));
  if (s.kernel == nullptr || s.kernel->family == SSS_KERNEL_SEPARABLE) {  // eq. (1): checked tap by tap
    SSS_FUZZ_CHECK(ctx->kernel.terms.size() == 1 && ctx->kernel.terms[0].horizontal.taps.size() ==
                                                        static_cast<std::size_t>(s.taps));
    std::vector<float> taps;
    for (const auto& t : ctx->kernel.terms[0].horizontal.taps) {
      taps.insert(taps.end(), {t.weight[0], t.weight[1], t.weight[2], t.offset_mm});
    }
    check_kernel(taps.data(), s.taps);
  }
  // Every family: 1..6 terms, finite weights, centre first.
  SSS_FUZZ_CHECK(!ctx->kernel.terms.empty() && ctx->kernel.terms.size() <= SSS_KERNEL_MAX_TERMS);
  for (const auto& term : ctx->kernel.terms) {
    for (const auto* pass : {&term.horizontal, &term.vertical}) {
      SSS_FUZZ_CHECK(!pass->taps.empty() && pass->taps[0].offset_mm == 0.0f);
      for (const auto& t : pass->taps) {
        SSS_FUZZ_CHECK(std::isfinite(t.weight[0]) && std::isfinite(t.weight[1]) && std::isfinite(t.weight[2]));
      }
    }
  }
}

void fuzz_camera(sss_context* ctx, sss_fuzz::Bytes& in) {
  float m[16];
  for (float& v : m) v = in.take<float>();
  const sss::math::Matrix4 before = ctx->projection;
  const sss_result r = sss_set_camera(ctx, m);
  bool finite = true;
  for (float v : m) finite = finite && std::isfinite(v);
  if (r != SSS_OK) {
    SSS_FUZZ_CHECK(r == SSS_ERROR_INVALID_ARGUMENT || r == SSS_ERROR_UNSUPPORTED);
    SSS_FUZZ_CHECK(std::memcmp(ctx->projection.data(), before.data(), sizeof m) == 0);
    SSS_FUZZ_CHECK(std::strlen(sss_last_error(ctx)) > 0);
    if (!finite) SSS_FUZZ_CHECK(r == SSS_ERROR_INVALID_ARGUMENT);
    return;
  }
  SSS_FUZZ_CHECK(finite && m[0] != 0.0f && m[5] != 0.0f);
  SSS_FUZZ_CHECK(m[1] == 0.0f && m[3] == 0.0f && m[4] == 0.0f && m[7] == 0.0f);
  SSS_FUZZ_CHECK(static_cast<double>(m[10]) * m[15] - static_cast<double>(m[14]) * m[11] != 0.0);
  SSS_FUZZ_CHECK(std::memcmp(ctx->projection.data(), m, sizeof m) == 0);
  // The constants a frame would use: never NaN, whatever the viewport.
  sss::math::FrameGeometry g;
  g.texture_width = 1 + in.take<uint16_t>() % 16384;
  g.texture_height = 1 + in.take<uint16_t>() % 16384;
  g.viewport = {0, 0, g.texture_width, g.texture_height};
  const auto k = sss::math::compute_pass_constants(ctx->settings, ctx->projection, g);
  SSS_FUZZ_CHECK(k.pixels_per_mm[0] >= 0.0f && k.pixels_per_mm[1] >= 0.0f);
  SSS_FUZZ_CHECK(k.follow_surface_factor >= 0.0f);
}

void fuzz_kernel_api(sss_fuzz::Bytes& in) {
  const int32_t samples = in.take<int32_t>();
  float strength[3], falloff[3];
  for (float& v : strength) v = in.take<float>();
  for (float& v : falloff) v = in.take<float>();
  const uint8_t nulls = in.take<uint8_t>();
  float out[65 * 4 + 4];
  for (float& v : out) v = -7.0f;
  const float* s = (nulls & 1) ? nullptr : strength;
  const float* f = (nulls & 2) ? nullptr : falloff;
  float* o = (nulls & 4) ? nullptr : out;
  const sss_result r = sss_kernel_separable(samples, s, f, o);
  bool valid = samples >= 3 && samples <= 65 && samples % 2 != 0 && s != nullptr && f != nullptr && o != nullptr;
  for (int c = 0; valid && c < 3; ++c) valid = unit(strength[c]) && unit(falloff[c]);
  SSS_FUZZ_CHECK(r == (valid ? SSS_OK : SSS_ERROR_INVALID_ARGUMENT));
  const int written = valid ? samples * 4 : 0;
  for (int i = written; i < 65 * 4 + 4; ++i) SSS_FUZZ_CHECK(out[i] == -7.0f);
  if (valid) check_kernel(out, samples);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static sss_context* ctx = [] {  // lives for the process, like a host's; as sss_create leaves it
    auto* c = new sss_context;
    c->kernel = sss::math::build_pass_kernel(c->settings);
    sss_default_kernel_desc(&c->kernel_desc);
    return c;
  }();
  sss_fuzz::Bytes in(data, size);
  switch (in.take<uint8_t>() % 3) {
    case 0:
      fuzz_settings(ctx, in);
      break;
    case 1:
      fuzz_camera(ctx, in);
      break;
    default:
      fuzz_kernel_api(in);
      break;
  }
  return 0;
}
