// A CPU model of the GPU's cross-bilateral passes (Mikkelsen 2010): the same taps, footprint,
// cosine correction, range weights, nearest-texel fetches and RGBA16F intermediate. Tests compare
// the GL result against it to tell shader bugs from approximation error. Math layer: no GL.
#pragma once

#include "cbf_constants.hpp"
#include "cbf_kernel.hpp"
#include "cpu_separable_filter.hpp"

namespace sss::math {

// Runs both passes into `out` (RGBA, may not alias image.color). Pixels outside the mask, with
// alpha <= 0, a non-finite colour or an unusable depth keep their input value; neighbours that
// are outside the mask, have alpha <= 0, or a non-finite colour or depth get weight 0.
// `normals` (optional, RGBA per pixel like the normal texture): view-space normals for the cosine
// correction instead of the depth of the neighbours.
void cpu_cbf_filter(const CbfKernel& kernel, const PassConstants& constants, const CbfConstants& cbf,
                    const CpuFilterImage& image, float* out, const float* normals = nullptr);

}  // namespace sss::math
