#include "pass_uniforms.hpp"

#include <string>

namespace sss::gl {

namespace {

// A field's GLSL type.
const char* glsl_type(const UniformField& f) {
  switch (f.kind) {
    case UniformKind::boolean: return "bool";
    case UniformKind::integer: return "int";
    case UniformKind::integers: return "ivec4";
    case UniformKind::uint_split: return "uint";
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

// The first and last pixel of a rectangle (x0, y0, x1, y1).
std::array<int, 4> corners(const std::array<int, 4>& r) { return {r[0], r[1], r[0] + r[2] - 1, r[1] + r[3] - 1}; }

}  // namespace

std::string uniform_struct_glsl(const UniformStruct& s) {
  std::string text;
  for (std::size_t i = 0; i < s.count; ++i) {
    const UniformField& f = s.fields[i];
    text += std::string("uniform ") + glsl_type(f) + " " + f.glsl_name + ";\n#define SSS_UNIFORM_" + f.glsl_name + "\n";
  }
  return text;
}

UniformLocations find_uniforms(const Functions& gl, GLuint program, const UniformStruct& s) {
  UniformLocations l;
  for (std::size_t i = 0; i < s.count; ++i) l.at[i] = gl.GetUniformLocation(program, s.fields[i].glsl_name);
  return l;
}

void upload_uniforms(const Functions& gl, const UniformStruct& s, const UniformLocations& locations, const float* values) {
  for (std::size_t i = 0; i < s.count; ++i) {
    const GLint at = locations.at[i];
    if (at < 0) continue;
    const UniformField& f = s.fields[i];
    const float* v = values + f.offset;
    switch (f.kind) {
      case UniformKind::boolean:
      case UniformKind::integer: gl.Uniform1i(at, static_cast<GLint>(v[0])); break;
      case UniformKind::integers:
        gl.Uniform4i(at, static_cast<GLint>(v[0]), static_cast<GLint>(v[1]), static_cast<GLint>(v[2]),
                     static_cast<GLint>(v[3]));
        break;
      case UniformKind::uint_split:
        gl.Uniform1ui(at, static_cast<GLuint>(v[0]) * 65536u + static_cast<GLuint>(v[1]));
        break;
      default:
        if (f.size == 1) gl.Uniform1f(at, v[0]);
        if (f.size == 2) gl.Uniform2f(at, v[0], v[1]);
        if (f.size == 4) gl.Uniform4f(at, v[0], v[1], v[2], v[3]);
        break;
    }
  }
}

BlurUniforms fill_blur_uniforms(const FilterRun& run, int axis, bool gaussian_depth, bool round_to_half) {
  const math::PassConstants& k = run.constants;
  const UniformStruct& s = kBlurUniforms;
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
  u.set(s, BlurField::rect, rect);
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
  return u;
}

InputsUniforms fill_inputs_uniforms(const math::PassConstants& k) {
  InputsUniforms u;
  float ndc[2], terms[4];
  set_depth(k, ndc, terms);
  u.set(kInputsUniforms, InputsField::ndc_from_depth, ndc);
  u.set(kInputsUniforms, InputsField::depth_terms, terms);
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
  return u;
}

}  // namespace sss::gl
