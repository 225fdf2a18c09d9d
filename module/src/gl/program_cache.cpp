#include "program_cache.hpp"

#include "../math/half_resolution.hpp"

#include <cstdio>

#include "debug_label.hpp"
#include "program.hpp"
#include "shader_constants.hpp"
#include "sss/sss.h"
#include "texture_units.hpp"

namespace sss::gl {

int image_format_index(GLint internal_format) {
  for (int i = 0; i < kImageFormats; ++i) {
    if (kComputeImageFormats[i].internal_format == static_cast<GLenum>(internal_format)) return i;
  }
  return -1;
}

sss_result ProgramCache::init(const Functions* gl, GlslVariant variant, bool labels, const Log* log,
                              Capabilities* caps, std::string* message) {
  gl_ = gl;
  variant_ = variant;
  labels_ = labels;
  log_ = log;
  caps_ = caps;
  std::string log_text;
  copy_ = build_program(*gl_, vertex_recipe(variant_), stage_recipe(variant_, "copy.frag"), &log_text);
  if (copy_ == 0) {
    *message = "copy shader: " + log_text;
    return SSS_ERROR_SHADER_COMPILE;
  }
  set_unit(copy_, "u_source", unit::source);
  label_object(*gl_, labels_, PROGRAM, copy_, "sss copy");

  // The default settings' fragment passes written back on hardware depth, culled by the depth the
  // inputs draw marks: their inputs, the horizontal pass (packed) and the vertical one, as the
  // planner asks for them on this context (again after a refusal it records, with its stand-in).
  sss_result r = SSS_OK;
  std::size_t refusals = 0;
  do {
    refusals = caps_->refusals();
    BlurProgram* unused = nullptr;
    BlurVariant common;
    common.follow_surface = 1;
    common.packed_output = true;
    common.image_taps = caps_->image_taps();
    common.half_taps = SSS_TAPS_MEDIUM / 2;  // the default's 17 taps
    if (caps_->preset_refused(common)) common.half_taps = 0;
    r = blur(common, &unused, message);
    common.outside = Outside::discard;
    common.packed_output = false;
    common.half_taps = SSS_TAPS_MEDIUM / 2;
    if (caps_->preset_refused(common)) common.half_taps = 0;
    if (r == SSS_OK) r = blur(common, &unused, message);
    PassInputsProgram* inputs = nullptr;
    PassInputsVariant culled;
    culled.mark_depth = true;
    // An RGBA16F colour that is complete, through the image unit where there is one.
    culled.color_image = caps_->image_inputs() ? 0 : -1;
    if (r == SSS_OK) r = pass_inputs(culled, &inputs, message);
  } while (r != SSS_OK && caps_->refusals() != refusals);
  return r;
}

void ProgramCache::destroy() {
  if (gl_ == nullptr) return;
  const Functions& f = *gl_;
  const auto remove = [&f](GLuint program) {
    if (program != 0) f.DeleteProgram(program);
  };
  for (const auto& entry : blur_) remove(entry.second.program);
  for (const auto& entry : compute_) remove(entry.second.program);
  for (const CbfProgram& p : cbf_) remove(p.program);
  for (const ResolveProgram& p : resolve_) remove(p.program);
  remove(copy_);
  remove(stencil_mark_);
  for (const SampleWriteProgram& p : sample_write_) remove(p.program);
  for (const ColourCopyProgram& p : colour_copy_) remove(p.program);
  for (const PassInputsProgram& p : pass_inputs_) remove(p.program);
  for (const HalfInputsProgram& p : half_inputs_) remove(p.program);
  for (const HalfUpsampleProgram& p : half_upsample_) remove(p.program);
  for (const TileMarkProgram& p : tile_mark_) remove(p.program);
  for (const TileViewProgram& p : tile_view_) remove(p.program);
  forget();
}

void ProgramCache::forget() { *this = ProgramCache{}; }

GLuint ProgramCache::link(const char* fragment, const std::string& defines, const std::string& what,
                          std::string* message, TileSpans spans) {
  std::string log;
  const GLuint program =
      build_program(*gl_, vertex_recipe(variant_, spans), stage_recipe(variant_, fragment, defines), &log);
  if (program == 0) *message = what + ": " + log;
  return program;
}

void ProgramCache::set_unit(GLuint program, const char* name, GLuint unit) const {
  if (has_explicit_bindings(variant_)) return;  // GLSL 420: layout(binding) in the shader
  const GLint location = gl_->GetUniformLocation(program, name);
  if (location < 0) return;
  gl_->UseProgram(program);
  gl_->Uniform1i(location, static_cast<GLint>(unit));
}

void ProgramCache::stand_in(const std::string& refused, const std::string& instead, std::string* message) const {
  if (log_ != nullptr && *log_) {
    (*log_)(SSS_LOG_WARNING, "the driver refused " + refused + "; " + instead + " stands in (" + *message + ")");
  }
  *message = "the driver refused " + refused + " (planned again with " + instead + ")";
}

void ProgramCache::finish(GLuint program, const char* label, const char* built, const char* dialect) {
  label_object(*gl_, labels_, PROGRAM, program, label);
  if (built != nullptr && log_ != nullptr && *log_) {
    (*log_)(SSS_LOG_DEBUG, std::string("built the ") + built + " program (" +
                               (dialect != nullptr ? dialect : glsl_variant_name(variant_)) + ", " + label + ")");
  }
}

sss_result ProgramCache::blur(const BlurVariant& v, BlurProgram** out, std::string* message) {
  const int key = (blur_variant_index(v) * (kMaxHalfTaps + 1) + v.half_taps) * 2 + (v.image_taps ? 1 : 0);
  BlurProgram& p = blur_[key * 4 + v.albedo];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = blur_defines(v, profile_capacity_);
  p.program = link(blur_fragment_file(v), defines, "separable blur shader (" + defines + ")", message,
                   TileSpans::passes);
  if (p.program == 0 && v.image_taps) {
    // Insurance, as for the preset counts below (no driver has refused this so far): the taps read
    // through the sampler give the same image, for this program and every one after it.
    stand_in("the separable blur program that reads its taps through an image unit",
             "the one that reads them through a sampler", message);
    caps_->image_taps_refused = true;
    return SSS_ERROR_SHADER_COMPILE;
  }
  if (p.program == 0 && v.half_taps > 0) {
    // The preset count's variant only lets the compiler unroll the loop; the one that reads the
    // count as a uniform gives the same image. A driver that refuses the first (NVIDIA's refused a
    // look-ahead index in the unrolled loop once) still gets the filter, and says so once.
    stand_in("the separable blur program for " + std::to_string(2 * v.half_taps + 1) + " taps as a constant",
             "the one that reads the count as a uniform", message);
    caps_->refused_presets.push_back(preset_key(v));
    return SSS_ERROR_SHADER_COMPILE;
  }
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  char label[144];
  std::snprintf(label, sizeof label,
                "sss blur outside=%d follow=%d jitter=%d accumulate=%d profiles=%d packed=%d taps=%d image=%d albedo=%d",
                static_cast<int>(v.outside), v.follow_surface, v.jitter ? 1 : 0, v.accumulate ? 1 : 0,
                v.profile_ids, v.packed_output ? 1 : 0, 2 * v.half_taps + 1, v.image_taps ? 1 : 0, v.albedo);
  finish(p.program, label, "blur");
  find_blur_uniforms(&p);
  p.gaussian_depth = v.follow_surface == 2 && v.profile_ids == 0;
  p.image_taps = v.image_taps;
  set_unit(p.program, "u_source", unit::source);
  set_unit(p.program, "u_strength", unit::pass_strength);
  set_unit(p.program, "u_original", unit::original);
  set_unit(p.program, "u_accumulated", unit::accumulated);
  set_unit(p.program, "u_profile_ids", unit::profile_ids);
  if (v.albedo != 0) set_unit(p.program, "u_albedo", unit::albedo);
  p.tile_grid = gl_->GetUniformLocation(p.program, "u_tile_grid");
  set_unit(p.program, "u_tiles", unit::tiles);
  if (v.profile_ids != 0) {  // the tables' block on binding point 0 (ProfileTables::bind)
    const GLuint block = gl_->GetUniformBlockIndex(p.program, "SssProfileTables");
    if (block != kInvalidIndex) gl_->UniformBlockBinding(p.program, block, 0);
  }
  return SSS_OK;
}

sss_result ProgramCache::compute(const BlurVariant& v, int image_format_slot, ComputePass pass, BlurProgram** out,
                                 std::string* message) {
  // Per-pixel profiles and packed outputs never take the compute path: the variants without them
  // come first (blur_variant_index's leading factor is 0 for them).
  const int variant = blur_variant_index(v);
  if (!is_compute_blur_variant(v) || variant >= kComputeBlurVariants) {
    *message = "separable blur compute shader: not a compute variant (per-pixel profiles run on the fragment passes)";
    return SSS_ERROR_SHADER_COMPILE;
  }
  const int index = ((variant * kImageFormats + image_format_slot) * kComputePassCount + static_cast<int>(pass)) * 4 +
                    v.albedo;
  BlurProgram& p = compute_[index];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  // The fragment variant's switches, then the compute ones.
  const ComputeImageFormat& format = kComputeImageFormats[image_format_slot];
  const std::string defines = compute_blur_defines(v, image_format_slot, pass);
  std::string log;
  p.program = build_compute_program(*gl_, compute_recipe(defines), &log);
  if (p.program == 0) {
    *message = "separable blur compute shader (" + defines + "): " + log;
    return SSS_ERROR_SHADER_COMPILE;
  }
  char label[160];
  std::snprintf(label, sizeof label,
                "sss compute blur pass=%d outside=%d follow=%d linear=%d jitter=%d accumulate=%d albedo=%d %s",
                static_cast<int>(pass), static_cast<int>(v.outside), v.follow_surface, v.linear_depth ? 1 : 0,
                v.jitter ? 1 : 0, v.accumulate ? 1 : 0, v.albedo, format.qualifier);
  finish(p.program, label, "blur", "GLSL 430 core");
  find_blur_uniforms(&p);
  p.gaussian_depth = v.follow_surface == 2;
  p.compute = true;
  return SSS_OK;
}

UniformLocations ProgramCache::struct_fields(GLuint program, const UniformStruct& s) const {
  // A program compiled from version_430.glsl (the compute blur) has explicit locations in any
  // dialect; looked up by name they are found all the same.
  return find_uniforms(*gl_, program, s, variant_);
}

void ProgramCache::find_blur_uniforms(BlurProgram* program) const {
  const Functions& f = *gl_;
  BlurProgram& p = *program;
  p.fields = struct_fields(p.program, kBlurUniforms);
  p.cdf = f.GetUniformLocation(p.program, "u_cdf");
  p.spacing = f.GetUniformLocation(p.program, "u_spacing");
  p.profile = f.GetUniformLocation(p.program, "u_profile");
}

sss_result ProgramCache::cross_bilateral(Outside outside, bool linear_depth, bool normals, int albedo,
                                         CbfProgram** out, std::string* message) {
  const int index = ((static_cast<int>(outside) * 2 + (linear_depth ? 1 : 0)) * 2 + (normals ? 1 : 0)) * 3 + albedo;
  CbfProgram& p = cbf_[static_cast<std::size_t>(index)];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = cbf_defines(outside, linear_depth, normals, albedo);
  p.program = link("cbf_blur.frag", defines, "cross-bilateral blur shader (" + defines + ")", message);
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  char label[80];
  std::snprintf(label, sizeof label, "sss cross-bilateral outside=%d linear=%d normals=%d albedo=%d",
                static_cast<int>(outside), linear_depth ? 1 : 0, normals ? 1 : 0, albedo);
  finish(p.program, label, "cross-bilateral");
  const Functions& f = *gl_;
  p.fields = struct_fields(p.program, kCbfUniforms);
  p.cdf = f.GetUniformLocation(p.program, "u_cdf");
  p.spacing = f.GetUniformLocation(p.program, "u_spacing");
  set_unit(p.program, "u_normals", unit::normals);
  set_unit(p.program, "u_source", unit::source);
  set_unit(p.program, "u_depth", unit::depth);
  set_unit(p.program, "u_original", unit::original);
  if (albedo != 0) set_unit(p.program, "u_albedo", unit::albedo);
  return SSS_OK;
}

sss_result ProgramCache::msaa_resolve(bool linear_depth, bool write_back, int albedo, ResolveProgram** out,
                                      std::string* message) {
  const int index = 4 * albedo + (write_back ? 2 : 0) + (linear_depth ? 1 : 0);
  ResolveProgram& p = resolve_[static_cast<std::size_t>(index)];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = msaa_resolve_defines(linear_depth, write_back, albedo);
  p.program = link("msaa_resolve.frag", defines, "MSAA resolve shader (" + defines + ")", message);
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  static const char* const kLabels[4] = {"sss msaa resolve", "sss msaa resolve linear", "sss msaa resolve for write-back",
                                         "sss msaa resolve linear for write-back"};
  char label[96];
  std::snprintf(label, sizeof label, "%s%s", kLabels[index % 4], albedo == 0 ? "" : albedo == 1 ? " over the albedo"
                                                                                     : " over its square root");
  finish(p.program, label, nullptr);
  p.fields = struct_fields(p.program, kResolveUniforms);
  set_unit(p.program, "u_color", unit::msaa_color);
  set_unit(p.program, "u_depth", unit::msaa_depth);
  if (albedo != 0) set_unit(p.program, "u_albedo", unit::albedo);
  return SSS_OK;
}

sss_result ProgramCache::stencil_mark(GLuint* out, std::string* message) {
  if (stencil_mark_ == 0) {
    stencil_mark_ = link("msaa_mask.frag", "", "stencil mask shader", message);
    if (stencil_mark_ == 0) return SSS_ERROR_SHADER_COMPILE;
    finish(stencil_mark_, "sss stencil mask from alpha", nullptr);
    set_unit(stencil_mark_, "u_source", unit::msaa_color);
  }
  *out = stencil_mark_;
  return SSS_OK;
}

sss_result ProgramCache::sample_write(int albedo, SampleWriteProgram** out, std::string* message) {
  SampleWriteProgram& p = sample_write_[static_cast<std::size_t>(albedo)];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  p.albedo = albedo;
  const std::string defines = msaa_write_defines(variant_, albedo);
  p.program = link("msaa_write.frag", defines, "MSAA write-back shader (" + defines + ")", message);
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  p.one_draw = msaa_write_in_one_draw(variant_);
  finish(p.program, p.one_draw ? "sss msaa write-back" : "sss msaa per-sample write-back", nullptr);
  p.fields = struct_fields(p.program, kSampleWriteUniforms);
  set_unit(p.program, "u_lowest", unit::msaa_lowest);
  set_unit(p.program, "u_blurred", unit::msaa_blurred);
  set_unit(p.program, "u_resolved", unit::msaa_resolved);
  set_unit(p.program, "u_translucent", unit::msaa_translucent);
  if (albedo != 0) set_unit(p.program, "u_albedo", unit::albedo);
  return SSS_OK;
}

sss_result ProgramCache::pass_inputs(const PassInputsVariant& v, PassInputsProgram** out, std::string* message) {
  PassInputsProgram& p = pass_inputs_[static_cast<std::size_t>(pass_inputs_variant_index(v))];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = pass_inputs_defines(v);
  p.program = link("pass_inputs.frag", defines, "pass inputs shader (" + defines + ")", message, TileSpans::inputs);
  if (p.program == 0 && v.color_image >= 0) {
    // Insurance, as for the blur's image taps: the sampler's read gives the same image.
    stand_in("the pass inputs program that reads the colour through an image unit",
             "the one that reads it through a sampler", message);
    caps_->image_inputs_refused = true;
    return SSS_ERROR_SHADER_COMPILE;
  }
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  char label[112];
  const char* image = v.color_image >= 0 ? kComputeImageFormats[v.color_image].qualifier : "none";
  std::snprintf(label, sizeof label, "sss pass inputs linear=%d profiles=%d mark=%d image=%s albedo=%d",
                v.linear_depth ? 1 : 0, v.profile_ids, v.mark_depth ? 1 : 0, image, v.albedo);
  finish(p.program, label, "pass inputs");
  p.color_image = v.color_image;
  const Functions& f = *gl_;
  p.fields = struct_fields(p.program, kInputsUniforms);
  set_unit(p.program, "u_color", unit::source);
  set_unit(p.program, "u_depth", unit::depth);
  set_unit(p.program, "u_profile_ids", unit::profile_ids);
  if (v.albedo != 0) {
    set_unit(p.program, "u_albedo", unit::albedo);
    p.texturing = f.GetUniformLocation(p.program, "u_texturing");
  }
  p.tile_grid = f.GetUniformLocation(p.program, "u_tile_grid");
  set_unit(p.program, "u_tiles", unit::tiles);
  set_unit(p.program, "u_tile_columns", unit::tile_columns);
  return SSS_OK;
}

sss_result ProgramCache::tile_mark(bool columns, int color_image, TileMarkProgram** out, std::string* message) {
  const int image = columns ? -1 : color_image;
  TileMarkProgram& p = tile_mark_[columns ? 0 : static_cast<std::size_t>(image + 2)];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = tile_mark_defines(columns, image);
  p.program = link("tile_mark.frag", defines, columns ? "tile columns shader" : "tile marks shader (" + defines + ")", message);
  if (p.program == 0 && image >= 0) {
    // Insurance, as for the passes' inputs: the sampler's read gives the same marks.
    stand_in("the tile marks program that reads the colour through an image unit",
             "the one that reads it through a sampler", message);
    caps_->image_inputs_refused = true;
    return SSS_ERROR_SHADER_COMPILE;
  }
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  char label[64];
  std::snprintf(label, sizeof label, "sss tile marks image=%s", image >= 0 ? kComputeImageFormats[image].qualifier : "none");
  finish(p.program, columns ? "sss tile columns" : label, columns ? "tile columns" : "tile marks");
  p.color_image = image;
  const Functions& f = *gl_;
  p.rect = f.GetUniformLocation(p.program, "u_rect");
  set_unit(p.program, "u_color", unit::source);
  set_unit(p.program, "u_tiles", unit::tiles);
  return SSS_OK;
}

sss_result ProgramCache::tile_view(TileSpans spans, TileViewProgram** out, std::string* message) {
  TileViewProgram& p = tile_view_[static_cast<std::size_t>(spans)];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  static const char* const kDraws[] = {"marks", "passes' bands", "inputs' bands"};
  const char* draw = kDraws[static_cast<std::size_t>(spans)];
  // The band draws' fragment stage writes a constant (their colour mask picks the channel).
  const std::string defines = spans == TileSpans::none ? "" : "#define SSS_TILE_VIEW_BANDS 1\n";
  p.program = link("tile_view.frag", defines, std::string("tiles view shader (") + draw + ")", message, spans);
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  char label[64];
  std::snprintf(label, sizeof label, "sss tiles view (%s)", draw);
  finish(p.program, label, "tiles view");
  const Functions& f = *gl_;
  p.rect = f.GetUniformLocation(p.program, "u_rect");
  p.tile_grid = f.GetUniformLocation(p.program, "u_tile_grid");
  set_unit(p.program, "u_tiles", unit::tiles);
  set_unit(p.program, "u_tile_columns", unit::tile_columns);
  return SSS_OK;
}

sss_result ProgramCache::half_inputs(const HalfVariant& v, HalfInputsProgram** out, std::string* message) {
  // The reduction reads no albedo: one program per index variant.
  HalfInputsProgram& p = half_inputs_[static_cast<std::size_t>(half_variant_index(HalfVariant{v.profile_ids, 0}))];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = half_inputs_defines(v);
  p.program = link("half_inputs.frag", defines, "half-size inputs shader (" + defines + ")", message,
                   TileSpans::inputs);
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  finish(p.program, v.profile_ids != 0 ? "sss half-size inputs profiles=1" : "sss half-size inputs", "half-size inputs");
  const Functions& f = *gl_;
  p.fields = struct_fields(p.program, kHalfInputsUniforms);
  p.depth_factor = f.GetUniformLocation(p.program, "u_depth_factor");
  set_unit(p.program, "u_source", unit::source);
  set_unit(p.program, "u_strength", unit::pass_strength);
  p.tile_grid = f.GetUniformLocation(p.program, "u_tile_grid");
  set_unit(p.program, "u_tiles", unit::tiles);
  set_unit(p.program, "u_tile_columns", unit::tile_columns);
  return SSS_OK;
}

sss_result ProgramCache::half_upsample(const HalfVariant& v, HalfUpsampleProgram** out, std::string* message) {
  HalfUpsampleProgram& p = half_upsample_[static_cast<std::size_t>(half_variant_index(v))];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = half_upsample_defines(v);
  p.program = link("half_upsample.frag", defines, "half-size upsample shader (" + defines + ")", message,
                   TileSpans::passes);
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  finish(p.program, v.profile_ids != 0 ? "sss half-size upsample profiles=1" : "sss half-size upsample",
         "half-size upsample");
  const Functions& f = *gl_;
  p.fields = struct_fields(p.program, kUpsampleUniforms);
  p.looks = f.GetUniformLocation(p.program, "u_looks");
  set_unit(p.program, "u_source", unit::source);
  set_unit(p.program, "u_strength", unit::pass_strength);
  set_unit(p.program, "u_half_source", unit::half_source);
  set_unit(p.program, "u_half_result", unit::half_result);
  set_unit(p.program, "u_tables", unit::half_tables);
  if (v.albedo != 0) set_unit(p.program, "u_albedo", unit::albedo);
  p.tile_grid = f.GetUniformLocation(p.program, "u_tile_grid");
  set_unit(p.program, "u_tiles", unit::tiles);
  return SSS_OK;
}

sss_result ProgramCache::colour_copy(const ColourCopyVariant& v, ColourCopyProgram** out, std::string* message) {
  ColourCopyProgram& p = colour_copy_[static_cast<std::size_t>(colour_copy_variant_index(v))];
  *out = &p;
  if (p.program != 0) return SSS_OK;
  const std::string defines = colour_copy_defines(v, profile_capacity_);
  p.program = link("colour_copy.frag", defines, "colour copy shader (" + defines + ")", message);
  if (p.program == 0) return SSS_ERROR_SHADER_COMPILE;
  char label[80];
  std::snprintf(label, sizeof label, "sss colour copy strength_texture=%d albedo=%d profiles=%d",
                v.strength_texture ? 1 : 0, v.albedo, v.profile_ids);
  finish(p.program, label, nullptr);
  const Functions& f = *gl_;
  p.fields = struct_fields(p.program, kColourCopyUniforms);
  p.texturing = f.GetUniformLocation(p.program, "u_texturing");
  set_unit(p.program, "u_source", unit::source);
  set_unit(p.program, "u_strength", unit::strength);
  set_unit(p.program, "u_albedo", unit::albedo);
  set_unit(p.program, "u_profile_ids", unit::profile_ids);
  return SSS_OK;
}

}  // namespace sss::gl
