#include "pass_uniforms.hpp"

#include <string>

namespace sss::gl {

namespace {

const char* components(int offset, int size) {
  static const char* const kOne[] = {"x", "y", "z", "w"};
  if (size == 4) return "";
  if (size == 2) return offset % 4 == 0 ? "xy" : "zw";
  return kOne[offset % 4];
}

// The GLSL expression that reads `f` from the struct's array.
std::string read_field(const char* array, const UniformField& f) {
  const std::string vector = std::string(array) + "[" + std::to_string(f.offset / 4) + "]";
  const char* part_of = components(f.offset, f.size);
  const std::string part = *part_of != '\0' ? vector + "." + part_of : vector;
  switch (f.kind) {
    case UniformKind::boolean: return "(" + part + " != 0.0)";
    case UniformKind::integer: return "int(" + part + ")";
    case UniformKind::integers: return "ivec4(" + part + ")";
    case UniformKind::uint_split:
      return "(uint(" + vector + "." + components(f.offset, 1) + ") * 65536u + uint(" + vector + "." +
             components(f.offset + 1, 1) + "))";
    default: return "(" + part + ")";
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
  std::string text = std::string("uniform vec4 ") + s.array + "[" + std::to_string(s.vectors) + "];\n";
  for (std::size_t i = 0; i < s.count; ++i) {
    text += std::string("#define ") + s.fields[i].glsl_name + " " + read_field(s.array, s.fields[i]) + "\n";
  }
  return text;
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
