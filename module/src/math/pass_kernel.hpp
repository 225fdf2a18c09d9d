// The kernel in the shape the passes consume (the GPU shader and its CPU model alike): a list of
// separable terms, each pass's 1D kernel as a footprint table (footprint_kernel.hpp), the sparse tap
// layout, which taps jitter, and each term's depth rule. Built once from the settings, never per
// frame. Math layer: no GL.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "filter_constants.hpp"
#include "kernel_plan.hpp"
#include "kernel_request.hpp"

namespace sss::math {

struct PassTaps {
  // The plan's taps: taps[0] has offset 0 (the centre); the others in increasing offset. Weights may
  // be negative. What sss_kernel_plan reports; the passes read `footprint`.
  std::vector<KernelTap> taps;
  // The pass's 1D kernel for the footprint-aware taps (footprint_kernel.hpp): the family's closed
  // form where it has one, else the taps above spread over their cells.
  FootprintTable footprint;
};

struct PassTerm {
  PassTaps horizontal, vertical;
  // > 0: supplementary §E's depth correction exp(-dz² / 2v) (dz in profile mm) blends each tap
  // towards the centre, in place of the follow-surface ramp. 0: the follow-surface ramp.
  float depth_variance_mm2 = 0.0f;
};

struct PassKernel {
  std::vector<PassTerm> terms;  // 1..SSS_KERNEL_MAX_TERMS
  float reach_mm = 0.0f;        // the largest |offset|: the follow-surface ramp's full blend
  // Every pass runs footprint-aware taps (footprint_kernel.hpp): each pixel's taps on whole pixels,
  // weighed by its footprint, at most `spacing.size()` on either side.
  FootprintLayout layout = FootprintLayout::cubic;  // the plan's
  std::vector<float> spacing;   // footprint_spacing(samples / 2, layout)
  // The first sparse tap that jitters within its cell (footprint_taps); kNoJitter: none.
  int jitter_from = kNoJitter;
  bool jittered() const { return jitter_from != kNoJitter; }
};

// Reorders each pass of `plan` centre first (a zero-weight centre tap is added when the plan has
// no tap at offset 0), takes each pass's footprint table from the plan (or from its taps), moves
// each term's mass into its vertical pass and lets the outermost round(jitter · samples / 2) taps
// on each side jitter (first_jittered_tap). jitter in [0, 1].
PassKernel make_pass_kernel(const KernelPlan& plan, float jitter);

// The kernel the settings describe: eq. (1) from samples, strength and falloff for the separable
// family, else build_kernel_plan(settings.kernel) with settings.samples taps; then jitter. May run an
// optimiser (the fitted families): build it when the settings change, not per frame.
PassKernel build_pass_kernel(const FilterSettings& settings);

// Whether a and b describe the same PassKernel (every input build_pass_kernel reads), so the
// kernel is rebuilt only when one of them changes.
bool same_pass_kernel_inputs(const FilterSettings& a, const FilterSettings& b);

// Deterministic per-pixel noise in [0, 1) for the jittered taps: an integer hash of the pixel, the
// pass axis (0 horizontal, 1 vertical) and the frame's noise index (sss_frame.noise_index: 0 gives
// the pattern of the releases before it), exact in GLSL's 32-bit uint arithmetic too
// (module/shaders/jitter.glsl, which separable_blur.frag and .comp include, must compute the same
// bits: a change here is a change there).
float jitter_noise(int x, int y, int axis, std::uint32_t noise_index);

}  // namespace sss::math
