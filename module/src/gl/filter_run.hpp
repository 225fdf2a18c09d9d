// What one frame asks of the GPU passes: the host's textures (already validated and described by
// the api layer), the kernel and its per-frame constants, and how the passes may run. The api
// layer fills a FilterRun (module/src/api/api_apply.cpp); SeparableFilter::run plans the frame
// from it (frame_plan.hpp) and runs the plan's steps. It describes the frame; the plan decides.
#pragma once

#include <array>
#include <cstdint>

#include "../math/cbf_kernel.hpp"
#include "../math/filter_constants.hpp"
#include "../math/pass_kernel.hpp"
#include "../math/profile_set.hpp"
#include "sss/sss.h"
#include "texture_query.hpp"

namespace sss::gl {

struct StencilInput {
  TextureInfo texture;  // the host's depth-stencil texture
  GLuint ref = 0, mask = 0;
};

// How the MSAA resolve turns a pixel's sample depths into one view distance (sss.h
// SSS_MSAA_DEPTH_*): the paper's average of the samples' linear depths, or the alternatives the
// benchmark compares it with.
enum class DepthResolve : int { average = 0, sample0 = 1, nearest = 2, farthest = 3 };

struct FilterRun {
  TextureInfo color;                       // multisampled: the MSAA path (depth has the same samples)
  TextureInfo depth;
  TextureInfo output;                      // name 0: write back into color
  TextureInfo normals;                     // name 0: none (cross-bilateral mode reconstructs from depth)
  // The host's strength texture (sss_frame.strength_texture; name 0: the colour's alpha is the
  // strength). The plan draws the colour with it as alpha into the module's copy first and runs the
  // passes on passes_run()'s run (frame_plan.hpp), which reads the copy.
  TextureInfo strength;
  const StencilInput* stencil = nullptr;   // nullptr: mask from alpha alone
  std::array<int, 4> viewport = {0, 0, 0, 0};
  // Where the passes draw and their taps stay (constants.clamp_*): the viewport, or the host's
  // region of translucent pixels (SSS_FRAME_REGION; region true). With a separate output the rest of
  // the viewport gets the colour copied first.
  std::array<int, 4> draw_rect = {0, 0, 0, 0};
  bool region = false;
  const math::PassKernel* kernel = nullptr;  // one pair of passes per term
  std::uint64_t kernel_revision = 0;       // changes whenever the kernel does
  math::PassConstants constants;
  // Per-pixel profiles (sss_frame.profile_texture; name 0: none, and the fields below are unused):
  // the host's R8UI/R16UI indices, and profile_count profiles' kernels ([0] is `kernel`; one term
  // each when there are several) with their per-frame constants (pixels per millimetre, the
  // follow-surface factor). profiles_revision changes whenever a kernel does.
  TextureInfo profile_ids;
  int profile_count = 1;
  std::array<const math::PassKernel*, math::kMaxProfiles> profile_kernels{};
  std::array<math::PassConstants, math::kMaxProfiles> profile_constants{};
  std::uint64_t profiles_revision = 0;
  bool has_profiles() const { return profile_ids.name != 0; }
  bool follow_surface = false;
  std::uint32_t noise_index = 0;           // sss_frame.noise_index: seeds the jitter (jitter.glsl)
  // sss_frame.debug_view: 0, or the view the first term's fragment passes write (SSS_DEBUG_VIEW).
  std::uint32_t debug_view = 0;
  bool identity = false;                   // nothing to blur: only copy into a separate output
  std::uint64_t frame = 0;                 // 1-based number of this frame (for the measurements)
  // The cross-bilateral mode (Mikkelsen 2010) instead of the separable kernel.
  bool cross_bilateral = false;
  const math::CbfKernel* cbf_kernel = nullptr;
  std::uint64_t cbf_kernel_revision = 0;
  // MSAA path only: the host depth's encoding for the resolve (`constants` then describe the
  // resolved linear distance the passes read), and how sample depths combine.
  math::PassConstants resolve_constants;
  DepthResolve depth_resolve = DepthResolve::average;
  // sss.h SSS_PATH_*: the compute path is taken (SSS_PATH_COMPUTE), or chosen by timing
  // (SSS_PATH_AUTO, per path_key: the frame's configuration), when path_unavailable() is "";
  // otherwise (and always on OpenGL ES or before GL 4.3) the fragment passes run.
  unsigned path = SSS_PATH_FRAGMENT;
  std::uint64_t path_key = 0;
  // SSS_PATH_AUTO may time the half-resolution path too (sss_settings.flags SSS_AUTO_HALF_RESOLUTION).
  bool auto_half_resolution = false;
  // Check each framebuffer's completeness. The api layer clears it for a steady frame (the same
  // textures, description and settings as the last successful one: api/steady_frame.hpp), whose
  // framebuffers that frame checked; SeparableFilter::run checks again when the path differs.
  bool verify = true;
  // The target (host colour in place, or the output) is complete, so the compute path's image
  // stores to it are defined: the host promised it (SSS_FRAME_TARGET_COMPLETE) or the GL said so
  // (gl/host_texture_state.hpp). False, the compute path is not taken: image stores to an incomplete
  // texture are undefined, a silent no-op on some drivers.
  bool target_complete = false;
  // The colour (single-sample) is complete too, so the passes' inputs draw may read it through an
  // image unit (PassInputsVariant::color_image; image loads from an incomplete texture read 0): in
  // place with SSS_FRAME_TARGET_COMPLETE, the GL's answer for an undescribed frame on GL 4.3+, or
  // the module's copy of a colour with a strength texture. False: the inputs read it through the
  // sampler, which gives the same image.
  bool color_complete = false;

  // The texturing modes (sss.h sss_texturing): the host's albedo (sss_frame.albedo_texture; name 0:
  // none) and each profile's mode ([0] the settings'; one per profile with per-pixel profiles).
  // Where a profile's is not pre-scatter the passes divide the colour by A_post where they first
  // read it (the inputs draw, or the module's colour copy: frame_plan.hpp copies_colour) and the
  // pass that writes the target multiplies by it again (module/shaders/albedo.glsl).
  TextureInfo albedo;
  std::array<std::uint8_t, math::kMaxProfiles> texturing{};
  // The host's colour where the passes read that divided copy instead (name 0 otherwise): a
  // separate output's untouched pixels are copied from it, exactly as the host gave them.
  TextureInfo original;

  bool writes_back() const { return output.name == 0; }
  // The last pass leaves the pixels it does not blur alone (discards them) instead of copying them
  // into the target: writing back, or writing the host's colour from the module's divided copy
  // (original: the target holds them already, and reading it while drawing into it would be a
  // feedback loop).
  bool keeps_untouched() const { return writes_back() || (original.name != 0 && original.name == output.name); }
  // The colour a separate output's untouched pixels get: the host's, or the passes' copy of it
  // (a strength texture's: the same rgb, the strength as alpha).
  GLuint untouched_colour() const { return original.name != 0 ? original.name : color.name; }
  // The texture the last pass writes: the host's colour (in place) or the separate output.
  const TextureInfo& target() const { return writes_back() ? color : output; }
  // The horizontal pass's target, as precise as the colour it reads: RGBA32F for RGBA32F colour
  // (irradiance above half float's 65504, or finer than its 11 bits, survives the passes), else
  // RGBA16F (an RGBA16F or R11F_G11F_B10F colour holds nothing it would lose).
  GLint intermediate_format() const {
    return color.internal_format == static_cast<GLint>(RGBA32F) ? static_cast<GLint>(RGBA32F)
                                                                 : static_cast<GLint>(RGBA16F);
  }
};

}  // namespace sss::gl
