// The page's "material" control: the library's measured materials (Jensen et al. 2001 as dipole
// profiles, sss_profile in sss.h) through a kernel family of the tools library (sss_tools.h) that
// needs no optimiser, so the WebAssembly build (the tools without NLopt) runs them all: the
// pre-integrated rank-1 kernel (supplementary S.5-S.6, Eigen only). Entry 0 is the library's
// default: eq. (1) fitted to d'Eon's skin (settings.kernel NULL).
#pragma once

#include <sss/sss_tools.h>

namespace web {

struct Material {
  const char* label;
  int32_t family;   // sss_kernel_family
  int32_t profile;  // sss_profile
};

inline constexpr Material kMaterials[] = {
    {"skin (the default: eq. (1), d'Eon's skin)", SSS_KERNEL_SEPARABLE, SSS_PROFILE_SKIN_DEON},
    {"skin, measured (Jensen skin1)", SSS_KERNEL_PREINTEGRATED, SSS_PROFILE_SKIN1},
    {"marble", SSS_KERNEL_PREINTEGRATED, SSS_PROFILE_MARBLE},
    {"skim milk", SSS_KERNEL_PREINTEGRATED, SSS_PROFILE_SKIMMILK},
    {"whole milk", SSS_KERNEL_PREINTEGRATED, SSS_PROFILE_WHOLEMILK},
    {"ketchup", SSS_KERNEL_PREINTEGRATED, SSS_PROFILE_KETCHUP},
    {"apple", SSS_KERNEL_PREINTEGRATED, SSS_PROFILE_APPLE},
    {"potato", SSS_KERNEL_PREINTEGRATED, SSS_PROFILE_POTATO},
};
inline constexpr int kMaterialCount = static_cast<int>(sizeof kMaterials / sizeof kMaterials[0]);

// Points s->kernel at the entry's kernel (index checked by the caller), filled into *storage with
// the other kernel fields at their defaults; entry 0 (eq. (1)) is NULL, the runtime's default.
// sss_set_settings copies the kernel, so *storage need only live through that call.
inline void apply_material(int index, sss_kernel_desc* storage, sss_settings* s) {
  if (kMaterials[index].family == SSS_KERNEL_SEPARABLE) {
    s->kernel = nullptr;
    return;
  }
  sss_default_kernel_desc(storage);  // a sss_tools.h call: registers the tools' kernels (sss_tools_init)
  storage->family = kMaterials[index].family;
  storage->taps = s->taps;
  storage->profile.profile = kMaterials[index].profile;
  s->kernel = storage;
}

}  // namespace web
