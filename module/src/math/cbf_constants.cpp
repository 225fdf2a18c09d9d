#include "cbf_constants.hpp"

#include <cmath>

namespace sss::math {

CbfConstants compute_cbf_constants(const FilterSettings& settings, const Matrix4& projection,
                                   const FrameGeometry& geometry) {
  CbfConstants k;
  k.xy_terms = {projection[0], projection[5], projection[8], projection[9]};
  k.xy_offset = {projection[12], projection[13]};
  const auto& vp = geometry.viewport;
  k.viewport = {static_cast<float>(vp[0]), static_cast<float>(vp[1]), static_cast<float>(vp[2]),
                static_cast<float>(vp[3])};
  // The same scale as the separable passes.
  k.world_per_mm = static_cast<float>(world_units_per_profile_mm(settings));
  k.orthographic = projection[11] == 0.0f;
  return k;
}

float footprint_cosine(float tx, float tz, float ex, float ez) {
  const float lt = std::sqrt(tx * tx + tz * tz), le = std::sqrt(ex * ex + ez * ez);
  const float c = std::fabs(tx * ez - tz * ex) / (lt * le);
  return c <= 1.0f ? c : 1.0f;  // NaN (a degenerate direction) and rounding above 1: no correction
}

}  // namespace sss::math
