// A CPU model of the GPU's cross-bilateral passes (Mikkelsen 2010): the same walk over the surface
// (pass_surface.hpp: per-axis footprint, the vertical pass sheared), the same footprint-aware taps
// (cbf_kernel.hpp), range weights on each tap's distance off the centre's surface, and the RGBA16F
// intermediate. Tests compare the GL result against it to tell shader bugs from approximation
// error. Math layer: no GL.
#pragma once

#include "cbf_kernel.hpp"
#include "cpu_separable_filter.hpp"

namespace sss::math {

// Runs both passes into `out` (RGBA, may not alias image.color). Pixels outside the mask, with
// alpha <= 0, a non-finite colour or an unusable depth keep their input value; neighbours that
// are outside the mask, have alpha <= 0, or a non-finite colour or depth get weight 0.
// `normals` (optional, RGBA per pixel like the normal texture): view-space normals for the
// surface's tangents instead of the depth of the neighbours.
void cpu_cbf_filter(const CbfKernel& kernel, const PassConstants& constants, const CpuFilterImage& image, float* out,
                    const float* normals = nullptr);

}  // namespace sss::math
