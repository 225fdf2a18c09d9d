#include "filter_constants.hpp"

#include <cmath>
#include <limits>

#include "separable_kernel.hpp"

namespace sss::math {

namespace {

// The magnitude of v as a float: beyond float's range FLT_MAX, not Inf (v is never NaN here: the
// settings and the projection are finite).
float clamp_to_float(double v) {
  const double a = std::fabs(v);
  return a < static_cast<double>(std::numeric_limits<float>::max()) ? static_cast<float>(a)
                                                                     : std::numeric_limits<float>::max();
}
}  // namespace

double world_units_per_profile_mm(const FilterSettings& settings) {
  return static_cast<double>(settings.world_units_per_mm) * static_cast<double>(settings.scale);
}

PassConstants compute_pass_constants(const FilterSettings& settings, const Matrix4& projection,
                                     const FrameGeometry& geometry, double reach_mm) {
  PassConstants k;
  // In double, then clamped to the float range: a huge projection scale times a large viewport
  // must not overflow to Inf (and Inf times a zero scale to NaN); a finite step too large for the
  // image only puts the taps on its edges (they are clamped to the viewport).
  const double world_per_mm = world_units_per_profile_mm(settings);
  // NDC spans 2 across the viewport, so one NDC unit is half the viewport in pixels. Using each
  // axis' own projection scale and size makes the horizontal pass aspect-correct. A negative scale
  // (a mirrored projection) only flips the tap order of a symmetric kernel: the magnitude is used.
  k.pixels_per_mm[0] = clamp_to_float(static_cast<double>(projection[0]) * 0.5 * geometry.viewport[2] * world_per_mm);
  k.pixels_per_mm[1] = clamp_to_float(static_cast<double>(projection[5]) * 0.5 * geometry.viewport[3] * world_per_mm);
  // Follow-surface: a tap is blended fully back to the centre colour once its depth differs by the
  // kernel's reach, R profile millimetres in world units (the shader also divides by the pixel's
  // alpha, which scales the reach like the taps). The reference shader's 300·(1/tan(fovy/2))·width
  // has units of 1/length²: it matches this only at the scale of the paper's own scene (about 6 mm
  // of reach there) and lets a background 0.5 m behind a metric-scale head bleed in. (A denormal
  // scale gives a factor beyond float's range: FLT_MAX.)
  const double reach = (reach_mm < 0.0 ? kSeparableKernelRangeMm / settings.separable_scale : reach_mm) *
                       world_per_mm;
  k.follow_surface_factor = settings.follow_surface && reach > 0.0 ? clamp_to_float(1.0 / reach) : 0.0f;
  k.mm_per_world = world_per_mm > 0.0 ? clamp_to_float(1.0 / world_per_mm) : std::numeric_limits<float>::max();

  k.linear_depth = geometry.depth == DepthEncoding::linear_distance;
  if (geometry.depth == DepthEncoding::hardware_zero_to_one) {
    k.ndc_scale = 1.0f;
    k.ndc_bias = 0.0f;
  }
  k.depth_terms = {projection[10], projection[11], projection[14], projection[15]};
  set_view_offsets(&k, projection, geometry.viewport);

  clamp_to_rect(&k, geometry.viewport);
  return k;
}

void set_view_offsets(PassConstants* k, const Matrix4& projection, const std::array<int, 4>& viewport) {
  const double m11 = projection[11];
  for (std::size_t a = 0; a < 2; ++a) {
    const double scale = projection[a == 0 ? 0 : 5];  // m[0], m[5]
    const double skew = projection[a == 0 ? 8 : 9];   // m[8], m[9]
    const double size = viewport[2 + a], origin = viewport[a];
    const double span = 2.0 / (scale * size);
    const double bias = (skew + m11 * (1.0 + 2.0 * origin / size)) / scale;
    const bool finite = std::isfinite(span) && std::isfinite(bias) && std::isfinite(-m11 * span);
    k->pixel_span[a] = finite ? static_cast<float>(span) : 0.0f;
    k->slope_scale[a] = finite ? static_cast<float>(-m11 * span) : 0.0f;
    k->slope_bias[a] = finite ? static_cast<float>(bias) : 0.0f;
  }
}

void clamp_to_rect(PassConstants* k, const std::array<int, 4>& rect) {
  k->clamp_min = {static_cast<float>(rect[0]) + 0.5f, static_cast<float>(rect[1]) + 0.5f};
  k->clamp_max = {static_cast<float>(rect[0] + rect[2]) - 0.5f, static_cast<float>(rect[1] + rect[3]) - 0.5f};
}

float linearise_depth(const PassConstants& k, float raw_depth) {
  if (k.linear_depth) return raw_depth;
  const float zn = raw_depth * k.ndc_scale + k.ndc_bias;
  // z_view = (m14 - zn·m15) / (zn·m11 - m10); distance = -z_view.
  return (zn * k.depth_terms[3] - k.depth_terms[2]) / (zn * k.depth_terms[1] - k.depth_terms[0]);
}

float clip_w(const PassConstants& k, float distance) {
  return -k.depth_terms[1] * distance + k.depth_terms[3];
}

}  // namespace sss::math
