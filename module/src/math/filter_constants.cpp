#include "filter_constants.hpp"

#include "separable_kernel.hpp"

namespace sss::math {

namespace {
// One profile millimetre spans 2/3 of `width` world units: the reference shader divides its step
// by 3 for offsets that reach ±3 mm over a texture-space span of 2 (NDC).
constexpr float kWorldUnitsPerMmPerWidth = 2.0f / 3.0f;
}  // namespace

PassConstants compute_pass_constants(const FilterSettings& settings, const Matrix4& projection,
                                     const FrameGeometry& geometry) {
  PassConstants k;
  const float world_per_mm = settings.width * kWorldUnitsPerMmPerWidth;
  // NDC spans 2 across the viewport, so one NDC unit is half the viewport in pixels. Using each
  // axis' own projection scale and size makes the horizontal pass aspect-correct.
  k.pixels_per_mm[0] = projection[0] * 0.5f * static_cast<float>(geometry.viewport[2]) * world_per_mm;
  k.pixels_per_mm[1] = projection[5] * 0.5f * static_cast<float>(geometry.viewport[3]) * world_per_mm;
  // A negative scale (a mirrored projection) only flips the tap order of a symmetric kernel.
  if (k.pixels_per_mm[0] < 0.0f) k.pixels_per_mm[0] = -k.pixels_per_mm[0];
  if (k.pixels_per_mm[1] < 0.0f) k.pixels_per_mm[1] = -k.pixels_per_mm[1];
  // Follow-surface: a tap is blended fully back to the centre colour once its depth differs by the
  // kernel's reach, R profile millimetres in world units (the shader also divides by the pixel's
  // alpha, which scales the reach like the taps). The reference shader's 300·(1/tan(fovy/2))·width
  // has units of 1/length²: it matches this only at the scale of the paper's own scene (about 6 mm
  // of reach there) and lets a background 0.5 m behind a metric-scale head bleed in.
  const float reach = static_cast<float>(separable_kernel_range_mm(settings.samples)) * world_per_mm;
  k.follow_surface_factor = settings.follow_surface && reach > 0.0f ? 1.0f / reach : 0.0f;

  k.linear_depth = geometry.depth == DepthEncoding::linear_distance;
  if (geometry.depth == DepthEncoding::hardware_zero_to_one) {
    k.ndc_scale = 1.0f;
    k.ndc_bias = 0.0f;
  }
  k.depth_terms = {projection[10], projection[11], projection[14], projection[15]};

  const auto& vp = geometry.viewport;
  k.clamp_min = {static_cast<float>(vp[0]) + 0.5f, static_cast<float>(vp[1]) + 0.5f};
  k.clamp_max = {static_cast<float>(vp[0] + vp[2]) - 0.5f, static_cast<float>(vp[1] + vp[3]) - 0.5f};
  return k;
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
