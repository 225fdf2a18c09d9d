// The measured materials of the separable SSS supplementary, §G. Math layer: no GL.
#pragma once

#include <array>
#include <string_view>

namespace sss::math {

struct MaterialCoefficients {
  const char* name;
  std::array<double, 3> sigma_a_per_mm;  // absorption, r g b
  std::array<double, 3> sigma_s_per_mm;  // scattering (g = 0, so also the reduced scattering)
  double eta;                            // relative index of refraction
};

inline constexpr int kMaterialCount = 11;

// In the order of §G: apple, chicken1, chicken2, cream, ketchup, marble, potato, skimmilk, skin1,
// skin2, wholemilk (the order of enum sss_material in sss_kernels.h).
const std::array<MaterialCoefficients, kMaterialCount>& measured_materials();

// Index of the material called `name`, or -1.
int material_index(std::string_view name);

}  // namespace sss::math
