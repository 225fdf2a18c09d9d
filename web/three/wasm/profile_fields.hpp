// The profiles of the three.js package as flat floats (web/three, docs/three.md): how
// sss3_set_profiles (sss_three.cpp, the WebAssembly) and sss_three_native_apply
// (web/three/test/native_apply.cpp, natively) turn the scratch buffer that sss-three.js fills into
// sss_settings and their kernels: both sides build the kernels by this code. No Emscripten here.
#ifndef SSS_THREE_PROFILE_FIELDS_HPP
#define SSS_THREE_PROFILE_FIELDS_HPP

#include <sss/sss.h>
#include <sss/sss_tools.h>

namespace sss_three {

// How a profile's kernel is chosen; the numbers are part of the contract with sss-three.js
// (PROFILE_KIND there). None needs a fit (NLopt, which the WebAssembly build lacks): the default
// kernel is the runtime's, the pre-integrated family is an SVD of the profile, and
// sss_profile_burley_from_measured looks the parameters up.
enum ProfileKind : int {
  kSeparable = 0,      // eq. (1) fitted to d'Eon's skin: the library's default kernel (settings.kernel NULL)
  kMeasured = 1,       // a measured material (Jensen et al. 2001's dipole) through the pre-integrated kernel
  kBurleyMeasured = 2, // Burley's normalized diffusion with a measured material's published parameters
  kBurley = 3          // Burley's normalized diffusion with the caller's albedo and mean free path
};

// The floats of one profile in the scratch buffer sss-three.js fills (PROFILE_FLOATS there).
enum ProfileField : int {
  kKind = 0, kProfile, kWorldUnitsPerMm, kScale, kStrengthR, kStrengthG, kStrengthB, kFalloffR, kFalloffG,
  kFalloffB, kAlbedoR, kAlbedoG, kAlbedoB, kDmfpR, kDmfpG, kDmfpB,
  kTexturing,  // sss_settings.texturing (an sss_texturing; -1: a name the pass does not know)
  kProfileFloats
};

// profiles[0..count) (count in [1, SSS_MAX_PROFILES]) from `count` profiles of kProfileFloats floats
// each at `fields` (values as the caller gave them: sss_set_profiles judges them), with the settings
// every profile shares; a profile with a kernel points at kernels[i], which must outlive the
// sss_set_profiles call. SSS_OK, or the tools' failure (its message: sss_last_error(NULL)).
sss_result profiles_from_fields(const float* fields, int count, int taps, int follow_surface, int path, float jitter,
                                sss_settings* profiles, sss_kernel_desc* kernels);

}  // namespace sss_three

#endif
