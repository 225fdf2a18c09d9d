// A CPU model of the GPU's two-pass separable filter: the same taps (footprint-aware whole-pixel
// taps, footprint_kernel.hpp, jittered ones included), the same per-pixel step, the same
// follow-surface blend, and the RGBA16F rounding of the intermediate target. Tests compare the GL
// result against it to tell shader bugs apart from approximation error (DESIGN.md §6, reference 2).
// Math layer: no GL.
#pragma once

#include <cstdint>
#include <vector>

#include "filter_constants.hpp"
#include "pass_kernel.hpp"
#include "pass_surface.hpp"
#include "profile_set.hpp"

namespace sss::math {

// How the model walks the surface (pass_surface.hpp). The defaults are the passes'; the others let
// tests/bench/surface_study.cpp measure the passes' choices against their alternatives.
struct CpuWalkChoices {
  TangentRule tangent = TangentRule::blend;
  float slack = kFollowSurfaceSlack;  // the ramp's slack per unit of a tap's distance along the line
  // The passes before they walked the surface: every pixel stepped as if its surface faced the
  // camera, follow-surface on the raw depth difference (no shear, no slack).
  bool facing = false;
  // Per-tap chords instead of the centre's footprint: each tap weighs the pass's 1D kernel
  // integrated between the midpoints of the taps' 3D distances from the centre (the alternative
  // issue 40 asked to measure; the passes keep the centre's footprint, docs/surface-turns.md).
  bool chords = false;
};

struct CpuFilterImage {
  int width = 0, height = 0;
  const float* color = nullptr;    // RGBA, row 0 at the bottom (GL order)
  const float* depth = nullptr;    // raw depth as stored in the depth texture, one per pixel
  const uint8_t* mask = nullptr;   // optional: 1 where the stencil test passes; nullptr: everywhere
  bool output_is_half = false;     // the output texture is RGBA16F: round the result like the GL
  bool accumulator_is_half = false;  // several terms: the module's sum of the earlier terms is RGBA16F (ES)
  // The horizontal pass's target is RGBA16F (every colour but RGBA32F, whose intermediate is
  // RGBA32F: gl::FilterRun::intermediate_format): round what it stores like the GL.
  bool intermediate_is_half = true;
  CpuWalkChoices walk;  // the passes' unless a study asks otherwise
  std::uint32_t noise_index = 0;  // sss_frame.noise_index: moves the jittered taps (jitter_noise)
  // sss_frame.debug_view (sss.h sss_debug_view): 0 filters; else the first term's passes write that
  // view, as separable_blur.frag's SSS_DEBUG_VIEW does: (0, 0, 0, 1) where they leave a pixel alone.
  std::uint32_t debug_view = 0;
  // The texturing modes (sss.h sss_texturing; cpu_texturing.hpp): `color` is then the module's copy,
  // the host's colour over A_post; each pixel the last pass blurs is multiplied by albedo_post
  // (width·height·3, rgb) before it is stored and rounded, and every other pixel keeps `original`
  // (the host's colour, RGBA) instead of the copy. nullptr: pre-scatter, neither.
  const float* albedo_post = nullptr;
  const float* original = nullptr;
};

// sss.h SSS_DEBUG_VIEW_TILES (the math layer includes no public header): the view that runs no pass,
// only the masked path's tile marks (math::write_tile_view).
inline constexpr std::uint32_t kTilesDebugView = 6;
// sss.h SSS_DEBUG_VIEW_ALBEDO: A_post, which the last pass's store multiplies its view of 1 by.
inline constexpr std::uint32_t kAlbedoDebugView = 7;
// Whether the last pass multiplies what it stores by the image's A_post: the filter, and the albedo view.
inline bool multiplies_albedo(const CpuFilterImage& image) {
  return image.albedo_post != nullptr && (image.debug_view == 0 || image.debug_view == kAlbedoDebugView);
}

// An image of `width` x `height` pixels with these colour and depth planes, the rest as above.
inline CpuFilterImage cpu_filter_image(int width, int height, const float* color, const float* depth) {
  CpuFilterImage image;
  image.width = width;
  image.height = height;
  image.color = color;
  image.depth = depth;
  return image;
}

// Runs both passes of every term of `kernel` (pass_kernel.hpp) into `out` (RGBA, width·height·4
// floats; may not alias color). Pixels that are outside the mask, have alpha <= 0 (after the
// intermediate's rounding), a non-finite colour or alpha (or one past +-2^125: kColourLimit), or an
// unusable depth keep their input value exactly; pixels outside the viewport too. Alpha above 1 counts
// as 1. Such a tap counts as the centre's colour (it does not spread). Per term: a horizontal pass into the intermediate (RGBA16F
// unless intermediate_is_half is false)
// and a vertical pass that adds the sum of the earlier terms (kept in RGBA32F, or RGBA16F with
// accumulator_is_half, as the GL does); jittered taps move by jitter_noise; a term with a depth
// variance blends taps towards the centre by 1 - exp(-dz²/2v) instead of the ramp.
void cpu_pass_kernel_filter(const PassKernel& kernel, const PassConstants& constants, const CpuFilterImage& image,
                            float* out);

// Per-pixel profiles (separable_blur.frag's SSS_PROFILE_IDS variant): each pixel runs the one-term
// kernel kernels[ids[i] & 15] with constants[ids[i] & 15] (their pixels per millimetre and
// follow-surface numbers; the depth linearisation and clamp are constants[0]'s, which every profile
// shares); a pixel whose index has no kernel keeps its value, and a tap whose whole index differs
// from the centre's counts as the centre's colour. `ids`: one value per pixel, row 0 at the bottom.
// `index_in_blue`: the ids came from an R8UI texture, which the GL carries in the low byte of each
// pixel's blue colour word (module/shaders/pass_inputs.frag): the passes read that byte as 0 (no
// change for an RGBA16F colour, whose float bits end in 13 zeros).
void cpu_profile_filter(const std::vector<const PassKernel*>& kernels, const std::vector<PassConstants>& constants,
                        const std::uint16_t* ids, const CpuFilterImage& image, float* out,
                        bool index_in_blue = false);

}  // namespace sss::math
