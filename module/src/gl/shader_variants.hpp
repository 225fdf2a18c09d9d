// Every program variant the module builds, as recipes for the shader assembler: the variants'
// compile-time switches, their #define lines (with the sizes of shader_constants.hpp) and the
// parts of each stage. SeparableFilter and the LUT generator build from these, and the
// shaders.glslang test writes every variant through them (tests/shaders/write_shader_variants.cpp),
// so the switches and numbers are spelt out here only.
#pragma once

#include <string>

#include "gl_functions.hpp"
#include "glsl_variant.hpp"
#include "shader_source.hpp"

namespace sss::gl {

// What a blur pass writes where it leaves a pixel (SSS_OUTSIDE): its own value (horizontal pass),
// nothing (discard: vertical pass writing back), or the host's original colour (separate output).
enum class BlurOutside : int { write_centre = 0, discard = 1, copy_original = 2 };

// The separable blur's compile-time switches (separable_blur.frag; .comp never accumulates).
struct BlurVariant {
  BlurOutside outside = BlurOutside::write_centre;
  int follow_surface = 0;  // 0 off, 1 ramp, 2 Gaussian depth correction
  bool linear_depth = false, jitter = false, accumulate = false;
  bool profile_ids = false;  // per-pixel profiles (SSS_PROFILE_IDS): fragment passes only
};
inline constexpr int kBlurVariantCount = 3 * 3 * 2 * 2 * 2 * 2;
// A variant's index in [0, kBlurVariantCount), and the variant at an index.
int blur_variant_index(const BlurVariant& v);
BlurVariant blur_variant_at(int index);
// `profiles`: SSS_PROFILES, the profiles the per-pixel variant's uniform block holds (the context's
// ProfileTables::capacity; SSS_MAX_PROFILES where the GL's block size allows).
std::string blur_defines(const BlurVariant& v, int profiles = SSS_MAX_PROFILES);

// The compute path's target image formats (every colour and output format the path takes).
struct ComputeImageFormat {
  GLenum internal_format;
  const char* qualifier;  // SSS_IMAGE_FORMAT
};
// RGBA16F and RGBA32F: the intermediate, a colour or an output; R11F_G11F_B10F: a colour with a
// strength texture, which the vertical pass writes as its output (strength_source.cpp).
inline constexpr ComputeImageFormat kComputeImageFormats[] = {
    {RGBA16F, "rgba16f"}, {RGBA32F, "rgba32f"}, {R11F_G11F_B10F, "r11f_g11f_b10f"}};
inline constexpr int kComputeImageFormatCount = 3;
// The blur variant's switches, then the compute shader's (segment, apron, image format).
std::string compute_blur_defines(const BlurVariant& v, int image_format);

// The cross-bilateral blur (cbf_blur.frag): SSS_OUTSIDE × SSS_LINEAR_DEPTH × SSS_NORMALS.
std::string cbf_defines(BlurOutside outside, bool linear_depth, bool normals);

// The MSAA resolve (msaa_resolve.frag): SSS_LINEAR_DEPTH × SSS_WRITE_BACK (the translucent
// samples' outputs for the write-back).
std::string msaa_resolve_defines(bool linear_depth, bool write_back);
// The MSAA write-back (msaa_write.frag): SSS_SAMPLE_MASK_OUTPUT, 1 where the dialect has
// gl_SampleMask (GLSL 4.20 here): one draw; else one draw per sample under glSampleMaski.
inline bool msaa_write_in_one_draw(GlslVariant v) { return v == GlslVariant::glsl420; }
inline std::string msaa_write_defines(GlslVariant v) {
  return msaa_write_in_one_draw(v) ? "#define SSS_SAMPLE_MASK_OUTPUT 1\n" : "#define SSS_SAMPLE_MASK_OUTPUT 0\n";
}
// Per-pixel profiles' view distance and index (profile_depth.frag): SSS_LINEAR_DEPTH.
inline std::string profile_depth_defines(bool linear_depth) {
  return linear_depth ? "#define SSS_LINEAR_DEPTH 1\n" : "#define SSS_LINEAR_DEPTH 0\n";
}
// The MSAA path's shaders read sampler2DMS, which GLSL ES 3.00 lacks: desktop dialects only.
inline bool has_msaa_shaders(GlslVariant v) { return v != GlslVariant::essl300; }

// The LUT generator (lut_generate.frag): SSS_LUT_KIND 0 diffuse, 1 shadow, and its array sizes.
std::string lut_defines(int kind);

// A stage of a program in dialect `v`: its header piece, `defines` and the stage's file.
ShaderRecipe stage_recipe(GlslVariant v, const char* file, std::string defines = "");
// The compute path's blur: GLSL 4.30 (version_430.glsl), `defines` (compute_blur_defines).
ShaderRecipe compute_recipe(std::string defines);
// The vertex stage of every program: the full-screen triangle.
inline ShaderRecipe vertex_recipe(GlslVariant v) { return stage_recipe(v, "fullscreen.vert"); }

}  // namespace sss::gl
