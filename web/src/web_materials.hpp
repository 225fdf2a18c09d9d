// The page's "material" control: the library's measured materials (sss_kernels.h, Jensen et al.
// 2001 as dipole profiles) through a kernel family that needs no optimiser, so the WebAssembly
// build (no NLopt) runs them all: the pre-integrated rank-1 kernel (supplementary S.5-S.6, Eigen
// only). Entry 0 is the library's default: eq. (1) fitted to d'Eon's skin.
#pragma once

#include <sss/sss.h>

namespace web {

struct Material {
  const char* label;
  int32_t family;    // sss_kernel_family
  int32_t material;  // sss_material
};

inline constexpr Material kMaterials[] = {
    {"skin (the default: eq. (1), d'Eon's skin)", SSS_KERNEL_SEPARABLE, SSS_MATERIAL_SKIN},
    {"skin, measured (Jensen skin1)", SSS_KERNEL_PREINTEGRATED, SSS_MATERIAL_SKIN1},
    {"marble", SSS_KERNEL_PREINTEGRATED, SSS_MATERIAL_MARBLE},
    {"skim milk", SSS_KERNEL_PREINTEGRATED, SSS_MATERIAL_SKIMMILK},
    {"whole milk", SSS_KERNEL_PREINTEGRATED, SSS_MATERIAL_WHOLEMILK},
    {"ketchup", SSS_KERNEL_PREINTEGRATED, SSS_MATERIAL_KETCHUP},
    {"apple", SSS_KERNEL_PREINTEGRATED, SSS_MATERIAL_APPLE},
    {"potato", SSS_KERNEL_PREINTEGRATED, SSS_MATERIAL_POTATO},
};
inline constexpr int kMaterialCount = static_cast<int>(sizeof kMaterials / sizeof kMaterials[0]);

// Sets s->kernel for the entry (index checked by the caller), the other kernel fields at their defaults.
inline void apply_material(int index, sss_settings* s) {
  sss_default_kernel_desc(&s->kernel);
  s->kernel.family = kMaterials[index].family;
  s->kernel.profile.material = kMaterials[index].material;
}

}  // namespace web
