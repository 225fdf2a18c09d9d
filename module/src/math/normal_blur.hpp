// A tangent-space normal map blurred by a diffusion profile (Penner and Borshukov §1.5), for the
// blurred normal (N_low) that pre-integrated shading blends per channel. Math layer, CPU, no GL;
// used by tools/blur_normals.cpp and the benchmark's pre-integrated head. Not in the library.
#pragma once

#include <cstdint>
#include <vector>

#include "radial_profile.hpp"

namespace sss::math {

// rgb: width·height·3 bytes of a tangent-space normal map (rgb = n·0.5 + 0.5). Decodes to vectors,
// blurs them linearly (no renormalising in between: Kilgard's linear normal filtering, which the
// paper adopts) with channel `channel` of the profile at `texel_mm` mm per texel, renormalises and
// encodes. Sums of Gaussians only (profile.gaussian_terms()), term by term as separable Gaussians
// clamped at the edges; returns an empty vector for other profiles.
std::vector<std::uint8_t> blur_normal_map(const std::vector<std::uint8_t>& rgb, int width, int height,
                                          double texel_mm, const RadialProfile& profile, int channel);

// Each channel's RMS scattering radius over that of `channel`, capped at 1: how far each colour's
// normal goes from the sharp towards the blurred map (1, 0.22, 0.13 for skin over red).
std::array<double, 3> normal_blend_factors(const RadialProfile& profile, int channel);

}  // namespace sss::math
