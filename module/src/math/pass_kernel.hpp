// The kernel in the shape the passes consume (the GPU shader and its CPU model alike): a list of
// separable terms, each tap list with the centre tap first (the shader weights the pixel's own
// colour with it without a texture fetch), per-tap jitter widths, and each term's depth rule.
// Built once from the settings, never per frame. Math layer: no GL.
#pragma once

#include <array>
#include <vector>

#include "filter_constants.hpp"
#include "kernel_plan.hpp"
#include "kernel_request.hpp"

namespace sss::math {

struct PassTaps {
  // taps[0] has offset 0 (the centre); the others in increasing offset. Weights may be negative.
  std::vector<KernelTap> taps;
  // Per tap, in profile millimetres: the width of the cell the tap stands for when the tap is
  // jittered (its position moves by (noise - 1/2) · width), 0 when it is not. Empty: no jitter.
  std::vector<float> jitter_mm;
};

struct PassTerm {
  PassTaps horizontal, vertical;
  // > 0: supplementary §E's depth correction exp(-dz² / 2v) (dz in profile mm) blends each tap
  // towards the centre, in place of the follow-surface ramp. 0: the follow-surface ramp.
  float depth_variance_mm2 = 0.0f;
};

// Footprint-adaptive filtering (SSS_ADAPTIVE_TAPS): a pixel whose kernel covers few pixels needs
// few taps. Each level serves the pixels whose step, the pixels one profile millimetre spans there
// (the pass's pixels_per_mm · strength / clip w), is at most max_step; the first level that serves
// a pixel is used, and a pixel no level serves runs the full kernel (terms[0]).
struct AdaptiveLevel {
  PassTaps taps;           // eq. (1) with fewer taps over the full kernel's range; no taps: pass through
  float max_step = 0.0f;   // pixels per profile mm
};

// The footprint rules, in pixels: a kernel whose whole range spans less than kPassThroughRadiusPx
// around the centre leaves the pixel as it is: the exact surface convolution keeps almost all of
// such a pixel's light in it, while bilinear taps at sub-pixel offsets would blend in neighbours
// (measured: passing through is closer to the exact reference there than the full kernel).
// Otherwise a level of n taps serves while its mean tap spacing, range / ((n - 1) / 2), stays within
// kLevelSpacingPx. An eighth of a pixel keeps the error at the full kernel's on the benchmark's
// head shots at 1080p (far shot: relative RMSE 0.01301 either way); a quarter let 9 taps serve
// footprints up to a 1-pixel radius and raised the far shot's to 0.01312 (+0.8 % on llvmpipe,
// +1.0 % on an H100), half a pixel cost 6 % on the mid shot, a whole pixel 18 %. With the
// default 17 taps an eighth leaves the pass-through and the full kernel (9 taps would serve only
// what the pass-through takes); 33 taps add 17 up to a 1-pixel radius, 65 taps 17 and 33.
constexpr float kPassThroughRadiusPx = 0.5f;
constexpr float kLevelSpacingPx = 0.125f;
// The tap counts of the levels below the kernel's own (only those smaller than it, and serving a
// larger footprint than the level before, are used; 3 and 5 taps would serve only footprints the
// pass-through already takes, and at an eighth-pixel spacing so would 9).
constexpr int kAdaptiveTapCounts[] = {9, 17, 33};
constexpr int kMaxAdaptiveLevels = 1 + static_cast<int>(sizeof kAdaptiveTapCounts / sizeof kAdaptiveTapCounts[0]);

struct PassKernel {
  std::vector<PassTerm> terms;  // 1..SSS_KERNEL_MAX_TERMS
  float reach_mm = 0.0f;        // the largest |offset|: the follow-surface ramp's full blend
  bool jittered = false;        // some tap has a jitter width
  // Empty unless SSS_ADAPTIVE_TAPS is on and the kernel is eq. (1) without jitter (one term, the
  // same taps on both axes): in increasing max_step, the pass-through level first.
  std::vector<AdaptiveLevel> adaptive;
};

// The levels of eq. (1) with `samples` taps: pass-through, then every count of kAdaptiveTapCounts
// below `samples` that serves a larger footprint than the level before it, each over
// separable_kernel_range_mm(samples).
std::vector<AdaptiveLevel> adaptive_levels(int samples, const std::array<float, 3>& strength,
                                           const std::array<float, 3>& falloff);

// The taps a pixel with this step runs: a level's, the full kernel's (`full`), or nullptr to pass
// the pixel through. The shader makes the same choice (separable_blur.frag, SSS_ADAPTIVE).
const PassTaps* adaptive_taps(const std::vector<AdaptiveLevel>& levels, const PassTaps& full, float step);

// Reorders each pass of `plan` centre first (a zero-weight centre tap is added when the plan has
// no tap at offset 0) and gives the outermost round(jitter · taps) taps of every pass (ties at equal
// |offset| both in or both out) a jitter width: the distance between the midpoints to their
// neighbours (the outer edge mirrors the inner one). jitter in [0, 1].
PassKernel make_pass_kernel(const KernelPlan& plan, float jitter);

// The kernel the settings describe: eq. (1) from samples, strength and falloff for the separable
// family, else build_kernel_plan(settings.kernel) with settings.samples taps; then jitter. May run an
// optimiser (the fitted families): build it when the settings change, not per frame.
PassKernel build_pass_kernel(const FilterSettings& settings);

// Whether a and b describe the same PassKernel (every input build_pass_kernel reads), so the
// kernel is rebuilt only when one of them changes.
bool same_pass_kernel_inputs(const FilterSettings& a, const FilterSettings& b);

// Deterministic per-pixel noise in [0, 1) for the jittered taps: an integer hash of the pixel and
// the pass axis (0 horizontal, 1 vertical), exact in GLSL's 32-bit uint arithmetic too
// (separable_blur.frag computes the same bits).
float jitter_noise(int x, int y, int axis);

}  // namespace sss::math
