// The three.js package's profiles from flat floats (profile_fields.hpp): shared by the WebAssembly
// (sss_three.cpp) and sss_three_native_apply (web/three/test/native_apply.cpp).
#include "profile_fields.hpp"

namespace sss_three {

sss_result profiles_from_fields(const float* fields, int count, int taps, int follow_surface, int path, float jitter,
                                sss_settings* profiles, sss_kernel_desc* kernels) {
  for (int i = 0; i < count; ++i) {
    const float* f = fields + i * kProfileFloats;
    sss_settings& s = profiles[i];
    sss_default_settings(&s);
    s.world_units_per_mm = f[kWorldUnitsPerMm];
    s.scale = f[kScale];
    for (int c = 0; c < 3; ++c) {
      s.strength[c] = f[kStrengthR + c];
      s.falloff[c] = f[kFalloffR + c];
    }
    s.taps = taps;
    s.flags = follow_surface != 0 ? SSS_FOLLOW_SURFACE : 0u;
    s.path = static_cast<uint32_t>(path);
    s.jitter = jitter;
    // An sss_texturing; what is none (negative, NaN, beyond the enum's range) becomes a value the
    // library names as it refuses it (a float outside uint32_t's range cannot be converted).
    const float texturing = f[kTexturing];
    s.texturing = texturing >= 0.0f && texturing <= 16.0f ? static_cast<uint32_t>(texturing) : 0xFFFFFFFFu;
    const int kind = static_cast<int>(f[kKind]);
    if (kind == kSeparable) continue;  // the default kernel: s.kernel stays NULL
    sss_kernel_desc& k = kernels[i];
    sss_default_kernel_desc(&k);  // also registers the tools' kernel families with the runtime
    k.family = SSS_KERNEL_PREINTEGRATED;
    k.taps = taps;
    k.rank = 1;  // one term: what sss_set_profiles allows with several profiles
    const int profile = static_cast<int>(f[kProfile]);
    if (kind == kMeasured) {
      k.profile.profile = profile;
    } else if (kind == kBurleyMeasured) {
      const sss_result r = sss_profile_burley_from_measured(profile, &k.profile);
      if (r != SSS_OK) return r;
    } else {
      k.profile.profile = SSS_PROFILE_BURLEY;
      for (int c = 0; c < 3; ++c) {
        k.profile.burley_albedo[c] = f[kAlbedoR + c];
        k.profile.burley_dmfp_mm[c] = f[kDmfpR + c];
      }
    }
    s.kernel = &k;
  }
  return SSS_OK;
}

}  // namespace sss_three
