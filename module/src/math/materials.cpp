#include "materials.hpp"

namespace sss::math {

const std::array<MaterialCoefficients, kMaterialCount>& measured_materials() {
  // Jimenez et al., "Separable Subsurface Scattering", supplementary material §G (tables G.1-G.11),
  // which take them from Jensen, Marschner, Levoy, Hanrahan, "A Practical Model for Subsurface
  // Light Transport", SIGGRAPH 2001. σa, σs in mm⁻¹ per RGB channel; g = 0 for all.
  static const std::array<MaterialCoefficients, kMaterialCount> table = {{
      {"apple", {0.0030, 0.0034, 0.0460}, {2.2900, 2.3900, 1.9700}, 1.3},
      {"chicken1", {0.0150, 0.0770, 0.1900}, {0.1500, 0.2100, 0.3800}, 1.3},
      {"chicken2", {0.0180, 0.0880, 0.2000}, {0.1900, 0.2500, 0.3200}, 1.3},
      {"cream", {0.0002, 0.0028, 0.0163}, {7.3800, 5.4700, 3.1500}, 1.3},
      {"ketchup", {0.0610, 0.9700, 1.4500}, {0.1800, 0.0700, 0.0300}, 1.3},
      {"marble", {0.0021, 0.0041, 0.0071}, {2.1900, 2.6200, 3.0000}, 1.5},
      {"potato", {0.0024, 0.0090, 0.1200}, {0.6800, 0.7000, 0.5500}, 1.3},
      {"skimmilk", {0.0014, 0.0025, 0.0142}, {0.7000, 1.2200, 1.9000}, 1.3},
      {"skin1", {0.0320, 0.1700, 0.4800}, {0.7400, 0.8800, 1.0100}, 1.3},
      {"skin2", {0.0130, 0.0700, 0.1450}, {1.0900, 1.5900, 1.7900}, 1.3},
      {"wholemilk", {0.0011, 0.0024, 0.0140}, {2.5500, 3.2100, 3.7700}, 1.3},
  }};
  return table;
}

int material_index(std::string_view name) {
  const auto& t = measured_materials();
  for (int i = 0; i < kMaterialCount; ++i) {
    if (name == t[static_cast<std::size_t>(i)].name) return i;
  }
  return -1;
}

}  // namespace sss::math
