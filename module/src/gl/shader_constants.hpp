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
// reaches (taps past the cached span read the textures, so any apron gives the same image).
// One line of 128 pixels and one pixel per invocation, in both passes: on an NVIDIA H200 (1080p
// head close-up, 17 taps; before the cache's sanitising, which took it to 0.085 ms:
// docs/benchmarks-gpu-passes.md) that pair took 0.105 ms, against 0.180 ms
// for vertical tiles of 8 columns with four pixels per invocation (whose rows read 64 contiguous
// bytes, which did not make up for a quarter of the invocations running four tap loops each),
// 0.109-0.119 ms for the other one-pixel-per-invocation tiles tried (256 or 512 pixels, 2 or 4
// columns) and 0.22 ms for 64-pixel groups. SSS_LINES > 1 stays supported (shaders.glslang builds
// such a variant) for hardware that prefers it.
struct ComputeTile {
  int segment, lines, apron;
};
inline constexpr int kComputeThreads = 128;
inline constexpr ComputeTile kComputeTiles[2] = {{128, 1, 64}, {128, 1, 64}};  // horizontal, vertical
// Shared memory: a vec4 per cached texel and one uint, within GL 4.3's minimum of 32768 bytes.
inline constexpr int compute_shared_bytes(const ComputeTile& t) { return 16 * t.lines * (t.segment + 2 * t.apron) + 16; }
static_assert(compute_shared_bytes(kComputeTiles[0]) <= 32768 && compute_shared_bytes(kComputeTiles[1]) <= 32768);
static_assert(kComputeTiles[0].segment * kComputeTiles[0].lines % kComputeThreads == 0 &&
              kComputeTiles[1].segment * kComputeTiles[1].lines % kComputeThreads == 0);

// The LUT generator (lut_generate.frag): u_terms[SSS_LUT_MAX_TERMS], the Gaussians of a profile
// it integrates (a profile of more is generated on the CPU), and u_gl[SSS_LUT_ORDER], the
// Gauss–Legendre rule of the CPU generator.
inline constexpr int kLutMaxTerms = 8;
inline constexpr int kLutOrder = math::kLutQuadratureOrder;

}  // namespace sss::gl
