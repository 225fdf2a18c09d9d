// A radial diffusion profile as the cross-bilateral mode consumes it: an unscattered share (the
// "spike", left to the unfiltered image) plus a sum of 2D-normalised Gaussians per channel. Every
// profile the module knows is expressed this way, so a new one (a measured material of the kernel
// family) plugs in by producing a SpikeGaussianProfile. Math layer: no GL.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "kernel_request.hpp"
#include "materials.hpp"
#include "radial_profile.hpp"
#include "skin_profile.hpp"

namespace sss::math {

struct SpikeGaussianProfile {
  std::string name;
  std::array<double, 3> spike = {0.0, 0.0, 0.0};  // r, g, b share that is not scattered
  double spike_variance_mm2 = 0.0;               // 0: a true delta; else the narrow Gaussian it stands for
  std::vector<GaussianTerm> terms;               // broad part; per channel, spike + Σ weights = 1
};

// Mikkelsen 2010, Table 1: spike 15/18/20 %, one broad Gaussian per channel of variance
// 2.3/1.4/1.1 mm² (DESIGN.md §5).
SpikeGaussianProfile mikkelsen_profile();

// d'Eon and Luebke's six-Gaussian skin profile with its narrowest term (0.0064 mm²) as the spike,
// as the separable kernel treats it.
SpikeGaussianProfile skin_spike_gaussian_profile();

// The ids of sss_settings.cbf_profile, sss_profile values (sss.h): 0 (d'Eon skin) to 11 (the measured
// materials, as kFittedGaussians Gaussians fitted to the dipole by fit_gaussian_sum, with no spike:
// the fit's narrowest term is a real part of the profile, not the unscattered share) and
// kMikkelsenProfileId. The API layer checks the value with is_spike_gaussian_profile_id.
inline constexpr unsigned kMikkelsenProfileId = 13u;  // SSS_PROFILE_MIKKELSEN_2010
inline constexpr int kFittedGaussians = 4;
bool is_spike_gaussian_profile_id(unsigned id);
SpikeGaussianProfile spike_gaussian_profile(unsigned id);

// SSS_PROFILE_KERNEL: sss_settings.cbf_profile naming the profile of sss_settings.kernel.profile.
// A sum of Gaussians (d'Eon's, any count) is taken as it is, any other profile (a dipole, a table)
// fitted with kFittedGaussians Gaussians; no spike.
inline constexpr unsigned kKernelProfileId = 14u;  // SSS_PROFILE_KERNEL
SpikeGaussianProfile spike_gaussian_profile(const RadialProfile& profile, const std::string& name);
// Any cbf_profile id, kKernelProfileId taking `kernel_profile`.
bool is_cbf_profile_id(unsigned id);
SpikeGaussianProfile cbf_profile(unsigned id, const ProfileRequest& kernel_profile);

// The Gaussians that transmit light through a slab (for the host's transmittance include): the broad
// terms, and the spike when it has a width. Weights as in the profile.
std::vector<GaussianTerm> transmittance_terms(const SpikeGaussianProfile& p);

// The transmittance profile Σ w · exp(-s² / v) at scaled thickness s (JWSG10, as the reference
// shader evaluates it), channel c. The include computes the same sum in GLSL.
double transmittance(const std::vector<GaussianTerm>& terms, int channel, double s);

// The broad part's weighted mean variance of channel c in mm² (Σ w·v / Σ w); 0 when the channel
// has no broad part.
double broad_variance_mm2(const SpikeGaussianProfile& p, int channel);

// The 1D marginal of channel c's broad part (the 2D profile integrated across the line): a sum of
// 1D Gaussians of the same variances. Its integral over [a, b] mm, unnormalised.
double broad_marginal_integral(const SpikeGaussianProfile& p, int channel, double a_mm, double b_mm);

// The radial profile R_c(r) at distance r mm (2D density, 1/mm²), spike excluded.
double broad_profile_2d(const SpikeGaussianProfile& p, int channel, double r_mm);

}  // namespace sss::math
