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

// The compute path's work groups (separable_blur.comp): kComputeThreads invocations write a tile of
// `lines` rows (horizontal pass) or columns (vertical pass) of `segment` pixels each, and cache the
// tile with up to `apron` pixels on both ends of each line in shared memory (SSS_THREADS,
// SSS_SEGMENT, SSS_LINES, SSS_APRON). A group fills only as much of the apron as its widest kernel
// reaches (taps past the cached span read the textures, so any apron gives the same image). The
// vertical pass's tiles are 8 columns wide so that the invocations that read one row of the tile
// read 8 neighbouring texels (64 bytes of RGBA16F: two whole 32-byte sectors) instead of one
// column's texels a row apart.
struct ComputeTile {
  int segment, lines, apron;
};
inline constexpr int kComputeThreads = 256;
inline constexpr ComputeTile kComputeTiles[2] = {{256, 1, 96}, {128, 8, 56}};  // horizontal, vertical
// Shared memory: a vec4 per cached texel and one uint, within GL 4.3's minimum of 32768 bytes.
inline constexpr int compute_shared_bytes(const ComputeTile& t) { return 16 * t.lines * (t.segment + 2 * t.apron) + 16; }
static_assert(compute_shared_bytes(kComputeTiles[0]) <= 32768 && compute_shared_bytes(kComputeTiles[1]) <= 32768);
static_assert(kComputeTiles[0].segment * kComputeTiles[0].lines % kComputeThreads == 0 &&
              kComputeTiles[1].segment * kComputeTiles[1].lines % kComputeThreads == 0);

// The cross-bilateral blur's u_kernel[SSS_MAX_TAPS]: the most taps a pass takes (sss.h).
inline constexpr int kCbfMaxTaps = SSS_MAX_TAPS;

// The LUT generator (lut_generate.frag): u_terms[SSS_LUT_MAX_TERMS], the Gaussians of a profile
// it integrates (a profile of more is generated on the CPU), and u_gl[SSS_LUT_ORDER], the
// Gauss–Legendre rule of the CPU generator.
inline constexpr int kLutMaxTerms = 8;
inline constexpr int kLutOrder = math::kLutQuadratureOrder;

}  // namespace sss::gl
