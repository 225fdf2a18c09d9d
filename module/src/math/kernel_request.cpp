#include "kernel_request.hpp"

#include "fitters.hpp"

namespace sss::math {

bool same_profile_request(const ProfileRequest& a, const ProfileRequest& b) {
  return a.material == b.material && a.gaussian_count == b.gaussian_count && a.table_radii_mm == b.table_radii_mm &&
         a.table_values == b.table_values && a.burley.albedo == b.burley.albedo && a.burley.dmfp_mm == b.burley.dmfp_mm;
}

std::unique_ptr<RadialProfile> make_profile(const ProfileRequest& r) {
  if (r.material == kProfileTable) return std::make_unique<TabulatedProfile>(r.table_radii_mm, r.table_values);
  if (r.material == kProfileBurley) return std::make_unique<BurleyProfile>(r.burley);
  if (r.material >= 0 && r.material < kMaterialCount) {
    return std::make_unique<DipoleProfile>(measured_materials()[static_cast<std::size_t>(r.material)]);
  }
  return std::make_unique<GaussianSumProfile>(GaussianSumProfile::skin(r.gaussian_count));
}

ProfileMatrix profile_matrix_for(const RadialProfile& profile, int taps, double radius_mm) {
  const double radius = radius_mm > 0.0 ? radius_mm : profile.extent_mm();
  return discretise_profile(profile, make_tap_grid(taps, radius, TapSpacing::quadratic));
}

KernelPlan build_kernel_plan(const KernelRequest& r) {
  switch (r.family) {
    case KernelFamily::separable:
      return separable_plan(r.taps, r.strength, r.falloff, r.separable_scale);
    case KernelFamily::artist:
      return artist_plan(r.artist, r.taps);
    case KernelFamily::sum_of_gaussians:
      // d'Eon's skin is a sum of Gaussians already; any other profile is fitted (the tools' fitters).
      if (r.profile.material == kProfileSkin) return gaussian_sum_plan(GaussianSumProfile::skin(r.rank), r.taps);
      break;
    default:
      break;
  }
  return fitters("the kernel family (SVD, pre-integrated, guided, or a sum of Gaussians fitted to a profile)")
      .build_plan(r);
}

}  // namespace sss::math
