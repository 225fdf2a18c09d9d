// The Gaussian terms an exact reference convolves a material's pixels with (the benchmark's
// per-material reference, the demo's heat map): d'Eon's six Gaussians for skin, exactly; for a
// measured material the library's fit of its dipole (sss_profile_transmittance_terms:
// SSS_PROFILE_FIT_GAUSSIANS Gaussians), each channel's weights scaled to sum to 1 as the filter's
// kernels are normalised (the material's albedo is in the irradiance). Header-only: the caller links
// sss::tools.
#pragma once

#include <array>
#include <stdexcept>
#include <string>

#include "math/exact_reference.hpp"
#include "sss/sss_tools.h"

namespace sss_bench {

inline sss::math::GaussianProfile material_profile_terms(int material) {
  if (material == SSS_PROFILE_SKIN_DEON) return sss::math::skin_profile_terms();
  float terms[SSS_PROFILE_MAX_TERMS * 4] = {};
  int32_t count = 0;
  if (sss_profile_transmittance_terms(static_cast<uint32_t>(material), terms, SSS_PROFILE_MAX_TERMS, &count) != SSS_OK) {
    throw std::runtime_error("no Gaussian terms for profile " + std::to_string(material) + ": " + sss_last_error(nullptr));
  }
  sss::math::GaussianProfile profile(static_cast<std::size_t>(count));
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  for (std::size_t t = 0; t < profile.size(); ++t) {
    profile[t].variance_mm2 = terms[t * 4];
    for (std::size_t c = 0; c < 3; ++c) {
      profile[t].weight[c] = terms[t * 4 + 1 + c];
      sum[c] += profile[t].weight[c];
    }
  }
  for (sss::math::GaussianTerm& term : profile) {
    for (std::size_t c = 0; c < 3; ++c) term.weight[c] /= sum[c];
  }
  return profile;
}

}  // namespace sss_bench
