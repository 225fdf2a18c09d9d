// Monte Carlo photon transport in a homogeneous slab (the MCML method of Wang, Jacques and Zheng
// 1995, one layer, isotropic scattering): a pencil beam enters at the origin along the normal, the
// photon packet loses weight μa/μt at each interaction (implicit capture), scatters isotropically,
// meets the boundaries with Fresnel reflection (all-or-none by a random draw, unbiased) and ends by
// Russian roulette (weight < 1e-4, survival 1/10). Escapes through the top surface are tallied on
// a radial grid: the diffuse reflectance profile R_d(r). Lengths in mm, coefficients in mm⁻¹.
#pragma once

#include <cstdint>
#include <vector>

namespace sss::mc {

struct SlabMedium {
  double sigma_a;            // absorption, mm⁻¹
  double sigma_s;            // scattering, mm⁻¹ (g = 0)
  double eta;                // index of the slab; the ambient above and below is 1
  double thickness_mm = 0.0; // 0: semi-infinite
};

struct RadialGrid {
  double dr_mm;
  int bins;
};

struct SlabTally {
  std::uint64_t photons = 0;
  double specular = 0.0;           // weight reflected at the first surface
  double diffuse_reflected = 0.0;  // all weight escaping through the top after entering
  double transmitted = 0.0;        // weight escaping through the bottom
  double absorbed = 0.0;           // weight deposited by implicit capture
  double roulette = 0.0;           // net weight added (+) or removed (−) by roulette (zero on average)
  std::vector<double> reflected_by_bin;  // diffuse reflected weight per radial bin (beyond: dropped)

  // R_d(r) per bin: weight per unit area per incident photon, mm⁻² (ring area π((i+1)² − i²)dr²).
  std::vector<double> profile(const RadialGrid& grid) const;
};

// Simulates `photons` photons on `threads` threads. The photons are cut into fixed chunks, each with
// its own generator seeded from (seed, chunk), and the chunks are summed in order: the result does
// not depend on the thread count.
SlabTally simulate_slab(const SlabMedium& medium, const RadialGrid& grid, std::uint64_t photons, int threads,
                        std::uint64_t seed);

// The supplementary's §F grid for a material: dr = min MFP / 20, bins = ceil(32 · max MFP / dr),
// MFP = 1 / (σa + σs) over the three channels.
RadialGrid supplementary_grid(const double sigma_a[3], const double sigma_s[3]);

}  // namespace sss::mc
