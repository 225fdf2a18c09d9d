// A CPU model of the half-resolution passes (half_resolution.hpp; module/src/gl/half_resolution_passes.cpp and
// module/shaders/half_inputs.frag, half_upsample.frag): the same 2x2 reduction, the same passes at
// half size (cpu_separable_filter's model of them), the same upsample and, for the pixels it does
// not serve, the full-size passes. Tests compare the GL result against it. Math layer: no GL; not
// shipped (sss_math only).
#pragma once

#include <cstdint>
#include <vector>

#include "cpu_separable_filter.hpp"

namespace sss::math {

struct CpuHalfResolutionStats {
  long long upsampled = 0;  // pixels the upsample wrote
  long long full_size = 0;  // translucent pixels left to the full-size passes
};

// One-term kernels only (the path's own limit). `kernels`/`constants`: one per profile as in
// cpu_profile_filter; `ids` nullptr (one profile: kernels[0]) or R8UI indices (carried in the
// distances' low byte, as the GL does). `min_reach_pixels`: kHalfResolutionMinReachPixels, or another
// value for the benchmark's study. `result_is_half`: the half-size result target is RGBA16F (the
// intermediate's format: image.intermediate_is_half). image.mask (a host stencil) limits the pixels
// either step writes; the reduction reads alpha alone, as the GL's does. Writes every pixel of `out`.
void cpu_half_resolution_filter(const std::vector<const PassKernel*>& kernels,
                                const std::vector<PassConstants>& constants, const std::uint16_t* ids,
                                const CpuFilterImage& image, float min_reach_pixels, float* out,
                                CpuHalfResolutionStats* stats = nullptr);

}  // namespace sss::math
