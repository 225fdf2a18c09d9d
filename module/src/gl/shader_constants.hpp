// The sizes the shaders are compiled with. Each is defined once, in C++, and reaches the shaders
// only as a #define the module writes (shader_variants.cpp), so neither the shaders nor the
// validation test (shaders.glslang, which compiles what the module assembles) repeats a number.
#pragma once

#include "../math/footprint_kernel.hpp"
#include "../math/preintegrated_lut.hpp"
#include "sss/sss_common.h"

namespace sss::gl {

// The separable blur's tables: u_cdf[SSS_CDF_ENTRIES] (vec4) and u_spacing[SSS_MAX_HALF_TAPS]
// (floats, a vector each at worst) stay within ES 3.0's 224 fragment uniform vectors with the rest.
inline constexpr int kCdfEntries = math::kFootprintEntries;
inline constexpr int kMaxHalfTaps = math::kMaxFootprintHalfTaps;

// Pixels a compute work group writes along a pass's axis, and those it caches on each side of
// them (separable_blur.comp SSS_SEGMENT, SSS_APRON): taps up to the apron away read shared memory.
constexpr int kComputeSegment = 128;
constexpr int kComputeApron = 64;

// The cross-bilateral blur's u_kernel[SSS_MAX_TAPS]: the most taps a pass takes (sss.h).
inline constexpr int kCbfMaxTaps = SSS_MAX_TAPS;

// The LUT generator (lut_generate.frag): u_terms[SSS_LUT_MAX_TERMS], the Gaussians of a profile
// it integrates (a profile of more is generated on the CPU), and u_gl[SSS_LUT_ORDER], the
// Gauss–Legendre rule of the CPU generator.
inline constexpr int kLutMaxTerms = 8;
inline constexpr int kLutOrder = math::kLutQuadratureOrder;

}  // namespace sss::gl
