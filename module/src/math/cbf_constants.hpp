// The per-frame numbers of the cross-bilateral passes beyond the separable ones: how to rebuild a
// pixel's view-space position (for the per-axis cosine correction of the footprint) and the world
// size of a profile millimetre. Shared by the shader's uniforms and the CPU model. Math layer.
#pragma once

#include <array>

#include "filter_constants.hpp"

namespace sss::math {

struct CbfConstants {
  // x_view = (ndc_x·w - m8·z - m12) / m0 and y_view = (ndc_y·w - m9·z - m13) / m5 with z = -distance.
  std::array<float, 4> xy_terms = {1.0f, 1.0f, 0.0f, 0.0f};  // m0, m5, m8, m9
  std::array<float, 2> xy_offset = {0.0f, 0.0f};              // m12, m13
  std::array<float, 4> viewport = {0.0f, 0.0f, 1.0f, 1.0f};   // x, y, w, h in pixels
  float world_per_mm = 0.0f;  // world_units_per_mm · scale: world units per profile millimetre at alpha 1
  bool orthographic = false;  // view direction is -Z everywhere (m11 == 0)
};

CbfConstants compute_cbf_constants(const FilterSettings& settings, const Matrix4& projection,
                                   const FrameGeometry& geometry);

// The cosine of the angle between a surface and the view ray, seen in the plane of the pass axis
// and Z (XZ for axis 0, YZ for axis 1): |sin| of the angle between the in-plane tangent `t` and the
// in-plane direction to the eye `e`, both given as (axis component, z). 1 when either is degenerate.
float footprint_cosine(float tx, float tz, float ex, float ez);

}  // namespace sss::math
