// Every program variant the module builds, as recipes for the shader assembler: the variants'
// compile-time switches, their #define lines (with the sizes of shader_constants.hpp) and the
// parts of each stage. SeparableFilter and the LUT generator build from these, and the
// shaders.glslang test writes every variant through them (tests/shaders/write_shader_variants.cpp),
// so the switches and numbers are spelt out here only.
#pragma once

#include <string>

#include "gl_functions.hpp"
#include "sss/sss.h"
#include "glsl_variant.hpp"
#include "shader_source.hpp"

namespace sss::gl {

// What a blur pass writes where it leaves a pixel (SSS_OUTSIDE): its own value (horizontal pass),
// nothing (discard: vertical pass writing back), or the host's original colour (separate output).
enum class BlurOutside : int { write_centre = 0, discard = 1, copy_original = 2 };

// The separable blur's compile-time switches (separable_blur.frag and .comp).
struct BlurVariant {
  BlurOutside outside = BlurOutside::write_centre;
  int follow_surface = 0;  // 0 off, 1 ramp, 2 Gaussian depth correction
  bool linear_depth = false, jitter = false, accumulate = false;
  // Per-pixel profiles (SSS_PROFILE_IDS), fragment passes only: 0 none, 1 R8UI indices (in the
  // distance word), 2 R16UI indices (read per tap).
  int profile_ids = 0;
  // SSS_PACKED_OUTPUT: the fragment path's horizontal pass, which writes RGBA32UI colour and distance.
  bool packed_output = false;
  // SSS_HALF_TAPS: the most taps on either side as a constant of the variant (the fragment passes
  // at a preset tap count, compile_time_half_taps); 0: a uniform (the compute path, whose loop
  // measured slower unrolled on an NVIDIA H200, and other tap counts). Not part of the index.
  int half_taps = 0;
  // SSS_IMAGE_TAPS: the fragment passes read their taps through image unit 0 (imageLoad) instead of
  // a sampler. Set by the program cache on desktop GL 4.3+ (where the module loads
  // glBindImageTexture) with the GLSL 4.20 dialect; a property of the context, not of the frame, so
  // not part of the index. On llvmpipe a texelFetch is a call to a sampling function that works out
  // a mip level per lane, around which the tap loop spills its registers; imageLoad is inlined.
  bool image_taps = false;
  // SSS_DEBUG_VIEW: 0 filters; else the fragment passes write that sss_debug_view instead
  // (fragment_passes.cpp). Above kBlurVariantCount's variants in the index (blur_variant_index).
  int debug_view = 0;
  // SSS_ALBEDO (albedo.glsl): the pass that writes the frame's target multiplies by A_post: 0 no
  // (pre-scatter, and every other pass), 1 the albedo, 2 its square root, 3 per pixel by its
  // profile's mode. Not part of the index (the program cache keys it apart).
  int albedo = 0;
};
// The fragment variant's SSS_HALF_TAPS for a kernel of `half_taps` on either side: the presets'
// (SSS_TAPS_LOW, _MEDIUM, _HIGH) get their own programs, with loops the compiler can unroll; any
// other count shares the program that reads it as a uniform (0), so a host that varies the count
// freely builds no program per count.
inline int compile_time_half_taps(int half_taps) {
  for (const int preset : {SSS_TAPS_LOW, SSS_TAPS_MEDIUM, SSS_TAPS_HIGH}) {
    if (half_taps == preset / 2) return half_taps;
  }
  return 0;
}
inline constexpr int kBlurVariantCount = 3 * 3 * 2 * 2 * 2 * 3 * 2;
// The fragment stage a blur variant is built from: the filter (separable_blur.frag), or for a debug
// view the same passes writing what they would use (blur_debug_view.frag); both read their pixel
// through blur_pixel.glsl.
inline const char* blur_fragment_file(const BlurVariant& v) {
  return v.debug_view != 0 ? "blur_debug_view.frag" : "separable_blur.frag";
}
// A variant's index: in [0, kBlurVariantCount) for the filtering variants, above for the debug views'
// (debug_view · kBlurVariantCount + the rest); the variant at an index (below kBlurVariantCount).
int blur_variant_index(const BlurVariant& v);
BlurVariant blur_variant_at(int index);
// The variants the module builds: fragment passes read pass_inputs.frag's view distances (no
// SSS_LINEAR_DEPTH), and only their horizontal pass (SSS_OUTSIDE 0, no SSS_ACCUMULATE) writes
// packed; the compute path runs neither per-pixel profiles nor packed texels.
inline bool is_fragment_blur_variant(const BlurVariant& v) {
  return !v.linear_depth && (!v.packed_output || (v.outside == BlurOutside::write_centre && !v.accumulate));
}
inline bool is_compute_blur_variant(const BlurVariant& v) { return v.profile_ids == 0 && !v.packed_output; }
// `profiles`: SSS_PROFILES, the profiles the per-pixel variant's uniform block holds (the context's
// ProfileTables::capacity; SSS_MAX_PROFILES where the GL's block size allows).
std::string blur_defines(const BlurVariant& v, int profiles = SSS_MAX_PROFILES);

// The compute path's target image formats (every colour and output format the path takes).
struct ComputeImageFormat {
  GLenum internal_format;
  const char* qualifier;  // SSS_IMAGE_FORMAT
};
// RGBA16F and RGBA32F: the intermediate, a colour or an output; R11F_G11F_B10F: a colour with a
// strength texture, which the vertical pass writes as its output (colour_copy.cpp).
inline constexpr ComputeImageFormat kComputeImageFormats[] = {
    {RGBA16F, "rgba16f"}, {RGBA32F, "rgba32f"}, {R11F_G11F_B10F, "r11f_g11f_b10f"}};
inline constexpr int kComputeImageFormatCount = 3;
// The compute path's dispatches: the horizontal pass (reading its pixels' strength from the
// colour, or, `horizontal_marked`, from the target image, which a stencil draw marked first:
// compute_passes.cpp) and the vertical pass (SSS_AXIS, SSS_MARKED).
enum class ComputePass : int { horizontal = 0, horizontal_marked = 1, vertical = 2 };
inline constexpr int kComputePassCount = 3;
struct ComputeTile;  // shader_constants.hpp
// The blur variant's switches, then the compute shader's (pass, tile, image format). `tile`:
// kComputeTiles[the pass's axis] unless given (shaders.glslang also builds another shape).
std::string compute_blur_defines(const BlurVariant& v, int image_format, ComputePass pass,
                                 const ComputeTile* tile = nullptr);

// The cross-bilateral blur (cbf_blur.frag): SSS_OUTSIDE × SSS_LINEAR_DEPTH × SSS_NORMALS.
// `albedo`: SSS_ALBEDO of the vertical pass (0-2; the horizontal pass's is 0).
std::string cbf_defines(BlurOutside outside, bool linear_depth, bool normals, int albedo = 0);

// The MSAA resolve (msaa_resolve.frag): SSS_LINEAR_DEPTH × SSS_WRITE_BACK (the translucent
// samples' outputs for the write-back) × SSS_ALBEDO (0-2: the texturing mode whose A_post divides
// each sample; the albedo is multisampled, SSS_ALBEDO_SAMPLES).
std::string msaa_resolve_defines(bool linear_depth, bool write_back, int albedo = 0);
// The MSAA write-back (msaa_write.frag): SSS_SAMPLE_MASK_OUTPUT, 1 where the dialect has
// gl_SampleMask (GLSL 4.20 here): one draw; else one draw per sample under glSampleMaski.
// SSS_ALBEDO (0-2): each sample's change times its own A_post.
inline bool msaa_write_in_one_draw(GlslVariant v) { return v == GlslVariant::glsl420; }
std::string msaa_write_defines(GlslVariant v, int albedo = 0);
// The fragment passes' inputs (pass_inputs.frag): SSS_LINEAR_DEPTH, SSS_PROFILE_IDS (0-2, as
// BlurVariant::profile_ids), SSS_MARK_DEPTH (the passes cull by the module's depth, not a stencil)
// and SSS_COLOR_IMAGE: `color_image` -1 reads the colour through the sampler, 0 or 1 through image
// unit 0 in kComputeImageFormats[color_image] (RGBA16F, RGBA32F: the colours the passes read, a
// strength texture's R11F_G11F_B10F colour being read from the module's RGBA16F copy).
// SSS_ALBEDO (0-3, albedo.glsl): the colour divided by A_post as it is read, where the plan runs no
// colour copy (the fragment and half-resolution paths without a strength texture): the copy's
// division and rounding without its draw.
struct PassInputsVariant {
  bool linear_depth = false;
  int profile_ids = 0;
  bool mark_depth = false;
  int color_image = -1;
  int albedo = 0;
};
inline constexpr int kPassInputsColorImageFormats = 2;
inline constexpr int kPassInputsVariantCount = 2 * 3 * 2 * (1 + kPassInputsColorImageFormats) * 4;
int pass_inputs_variant_index(const PassInputsVariant& v);
PassInputsVariant pass_inputs_variant_at(int index);
std::string pass_inputs_defines(const PassInputsVariant& v);
// The half-resolution path (half_inputs.frag, half_upsample.frag): SSS_PROFILE_IDS 0 or 1 (R16UI
// indices run at full size). Where the upsample writes changes nothing in it (the runner masks
// alpha off when writing back).
struct HalfVariant {
  int profile_ids = 0;
  int albedo = 0;  // the upsample's SSS_ALBEDO, 0-2 (the reduction reads no albedo)
};
inline constexpr int kHalfVariantCount = 2 * 3;
inline int half_variant_index(const HalfVariant& v) { return v.profile_ids + 2 * v.albedo; }
inline HalfVariant half_variant_at(int index) { return HalfVariant{index % 2, index / 2}; }
std::string half_inputs_defines(const HalfVariant& v);
std::string half_upsample_defines(const HalfVariant& v);
// The module's copy of the colour the passes read (colour_copy.frag): SSS_STRENGTH_TEXTURE (its
// alpha from the host's strength texture), SSS_ALBEDO (divided by A_post, albedo.glsl) and, for
// SSS_ALBEDO 3, SSS_PROFILE_IDS (1 R8UI, 2 R16UI: the index that picks each pixel's mode).
struct ColourCopyVariant {
  bool strength_texture = false;
  int albedo = 0;
  int profile_ids = 0;
};
inline constexpr int kColourCopyVariantCount = 2 * 4 * 3;
inline int colour_copy_variant_index(const ColourCopyVariant& v) {
  return ((v.strength_texture ? 1 : 0) * 4 + v.albedo) * 3 + v.profile_ids;
}
inline ColourCopyVariant colour_copy_variant_at(int index) {
  return ColourCopyVariant{index / 12 != 0, (index / 3) % 4, index % 3};
}
std::string colour_copy_defines(const ColourCopyVariant& v, int profiles = SSS_MAX_PROFILES);

// The MSAA path's shaders read sampler2DMS, which GLSL ES 3.00 lacks: desktop dialects only.
inline bool has_msaa_shaders(GlslVariant v) { return v != GlslVariant::essl300; }

// The masked path's tile marks (tile_mark.frag): SSS_TILE_COLUMNS 1 the columns' marks, 0 the tiles',
// which read the colour's alpha through image unit 0 in kComputeImageFormats[color_image]
// (SSS_COLOR_IMAGE, as PassInputsVariant::color_image), or through the sampler for -1.
std::string tile_mark_defines(bool columns, int color_image = -1);

// The LUT generator (lut_generate.frag): SSS_LUT_KIND 0 diffuse, 1 shadow, and its array sizes.
std::string lut_defines(int kind);

// A stage of a program in dialect `v`: its header piece, `defines` and the stage's file.
ShaderRecipe stage_recipe(GlslVariant v, const char* file, std::string defines = "");
// The compute path's blur: GLSL 4.30 (version_430.glsl), `defines` (compute_blur_defines).
ShaderRecipe compute_recipe(std::string defines);
// The vertex stage of every program: the full-screen triangle; `spans` 1 or 2 adds the masked
// path's rows of tiles (fullscreen.vert's SSS_TILE_SPANS: 1 the blur passes', 2 the inputs draw's).
enum class TileSpans { none = 0, passes = 1, inputs = 2 };
ShaderRecipe vertex_recipe(GlslVariant v, TileSpans spans = TileSpans::none);

}  // namespace sss::gl
