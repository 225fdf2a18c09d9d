// Per-pixel profiles (sss_set_profiles, sss_frame.profile_texture): several materials in one pass
// pair. Each pixel's index picks its profile's kernel and scale; a tap whose index differs from the
// centre's is not taken (its weight stays on the centre, as across a depth step), so no light crosses
// between materials or objects. This file holds what the shaders need per profile, in the layout of
// their uniform block (module/shaders/footprint_taps.glsl, SSS_PROFILE_IDS). Math layer: no GL.
#pragma once

#include <array>
#include <vector>

#include "filter_constants.hpp"
#include "pass_kernel.hpp"

namespace sss::math {

inline constexpr int kMaxProfiles = 16;          // sss.h SSS_MAX_PROFILES
inline constexpr unsigned kProfileIndexMask = 15u;  // index = value & 15; value >> 4 is an object ID
// One profile's table for one pass in the block: the pass's cumulative table (kFootprintEntries
// vec4, rgb used), then (reach in mm, centre delta rgb).
inline constexpr int kProfileTableVectors = kFootprintEntries + 1;

// A profile besides the first (which is the context's settings and kernel).
struct Profile {
  FilterSettings settings;
  PassKernel kernel;
};

// The block's vectors of one pass's table (4 floats each, kProfileTableVectors of them) into
// `out`. A kernel without a table (the whole kernel is the centre delta) gets zeros.
void pack_profile_table(const PassTaps& taps, float* out);

// A profile's per-frame numbers for the pass along `axis` (0 horizontal, 1 vertical), as the
// shader's u_profile[] vector: pixels per profile millimetre at clip w 1; the follow-surface
// factor (or, for a term with the Gaussian depth correction, profile millimetres per world unit);
// 1 / (2v) of that correction (0 without); 0.
std::array<float, 4> profile_pass_vector(const PassConstants& constants, const PassTerm& term, int axis);

}  // namespace sss::math
