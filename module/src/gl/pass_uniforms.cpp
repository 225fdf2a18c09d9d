#include "pass_uniforms.hpp"

#include <cstring>
#include <string>

#include "math/half_resolution.hpp"

namespace sss::gl {

namespace {

// A field's GLSL type.
const char* glsl_type(const UniformField& f) {
  switch (f.kind) {
    case UniformKind::boolean: return "bool";
    case UniformKind::integer: return "int";
    case UniformKind::integers: return "ivec4";
    case UniformKind::uint_bits: return "uint";
    default: return f.size == 1 ? "float" : f.size == 2 ? "vec2" : "vec4";
  }
}

void set_depth(const math::PassConstants& k, float* ndc, float* terms) {
  ndc[0] = k.ndc_scale;
  ndc[1] = k.ndc_bias;
  for (std::size_t i = 0; i < 4; ++i) terms[i] = k.depth_terms[i];
}

void set_clamp(const math::PassConstants& k, float* clamp) {
  clamp[0] = k.clamp_min[0];
  clamp[1] = k.clamp_min[1];
  clamp[2] = k.clamp_max[0];
  clamp[3] = k.clamp_max[1];
}

void set_slope(const math::PassConstants& k, float* slope) {
  slope[0] = k.slope_scale[0];
  slope[1] = k.slope_scale[1];
  slope[2] = k.slope_bias[0];
  slope[3] = k.slope_bias[1];
}

// The fields of a pass that walks the surface: the depth's clip w and the view rays.
template <typename Values, typename Field>
void set_walk(Values& u, const UniformStruct& s, const math::PassConstants& k, Field span, Field terms, Field slope) {
  float depth_terms[4], ray_slope[4];
  for (std::size_t i = 0; i < 4; ++i) depth_terms[i] = k.depth_terms[i];
  set_slope(k, ray_slope);
  u.set(s, span, k.pixel_span.data());
  u.set(s, terms, depth_terms);
  u.set(s, slope, ray_slope);
}

// A rectangle's four integers as floats (exact: pixel coordinates are below 2^24).
void set_rect(const std::array<int, 4>& r, float* out) {
  for (std::size_t i = 0; i < 4; ++i) out[i] = static_cast<float>(r[i]);
}

// A footprint table's reach and centre delta (footprint_cells.glsl's u_footprint).
std::array<float, 4> footprint_of(const math::FootprintTable& table) {
  return {table.reach_mm, table.delta[0], table.delta[1], table.delta[2]};
}

// The first and last pixel of a rectangle (x0, y0, x1, y1).
std::array<int, 4> corners(const std::array<int, 4>& r) { return {r[0], r[1], r[0] + r[2] - 1, r[1] + r[3] - 1}; }

}  // namespace

std::string uniform_struct_glsl(const UniformStruct& s) {
  std::string placed, arrayed, guards;
  const std::string array = s.glsl_array;
  arrayed += "uniform ivec4 " + array + "[" + std::to_string(s.vectors) + "];\n";
  for (std::size_t i = 0; i < s.count; ++i) {
    const UniformField& f = s.fields[i];
    placed += "SSS_UNIFORM_AT(" + std::to_string(i) + ") uniform " + glsl_type(f) + " " + f.glsl_name + ";\n";
    // The field's part of the array: its vector, and its components where it is narrower.
    std::string part = array + "[" + std::to_string(f.offset / 4) + "]";
    if (f.size < 4) part += "." + std::string("xyzw").substr(static_cast<std::size_t>(f.offset % 4), f.size);
    std::string read = part;
    switch (f.kind) {
      case UniformKind::floats: read = "intBitsToFloat(" + part + ")"; break;
      case UniformKind::boolean: read = "(" + part + " != 0)"; break;
      case UniformKind::uint_bits: read = "uint(" + part + ")"; break;
      default: break;
    }
    arrayed += std::string("#define ") + f.glsl_name + " " + read + "\n";
    guards += std::string("#define SSS_UNIFORM_") + f.glsl_name + "\n";
  }
  return "#ifdef SSS_UNIFORM_ARRAYS\n" + arrayed + "#else\n" + placed + "#endif\n" + guards;
}

UniformLocations find_uniforms(const Functions& gl, GLuint program, const UniformStruct& s, GlslVariant dialect) {
  UniformLocations l;
  if (has_uniform_arrays(dialect)) {
    l.array = gl.GetUniformLocation(program, s.glsl_array);
    return l;
  }
  if (!has_explicit_uniform_locations(dialect)) {
    for (std::size_t i = 0; i < s.count; ++i) l.at[i] = gl.GetUniformLocation(program, s.fields[i].glsl_name);
    return l;
  }
  // A field the program does not use has no index (and setting its location would be ignored,
  // but it would cost a call whenever its value changes).
  std::array<const GLchar*, kMaxUniformFields> names{};
  std::array<GLuint, kMaxUniformFields> indices{};
  for (std::size_t i = 0; i < s.count; ++i) names[i] = s.fields[i].glsl_name;
  gl.GetUniformIndices(program, static_cast<GLsizei>(s.count), names.data(), indices.data());
  for (std::size_t i = 0; i < s.count; ++i) l.at[i] = indices[i] != kInvalidIndex ? static_cast<GLint>(i) : -1;
  return l;
}

void upload_uniforms(const Functions& gl, const UniformStruct& s, const UniformLocations& locations,
                     const std::int32_t* values) {
  if (locations.array >= 0) {
    const std::size_t bytes = sizeof(std::int32_t) * 4 * static_cast<std::size_t>(s.vectors);
    if (locations.holds_values && std::memcmp(locations.held.data(), values, bytes) == 0) return;
    std::memcpy(locations.held.data(), values, bytes);
    gl.Uniform4iv(locations.array, s.vectors, values);
    locations.holds_values = true;
    return;
  }
  for (std::size_t i = 0; i < s.count; ++i) {
    const GLint at = locations.at[i];
    if (at < 0) continue;
    const UniformField& f = s.fields[i];
    const std::int32_t* v = values + f.offset;
    std::int32_t* held = locations.held.data() + f.offset;
    const std::size_t bytes = sizeof(std::int32_t) * static_cast<std::size_t>(f.size);
    if (locations.holds_values && std::memcmp(held, v, bytes) == 0) continue;
    std::memcpy(held, v, bytes);
    switch (f.kind) {
      case UniformKind::boolean:
      case UniformKind::integer: gl.Uniform1i(at, v[0]); break;
      case UniformKind::integers: gl.Uniform4i(at, v[0], v[1], v[2], v[3]); break;
      case UniformKind::uint_bits: gl.Uniform1ui(at, static_cast<GLuint>(v[0])); break;
      default: {
        float x[4];
        std::memcpy(x, v, sizeof(float) * static_cast<std::size_t>(f.size));
        if (f.size == 1) gl.Uniform1f(at, x[0]);
        if (f.size == 2) gl.Uniform2f(at, x[0], x[1]);
        if (f.size == 4) gl.Uniform4f(at, x[0], x[1], x[2], x[3]);
        break;
      }
    }
  }
  locations.holds_values = true;
}

BlurUniforms fill_blur_uniforms(const FilterRun& run, std::size_t term, int axis, bool gaussian_depth,
                                bool round_to_half) {
  const math::PassConstants& k = run.constants;
  const UniformStruct& s = kBlurUniforms;
  const math::PassTerm& t = run.kernel->terms[term];
  const math::FootprintTable& table = (axis == 0 ? t.horizontal : t.vertical).footprint;
  BlurUniforms u;
  float ndc[2], terms[4], clamp[4], rect[4];
  set_depth(k, ndc, terms);
  set_clamp(k, clamp);
  set_rect(run.draw_rect, rect);
  set_walk(u, s, k, BlurField::pixel_span, BlurField::depth_terms, BlurField::ray_slope);
  u.set(s, BlurField::pixels_per_mm, k.pixels_per_mm[static_cast<std::size_t>(axis)]);
  // The Gaussian depth correction measures depth in profile millimetres; the ramp in reaches.
  u.set(s, BlurField::follow_surface, gaussian_depth ? k.mm_per_world : k.follow_surface_factor);
  u.set(s, BlurField::round_to_half, round_to_half ? 1.0f : 0.0f);
  u.set(s, BlurField::profile_count, static_cast<float>(run.profile_count));
  u.set(s, BlurField::ndc_from_depth, ndc);
  u.set(s, BlurField::clamp, clamp);
  u.set_uint(s, BlurField::noise_index, run.noise_index);
  u.set(s, BlurField::jitter_from, static_cast<float>(run.kernel->jitter_from));
  u.set(s, BlurField::half_taps, static_cast<float>(run.kernel->spacing.size()));
  u.set(s, BlurField::rect, rect);
  u.set(s, BlurField::footprint, footprint_of(table).data());
  u.set(s, BlurField::inv_two_variance, 0.5f / t.depth_variance_mm2);
  return u;
}

CbfUniforms fill_cbf_uniforms(const FilterRun& run, int axis, bool round_to_half) {
  const math::PassConstants& k = run.constants;
  const UniformStruct& s = kCbfUniforms;
  CbfUniforms u;
  float ndc[2], terms[4], clamp[4];
  set_depth(k, ndc, terms);
  set_clamp(k, clamp);
  set_walk(u, s, k, CbfField::pixel_span, CbfField::depth_terms, CbfField::ray_slope);
  u.set(s, CbfField::pixels_per_mm, k.pixels_per_mm[static_cast<std::size_t>(axis)]);
  u.set(s, CbfField::mm_per_world, k.mm_per_world);
  u.set(s, CbfField::round_to_half, round_to_half ? 1.0f : 0.0f);
  u.set(s, CbfField::ndc_from_depth, ndc);
  u.set(s, CbfField::clamp, clamp);
  const math::CbfKernel& kernel = *run.cbf_kernel;
  const float spike_blend[4] = {kernel.spike_blend[0], kernel.spike_blend[1], kernel.spike_blend[2], 0.0f};
  const float inv_two_variance[4] = {kernel.inv_two_variance[0], kernel.inv_two_variance[1],
                                     kernel.inv_two_variance[2], 0.0f};
  u.set(s, CbfField::half_taps, static_cast<float>(kernel.spacing.size()));
  u.set(s, CbfField::footprint, footprint_of(kernel.table).data());
  u.set(s, CbfField::spike_blend, spike_blend);
  u.set(s, CbfField::inv_two_variance, inv_two_variance);
  return u;
}

InputsUniforms fill_inputs_uniforms(const FilterRun& run) {
  InputsUniforms u;
  float ndc[2], terms[4];
  set_depth(run.constants, ndc, terms);
  u.set(kInputsUniforms, InputsField::ndc_from_depth, ndc);
  u.set(kInputsUniforms, InputsField::depth_terms, terms);
  // The quotient colour / albedo rounded as the copy rounds it where the passes read RGBA16F.
  u.set(kInputsUniforms, InputsField::round_to_half,
        run.intermediate_format() == static_cast<GLint>(RGBA16F) ? 1.0f : 0.0f);
  return u;
}

ColourCopyUniforms fill_colour_copy_uniforms(const FilterRun& run) {
  ColourCopyUniforms u;
  u.set(kColourCopyUniforms, ColourCopyField::round_to_half,
        run.intermediate_format() == static_cast<GLint>(RGBA16F) ? 1.0f : 0.0f);
  return u;
}

ResolveUniforms fill_resolve_uniforms(const FilterRun& host) {
  const UniformStruct& s = kResolveUniforms;
  ResolveUniforms u;
  float ndc[2], terms[4];
  set_depth(host.resolve_constants, ndc, terms);
  u.set(s, ResolveField::samples, static_cast<float>(host.color.samples));
  u.set(s, ResolveField::depth_mode, static_cast<float>(host.depth_resolve));
  // The resolved colour rounded to nearest where it is RGBA16F, so that it and the inputs' copy of
  // it hold the same value whatever the driver's conversion does.
  u.set(s, ResolveField::round_to_half, host.color.internal_format == static_cast<GLint>(RGBA16F) ? 1.0f : 0.0f);
  u.set(s, ResolveField::ndc_from_depth, ndc);
  u.set(s, ResolveField::depth_terms, terms);
  return u;
}

SampleWriteUniforms fill_sample_write_uniforms(const FilterRun& host, int sample) {
  SampleWriteUniforms u;
  u.set(kSampleWriteUniforms, SampleWriteField::samples, static_cast<float>(host.color.samples));
  u.set(kSampleWriteUniforms, SampleWriteField::sample, static_cast<float>(sample));
  return u;
}

HalfInputsUniforms fill_half_inputs_uniforms(const FilterRun& run) {
  const UniformStruct& s = kHalfInputsUniforms;
  HalfInputsUniforms u;
  float rect[4];
  set_rect(corners(run.draw_rect), rect);
  u.set(s, HalfInputsField::rect, rect);
  u.set(s, HalfInputsField::profile_count, static_cast<float>(run.profile_count));
  u.set(s, HalfInputsField::merge_reach, math::kHalfResolutionMergeReach);
  return u;
}

UpsampleUniforms fill_upsample_uniforms(const FilterRun& run, const std::array<int, 4>& half, bool round_to_half) {
  const math::PassConstants& k = run.constants;
  const UniformStruct& s = kUpsampleUniforms;
  UpsampleUniforms u;
  const std::vector<float>& spacing = run.kernel->spacing;
  const float first_two[2] = {spacing.empty() ? 0.0f : spacing[0], spacing.size() < 2 ? 0.0f : spacing[1]};
  float half_rect[4], rect[4];
  set_rect(corners(half), half_rect);
  set_rect(corners(run.draw_rect), rect);
  set_walk(u, s, k, UpsampleField::pixel_span, UpsampleField::depth_terms, UpsampleField::ray_slope);
  u.set(s, UpsampleField::half_taps, static_cast<float>(spacing.size()));
  u.set(s, UpsampleField::round_to_half, round_to_half ? 1.0f : 0.0f);
  u.set(s, UpsampleField::profile_count, static_cast<float>(run.profile_count));
  u.set(s, UpsampleField::spacing, first_two);
  u.set(s, UpsampleField::half_rect, half_rect);
  u.set(s, UpsampleField::rect, rect);
  u.set(s, UpsampleField::min_reach, math::kHalfResolutionMinReachPixels);
  u.set(s, UpsampleField::min_weight, math::kHalfResolutionMinWeight);
  return u;
}

}  // namespace sss::gl
