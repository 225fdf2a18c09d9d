// One description of "which kernel from which profile" and the function that builds its plan: what
// the C API (sss_kernels.h) and the settings map onto. Math layer: no GL.
//
// Units: offsets of plans built from a profile are millimetres of that profile (physical mm for the
// skin Gaussians, the dipoles and tables in mm). The eq. (1) kernel's taps are its own kernel
// millimetres divided by separable_scale, so every family's plan is in surface millimetres and one
// screen scale (world_units_per_mm · scale) serves them all.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "burley_profile.hpp"
#include "default_kernel_fit.hpp"
#include "kernel_families.hpp"
#include "separable_kernel.hpp"
#include "radial_profile.hpp"

namespace sss::math {

// sss_tools.h's sss_kernel_family, value for value (the api layer casts one to the other).
enum class KernelFamily { separable, sum_of_gaussians, svd, preintegrated, guided, artist };
// Whether a family builds its plan from the request's profile: every family but eq. (1) and the
// artist model, which are closed forms of their own parameters (cheap to rebuild, nothing to fit,
// no profile to check). The C API's checks, the settings and the kernel cache ask this, so a new
// family is classified here once.
inline bool builds_from_profile(KernelFamily f) { return f != KernelFamily::separable && f != KernelFamily::artist; }

struct ProfileRequest {
  // -1: d'Eon–Luebke skin (the first gaussian_count of its six Gaussians); 0..10: the dipole of
  // measured_materials()[material]; -2: the table below; -3: Burley's normalized diffusion.
  int material = -1;
  int gaussian_count = 6;
  std::vector<double> table_radii_mm;
  std::vector<Rgb> table_values;
  BurleyParameters burley = burley_default_parameters();
};
inline constexpr int kProfileSkin = -1;
inline constexpr int kProfileTable = -2;
inline constexpr int kProfileBurley = -3;

std::unique_ptr<RadialProfile> make_profile(const ProfileRequest& request);
// Whether two requests describe the same profile (every field make_profile reads).
bool same_profile_request(const ProfileRequest& a, const ProfileRequest& b);

inline ArtistModel calibrated_artist_model() {
  ArtistModel m{};
  for (std::size_t c = 0; c < 3; ++c) {
    m.near_variance_mm2[c] = kCalibratedNearVarianceMm2[c];
    m.far_variance_mm2[c] = kCalibratedFarVarianceMm2[c];
    m.near_weight[c] = kCalibratedNearWeight[c];
  }
  return m;
}

struct KernelRequest {
  KernelFamily family = KernelFamily::separable;
  int taps = 17;                 // per pass, odd
  int rank = 1;                  // sum of Gaussians: N Gaussians; SVD: rank N (1..6)
  bool rescale_energy = true;    // SVD: scale to the profile's energy (S.4)
  double guide_k = 1.55;         // guided rank-1: the guide's exponent, [0, 4]
  double radius_mm = 0.0;        // SVD, pre-integrated, guided: grid half-width; 0 = the family's default
                                 // (the profile's extent; guided: guided_radius_mm)
  std::array<float, 3> strength = kTable1Strength;  // separable
  std::array<float, 3> falloff = kTable1Falloff;
  double separable_scale = 1.0;  // separable: kernel millimetres per millimetre of surface
  // The artist model's defaults are its fit to d'Eon's skin (default_kernel_fit.hpp): the hand-set
  // values it had before (near 0.0484 mm², far 1.99/0.567/0.567 mm², near weight .5/.8/.9) spread
  // blue 14 times further from the exact result than doing nothing at 2 mm per pixel.
  ArtistModel artist = calibrated_artist_model();
  ProfileRequest profile;
};

// Builds the plan. Sum of Gaussians on a profile that is not the skin Gaussians fits N Gaussians to
// it first (fit_gaussian_sum). Preconditions (checked by the API layer): the ranges above.
KernelPlan build_kernel_plan(const KernelRequest& request);

// The matrix the SVD, pre-integrated and guided families start from: the profile on a quadratic
// grid of `taps` cells out to radius_mm (or the profile's extent).
ProfileMatrix profile_matrix_for(const RadialProfile& profile, int taps, double radius_mm);

}  // namespace sss::math
