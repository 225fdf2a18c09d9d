#include "shader_variants.hpp"

#include <cstdio>
#include <utility>

#include "../math/tile_culling.hpp"
#include "pass_uniforms.hpp"
#include "shader_constants.hpp"

namespace sss::gl {

int blur_variant_index(const BlurVariant& v) {
  int index = (v.packed_output ? 3 : 0) + v.profile_ids;
  index = index * 3 + static_cast<int>(v.outside);
  index = index * 3 + v.follow_surface;
  index = index * 2 + (v.linear_depth ? 1 : 0);
  index = index * 2 + (v.jitter ? 1 : 0);
  index = index * 2 + (v.accumulate ? 1 : 0);
  return v.debug_view * kBlurVariantCount + index;
}

BlurVariant blur_variant_at(int index) {
  BlurVariant v;
  v.accumulate = index % 2 != 0;
  index /= 2;
  v.jitter = index % 2 != 0;
  index /= 2;
  v.linear_depth = index % 2 != 0;
  index /= 2;
  v.follow_surface = index % 3;
  index /= 3;
  v.outside = static_cast<BlurOutside>(index % 3);
  index /= 3;
  v.profile_ids = index % 3;
  v.packed_output = index / 3 != 0;
  return v;
}

std::string blur_defines(const BlurVariant& v, int profiles) {
  char defines[480];
  std::snprintf(defines, sizeof defines,
                "#define SSS_OUTSIDE %d\n#define SSS_FOLLOW_SURFACE %d\n#define SSS_LINEAR_DEPTH %d\n"
                "#define SSS_JITTER %d\n#define SSS_ACCUMULATE %d\n#define SSS_CDF_ENTRIES %d\n"
                "#define SSS_MAX_HALF_TAPS %d\n#define SSS_PROFILE_IDS %d\n#define SSS_PROFILES %d\n"
                "#define SSS_PACKED_OUTPUT %d\n#define SSS_IMAGE_TAPS %d\n#define SSS_DEBUG_VIEW %d\n"
                "#define SSS_ALBEDO %d\n",
                static_cast<int>(v.outside), v.follow_surface, v.linear_depth ? 1 : 0, v.jitter ? 1 : 0,
                v.accumulate ? 1 : 0, kCdfEntries, kMaxHalfTaps, v.profile_ids, profiles, v.packed_output ? 1 : 0,
                v.image_taps ? 1 : 0, v.debug_view, v.albedo);
  std::string text = defines;
  if (v.half_taps > 0) text += "#define SSS_HALF_TAPS " + std::to_string(v.half_taps) + "\n";
  return text + uniform_struct_glsl(kBlurUniforms);  // the pass's uniform struct (pass_uniforms.hpp)
}

std::string compute_blur_defines(const BlurVariant& v, int image_format, ComputePass pass,
                                 const ComputeTile* shape) {
  const int axis = pass == ComputePass::vertical ? 1 : 0;
  const ComputeTile& tile = shape != nullptr ? *shape : kComputeTiles[axis];
  char defines[256];
  std::snprintf(defines, sizeof defines,
                "#define SSS_AXIS %d\n#define SSS_MARKED %d\n#define SSS_THREADS %d\n#define SSS_SEGMENT %d\n"
                "#define SSS_LINES %d\n#define SSS_APRON %d\n#define SSS_IMAGE_FORMAT %s\n",
                axis, pass == ComputePass::horizontal_marked ? 1 : 0, kComputeThreads, tile.segment, tile.lines,
                tile.apron, kComputeImageFormats[image_format].qualifier);
  return blur_defines(v) + defines;
}

std::string cbf_defines(BlurOutside outside, bool linear_depth, bool normals, int albedo) {
  // The horizontal pass is the one that writes every pixel (the intermediate): its axis follows
  // from what it writes outside. Its taps: footprint_cells.glsl's tables, no profiles, no jitter.
  char defines[320];
  std::snprintf(defines, sizeof defines,
                "#define SSS_OUTSIDE %d\n#define SSS_AXIS %d\n#define SSS_LINEAR_DEPTH %d\n#define SSS_NORMALS %d\n"
                "#define SSS_CDF_ENTRIES %d\n#define SSS_MAX_HALF_TAPS %d\n#define SSS_PROFILE_IDS 0\n"
                "#define SSS_FOLLOW_SURFACE 0\n#define SSS_JITTER 0\n#define SSS_ALBEDO %d\n",
                static_cast<int>(outside), outside == BlurOutside::write_centre ? 0 : 1, linear_depth ? 1 : 0,
                normals ? 1 : 0, kCdfEntries, kMaxHalfTaps, albedo);
  return defines + uniform_struct_glsl(kCbfUniforms);
}

namespace {
// albedo.glsl's switches for the MSAA programs: the mode, and the albedo read per sample.
std::string msaa_albedo_defines(int albedo) {
  return "#define SSS_ALBEDO " + std::to_string(albedo) + "\n" + (albedo != 0 ? "#define SSS_ALBEDO_SAMPLES 1\n" : "");
}
}  // namespace

std::string msaa_resolve_defines(bool linear_depth, bool write_back, int albedo) {
  return std::string(linear_depth ? "#define SSS_LINEAR_DEPTH 1\n" : "#define SSS_LINEAR_DEPTH 0\n") +
         (write_back ? "#define SSS_WRITE_BACK 1\n" : "#define SSS_WRITE_BACK 0\n") + msaa_albedo_defines(albedo) +
         uniform_struct_glsl(kResolveUniforms);
}

std::string msaa_write_defines(GlslVariant v, int albedo) {
  return (msaa_write_in_one_draw(v) ? "#define SSS_SAMPLE_MASK_OUTPUT 1\n" : "#define SSS_SAMPLE_MASK_OUTPUT 0\n") +
         msaa_albedo_defines(albedo) + uniform_struct_glsl(kSampleWriteUniforms);
}

int pass_inputs_variant_index(const PassInputsVariant& v) {
  const int sampler_variant = ((v.linear_depth ? 1 : 0) * 3 + v.profile_ids) * 2 + (v.mark_depth ? 1 : 0);
  return (sampler_variant * (1 + kPassInputsColorImageFormats) + v.color_image + 1) * 4 + v.albedo;
}

PassInputsVariant pass_inputs_variant_at(int index) {
  PassInputsVariant v;
  v.albedo = index % 4;
  index /= 4;
  v.color_image = index % (1 + kPassInputsColorImageFormats) - 1;
  index /= 1 + kPassInputsColorImageFormats;
  v.mark_depth = index % 2 != 0;
  v.profile_ids = (index / 2) % 3;
  v.linear_depth = index / 6 != 0;
  return v;
}

std::string pass_inputs_defines(const PassInputsVariant& v) {
  char defines[192];
  std::snprintf(defines, sizeof defines,
                "#define SSS_LINEAR_DEPTH %d\n#define SSS_PROFILE_IDS %d\n#define SSS_MARK_DEPTH %d\n"
                "#define SSS_COLOR_IMAGE %d\n#define SSS_ALBEDO %d\n#define SSS_PROFILES %d\n",
                v.linear_depth ? 1 : 0, v.profile_ids, v.mark_depth ? 1 : 0, v.color_image >= 0 ? 1 : 0, v.albedo,
                SSS_MAX_PROFILES);
  std::string text = defines;
  if (v.color_image >= 0) {
    text += std::string("#define SSS_COLOR_IMAGE_FORMAT ") + kComputeImageFormats[v.color_image].qualifier + "\n";
  }
  return text + uniform_struct_glsl(kInputsUniforms);
}

std::string half_inputs_defines(const HalfVariant& v) {
  return "#define SSS_PROFILE_IDS " + std::to_string(v.profile_ids) + "\n" + uniform_struct_glsl(kHalfInputsUniforms);
}

std::string half_upsample_defines(const HalfVariant& v) {
  // SSS_LINEAR_DEPTH 1: depth.glsl's clip_w only (the upsample reads view distances).
  return "#define SSS_PROFILE_IDS " + std::to_string(v.profile_ids) + "\n#define SSS_ALBEDO " + std::to_string(v.albedo) +
         "\n#define SSS_LINEAR_DEPTH 1\n#define SSS_CDF_ENTRIES " +
         std::to_string(math::kFootprintEntries) + "\n" + uniform_struct_glsl(kUpsampleUniforms);
}

std::string colour_copy_defines(const ColourCopyVariant& v, int profiles) {
  char defines[160];
  std::snprintf(defines, sizeof defines,
                "#define SSS_STRENGTH_TEXTURE %d\n#define SSS_ALBEDO %d\n#define SSS_PROFILE_IDS %d\n"
                "#define SSS_PROFILES %d\n",
                v.strength_texture ? 1 : 0, v.albedo, v.profile_ids, profiles);
  return defines + uniform_struct_glsl(kColourCopyUniforms);
}

std::string lut_defines(int kind) {
  char defines[128];
  std::snprintf(defines, sizeof defines, "#define SSS_LUT_KIND %d\n#define SSS_MAX_TERMS %d\n#define SSS_GL_ORDER %d\n",
                kind, kLutMaxTerms, kLutOrder);
  return defines + uniform_struct_glsl(kLutUniforms);
}

ShaderRecipe stage_recipe(GlslVariant v, const char* file, std::string defines) {
  return ShaderRecipe{glsl_header_name(v), std::move(defines), file};
}

ShaderRecipe compute_recipe(std::string defines) {
  return ShaderRecipe{"version_430.glsl", std::move(defines), "separable_blur.comp"};
}

std::string tile_mark_defines(bool columns, int color_image) {
  std::string text = std::string("#define SSS_TILE_COLUMNS ") + (columns ? "1\n" : "0\n") +
                     "#define SSS_COLOR_IMAGE " + (color_image >= 0 ? "1\n" : "0\n");
  if (color_image >= 0) {
    text += std::string("#define SSS_COLOR_IMAGE_FORMAT ") + kComputeImageFormats[color_image].qualifier + "\n";
  }
  return text;
}

ShaderRecipe vertex_recipe(GlslVariant v, TileSpans spans) {
  if (spans == TileSpans::none) return stage_recipe(v, "fullscreen.vert");
  return stage_recipe(v, "fullscreen.vert",
                      "#define SSS_TILE_SPANS " + std::to_string(static_cast<int>(spans)) +
                          "\n#define SSS_TILE_BAND " + std::to_string(math::kTileBand) + "\n");
}

}  // namespace sss::gl
