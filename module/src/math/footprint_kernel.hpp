// Footprint-aware taps: what one pass of the separable filter reads at a pixel and how much each
// read weighs, from the pixel's footprint (pixels per profile millimetre). Math layer: no GL.
//
// A pass's 1D kernel is kept as its cumulative half-integral C_c(x) = ∫_0^x k_c (per channel),
// tabulated once when the kernel is built. At a pixel whose step is s pixels per millimetre the
// taps sit on whole pixels (no bilinear read blends a neighbour into a tap) and each weighs the
// kernel integrated over the pixels it stands for, so:
//   - where the kernel spans few pixels every pixel out to its reach gets a tap of its own, weighed
//     by the kernel over exactly that pixel: the exact discrete convolution of a fronto-parallel
//     plane (and no more taps than the reach needs: a distant surface pays for few or none);
//   - the part of the kernel narrower than a pixel stays in the centre tap, so a kernel that fits
//     inside its pixel leaves the pixel as it is;
//   - where the kernel spans more pixels than there are taps, the taps spread out (denser at the
//     centre, never two on one pixel) and each stands for the pixels between the
//     midpoints to its neighbours.
// Each channel's weights sum to the kernel's mass (1 for a normalised pass) by construction: the
// cell integrals telescope. The shaders (module/shaders/footprint_taps.glsl, which
// separable_blur.frag and .comp include) compute the same taps in the same float operations;
// footprint_taps() is their model.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "separable_kernel.hpp"

namespace sss::math {

// Entries of a pass's cumulative table (uniform vec4 u_cdf[] in the shaders). Entry j holds
// C(reach · (j / (N − 1))²) (denser at the centre, where skin's narrow peak is), the last C(∞).
// 128 entries put a table's interpolation error below 2e-4 of a channel's mass on the skin kernels
// (FootprintKernel.TableInterpolatesTheExactCumulative measures it).
inline constexpr int kFootprintEntries = 128;
// A table reaches as far as the kernel holds more than this share of a channel's mass beyond it;
// the rest goes to the outermost tap (the last entry is the whole half mass).
inline constexpr double kFootprintTail = 1e-4;

struct FootprintTable {
  float reach_mm = 0.0f;            // where the table ends (0: the whole kernel is the delta)
  std::array<float, 3> delta{};     // weight of a delta at the centre (eq. (1)'s unscattered share)
  std::vector<std::array<float, 3>> half_cdf;  // kFootprintEntries values (empty: no table)
  bool empty() const { return half_cdf.empty(); }
};

using Rgb3 = std::array<double, 3>;

// The table of a kernel given its half-CDF C(x) for x >= 0 (per channel), C(∞) and a centre delta.
// reach_mm: where the table ends; <= 0 picks the smallest radius beyond which every channel holds at
// most kFootprintTail of its half mass (searched up to `search_limit_mm`).
FootprintTable tabulate_footprint_table(const std::function<Rgb3(double x_mm)>& half_cdf, const Rgb3& half_total,
                                        const Rgb3& delta, double reach_mm, double search_limit_mm = 0.0);

// The table of a tap list (any order, symmetric about 0): each tap's weight spread evenly over its
// cell, bounded by the midpoints to its neighbours and by the outermost taps (the cells of
// make_tap_grid); a centre tap whose cell is empty (a single tap) is a delta.
FootprintTable footprint_table_from_taps(const std::vector<KernelTap>& taps);

// A mixture of 1D Gaussians per channel: Σ_i weight_i,c · N(0, variance_i) (a variance of 0 is a
// delta), the kernel of a sum-of-Gaussians term or of the artist model.
struct LineGaussian {
  double variance_mm2;
  Rgb3 weight;
};
FootprintTable footprint_table_gaussians(const std::vector<LineGaussian>& mixture);

// C(x) by the table, in float as the shaders interpolate it.
std::array<float, 3> footprint_half_cdf(const FootprintTable& table, float x_mm);
// The same at x = `fraction` of the table's reach: the form the taps use, with the fraction a sum of
// two tap positions times footprint_midpoint_scale (the shaders' half_cdf).
std::array<float, 3> footprint_half_cdf_at_fraction(const FootprintTable& table, float fraction);
// What turns the sum of two tap positions (pixels) into the fraction of the reach at their midpoint,
// at `step` pixels per profile mm: 0.5 / (reach · step). One division per pixel, where dividing each
// midpoint by the step and then by the reach put two in every tap: on llvmpipe the tap loop waited on
// them, 3-4 % of the close-up's time.
float footprint_midpoint_scale(const FootprintTable& table, float step);

// The most taps on each side of the centre (the filter's `samples` is 2·this + 1).
inline constexpr int kMaxFootprintHalfTaps = 32;

// Where the taps of the sparse layout go, as a share of the reach (the shaders' u_spacing[]): tap i
// of half at (i / half)^p, p by the shape of the pass's kernel.
enum class FootprintLayout {
  // p = 3, for a kernel with a peak on a long tail (eq. (1), the artist model, the SVD and
  // pre-integrated terms, one term holding all of skin's profile). Cubic rather than eq. (1)'s
  // quadratic: skin's kernels hold most of their mass within a few tenths of a millimetre and their
  // reach is set by a tail to 1e-4, so at a 4K close-up (0.05 mm per pixel) the quadratic layout
  // left one tap in the peak; on the footprint sweep at 17 taps (the d'Eon marginal kernel) the
  // largest interior miss at 0.05 mm per pixel fell from 0.269 to 0.160 with the cube, and a fourth
  // power gave no more (0.166).
  cubic,
  // p = 2.5, for terms that are one Gaussian each (the sum of Gaussians of two or more: its peak is
  // its narrower terms'). The cube put half of a Gaussian's taps within half a standard deviation
  // (its reach to 1e-4 is 3.9σ) and three in the 1-3σ where most of its mass lies, so the widest
  // term read a 1 mm albedo checker in step: the texturing benchmark's largest interior miss on a
  // plane at 17 taps was 0.091 with the cube (0.2 mm per pixel) and is 0.041 with this power
  // (docs/benchmarks/texturing.md). Chosen on that benchmark and the quick footprint sweep
  // (tests/bench/miss_baseline.csv): p = 2 did as well on the checker but was up to 0.005 worse
  // than the cube on the sweep's planes near 0.05 mm per pixel (p = 2.5: at most 0.001), and p = 1
  // and 1.5 were worse at 0.5 mm per pixel. On the turn sweep (docs/benchmarks/turn-sweep.md) this
  // power leaves one frame worse than the cube by more than 0.005 (a plane turned 75 degrees in
  // perspective at 0.2 mm per pixel: red reads the 2.7 mm term through cells about one standard
  // deviation wide over an interior of 423 pixels). Its neighbours do no better: p = 2.25 and 2.75
  // leave three and two frames so, by up to 0.012 and 0.016.
  gaussian,
};
std::vector<float> footprint_spacing(int half_taps, FootprintLayout layout);

struct FootprintTaps {
  int count = 0;  // taps on each side of the centre
  std::array<int, kMaxFootprintHalfTaps> position{};                // the pixels read, increasing
  std::array<std::array<float, 3>, kMaxFootprintHalfTaps + 1> weight{};  // [0] the centre, [i] each of ±position[i-1]
};

// No tap jitters (FootprintTaps' jitter_from).
inline constexpr int kNoJitter = kMaxFootprintHalfTaps + 1;

// The first tap, counting 1, 2, ... out from the centre, that a kernel with `jitter` (sss_settings,
// [0, 1]: the outermost share of the taps) moves: the outermost round(jitter · half_taps) on
// each side; kNoJitter for none.
int first_jittered_tap(float jitter, int half_taps);

// The taps at a pixel whose step is `step` pixels per profile millimetre, with at most `half_taps`
// on each side (spacing from footprint_spacing(half_taps)).
//
// Jitter (supplementary Fig. S.6-S.7: few taps' banding turned into fine noise): where the taps are
// spread out (the kernel spans more pixels than there are taps), taps jitter_from and beyond read
// one pixel of the cell they stand for, chosen by `noise` in [0, 1) (jitter_noise of the pixel and
// pass): the cell's first pixel past the midpoint to the inner neighbour, plus
// floor(noise · the cell's pixels); the outermost tap's cell is its inner half mirrored. The weights
// stay the cells' integrals, so energy and the pass-through are as without jitter, and where every
// pixel out to the reach has its own tap nothing moves.
FootprintTaps footprint_taps(const FootprintTable& table, const std::vector<float>& spacing, float step,
                             int jitter_from = kNoJitter, float noise = 0.0f);

}  // namespace sss::math
