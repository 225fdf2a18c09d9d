// Each pass kind's per-draw uniforms as one struct: a table of fields (name, place, size, kind),
// from which the shader's declarations are written (uniform_struct_glsl, into every variant's
// defines: the GLSL declares none of its own), the program's locations are found once at link
// (UniformLocations), and one draw's values are filled by the pass kind's one function from the
// frame's constants (math::PassConstants, computed once a frame by compute_pass_constants) and set
// in one call (upload_uniforms). A new uniform is one line of its pass kind's table and the line
// that fills it (pass_uniforms.cpp).
//
// The fields stay separate GLSL uniforms. Two ways of making a pass kind one GL object were
// measured against the bounds of issue 47: a uniform array (one `vec4` array and a #define per
// field) costs llvmpipe 0.12 instructions a pixel in a full-screen draw (callgrind, the empty
// 640x360 frame on the fragment path: 27,800 instructions more of the inputs draw alone), and a
// std140 block reads a buffer bound to an indexed binding point, the host's context state, which the
// state guard would save and restore every frame (more queries per steady frame). The pieces the
// pass kinds share declare a uniform only where no struct does (depth.glsl, pass_surface.glsl,
// nearest_half.glsl, jitter.glsl: `#ifndef SSS_UNIFORM_u_depth_terms`).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>

#include "filter_run.hpp"
#include "gl_functions.hpp"

namespace sss::gl {

// How a field is stored in the floats and read back in GLSL.
enum class UniformKind {
  floats,      // 1, 2 or 4 floats: float, vec2, vec4
  boolean,     // 0 or 1: a bool
  integer,     // a small integer held exactly in a float: an int
  integers,    // four small integers: an ivec4
  uint_split,  // a 32-bit uint as two 16-bit halves (high, low): a uint
};

struct UniformField {
  const char* glsl_name;
  int offset;  // in floats; a field never straddles a vec4
  int size;    // floats
  UniformKind kind;
};

// A pass kind's struct: a name for the log, its size in vec4s and its fields (by an enum of the kind's).
struct UniformStruct {
  const char* name;
  int vectors;
  const UniformField* fields;
  std::size_t count;
};
// The most fields of a struct.
inline constexpr std::size_t kMaxUniformFields = 12;

// A program's locations of a struct's fields (-1: the program does not use the field).
struct UniformLocations {
  std::array<GLint, kMaxUniformFields> at{};
  UniformLocations() { at.fill(-1); }
};

// One draw's values of a struct of `Vectors` vec4s, in the shader's layout.
template <int Vectors>
struct UniformValues {
  std::array<float, 4 * Vectors> values{};
  template <typename Field>
  void set(const UniformStruct& s, Field field, const float* v) {
    const UniformField& f = s.fields[static_cast<std::size_t>(field)];
    for (int i = 0; i < f.size; ++i) values[static_cast<std::size_t>(f.offset + i)] = v[i];
  }
  template <typename Field>
  void set(const UniformStruct& s, Field field, float v) {
    set(s, field, &v);
  }
  // Two exact 16-bit halves (a UniformKind::uint_split field): a float holds integers to 2^24.
  template <typename Field>
  void set_uint(const UniformStruct& s, Field field, std::uint32_t v) {
    const auto at = static_cast<std::size_t>(s.fields[static_cast<std::size_t>(field)].offset);
    values[at] = static_cast<float>(v >> 16u);
    values[at + 1] = static_cast<float>(v & 0xFFFFu);
  }
};

// The struct's declarations, for the variant's defines: each field as a uniform of its GLSL type,
// and a SSS_UNIFORM_<name> #define for the pieces' guards.
std::string uniform_struct_glsl(const UniformStruct& s);
// Each field's location in `program` (once, at link).
UniformLocations find_uniforms(const Functions& gl, GLuint program, const UniformStruct& s);
// One draw's values into the program in use: a glUniform call per field it uses.
void upload_uniforms(const Functions& gl, const UniformStruct& s, const UniformLocations& locations, const float* values);

// ---- The separable blur pass (separable_blur.frag, blur_debug_view.frag, separable_blur.comp) ----
// (The table's offsets pack the values a draw uploads; the GLSL types come from the kinds.)
enum class BlurField : int {
  pixels_per_mm,   // along the axis, at clip w = 1 and strength 1 (blur_pixel.glsl)
  follow_surface,  // 1 / the reach in world units (the depth Gaussian: profile mm per world unit)
  round_to_half,   // what the pass writes is rounded to half float (nearest_half.glsl)
  profile_count,   // per-pixel profiles: the profiles set
  ndc_from_depth,  // z_ndc = depth · x + y (depth.glsl)
  pixel_span,      // world width of a window pixel per unit of clip w, x and y (pass_surface.glsl)
  depth_terms,     // projection m10, m11, m14, m15 (depth.glsl)
  clamp,           // tap positions are kept inside (xy min, zw max), in pixels
  ray_slope,       // the view ray's lateral slope at window p: p · xy + zw (pass_surface.glsl)
  noise_index,     // sss_frame.noise_index (jitter.glsl)
  debug_fill,      // a debug view's vertical pass: 1 writes (0, 0, 0, 1) everywhere it draws
  rect,            // the compute passes: the pixels they write (x, y, width, height)
};
inline constexpr UniformField kBlurFields[] = {
    {"u_pixels_per_mm", 0, 1, UniformKind::floats}, {"u_follow_surface", 1, 1, UniformKind::floats},
    {"u_round_to_half", 2, 1, UniformKind::boolean}, {"u_profile_count", 3, 1, UniformKind::integer},
    {"u_ndc_from_depth", 4, 2, UniformKind::floats}, {"u_pixel_span", 6, 2, UniformKind::floats},
    {"u_depth_terms", 8, 4, UniformKind::floats},    {"u_clamp", 12, 4, UniformKind::floats},
    {"u_ray_slope", 16, 4, UniformKind::floats},     {"u_noise_index", 20, 2, UniformKind::uint_split},
    {"u_debug_fill", 22, 1, UniformKind::integer},   {"u_rect", 24, 4, UniformKind::integers},
};
inline constexpr int kBlurUniformVectors = 7;
inline constexpr UniformStruct kBlurUniforms = {"blur pass", kBlurUniformVectors, kBlurFields, std::size(kBlurFields)};
using BlurUniforms = UniformValues<kBlurUniformVectors>;
// Term `term`'s pass along `axis` of `run`: `gaussian_depth` the variant's depth correction
// (SSS_FOLLOW_SURFACE 2, whose u_follow_surface is profile mm per world unit), `round_to_half`
// whether what it writes is rounded to half float.
BlurUniforms fill_blur_uniforms(const FilterRun& run, int axis, bool gaussian_depth, bool round_to_half);

// ---- The cross-bilateral passes (cbf_blur.frag) ----
enum class CbfField : int {
  pixels_per_mm, mm_per_world, round_to_half, ndc_from_depth, pixel_span, depth_terms, clamp, ray_slope
};
inline constexpr UniformField kCbfFields[] = {
    {"u_pixels_per_mm", 0, 1, UniformKind::floats},  {"u_mm_per_world", 1, 1, UniformKind::floats},
    {"u_round_to_half", 2, 1, UniformKind::boolean}, {"u_ndc_from_depth", 4, 2, UniformKind::floats},
    {"u_pixel_span", 6, 2, UniformKind::floats},     {"u_depth_terms", 8, 4, UniformKind::floats},
    {"u_clamp", 12, 4, UniformKind::floats},         {"u_ray_slope", 16, 4, UniformKind::floats},
};
inline constexpr UniformStruct kCbfUniforms = {"cross-bilateral pass", 5, kCbfFields, std::size(kCbfFields)};
using CbfUniforms = UniformValues<5>;
CbfUniforms fill_cbf_uniforms(const FilterRun& run, int axis, bool round_to_half);

// ---- The passes' inputs (pass_inputs.frag) ----
enum class InputsField : int { ndc_from_depth, depth_terms };
inline constexpr UniformField kInputsFields[] = {
    {"u_ndc_from_depth", 0, 2, UniformKind::floats},
    {"u_depth_terms", 4, 4, UniformKind::floats},
};
inline constexpr UniformStruct kInputsUniforms = {"pass inputs", 2, kInputsFields, std::size(kInputsFields)};
using InputsUniforms = UniformValues<2>;
InputsUniforms fill_inputs_uniforms(const math::PassConstants& k);

// ---- The MSAA resolve (msaa_resolve.frag) ----
enum class ResolveField : int { samples, depth_mode, round_to_half, ndc_from_depth, depth_terms };
inline constexpr UniformField kResolveFields[] = {
    {"u_samples", 0, 1, UniformKind::integer},       {"u_depth_mode", 1, 1, UniformKind::integer},
    {"u_round_to_half", 2, 1, UniformKind::boolean}, {"u_ndc_from_depth", 4, 2, UniformKind::floats},
    {"u_depth_terms", 8, 4, UniformKind::floats},
};
inline constexpr UniformStruct kResolveUniforms = {"MSAA resolve", 3, kResolveFields, std::size(kResolveFields)};
using ResolveUniforms = UniformValues<3>;
ResolveUniforms fill_resolve_uniforms(const FilterRun& host);

// ---- The half-resolution path's upsample (half_upsample.frag) ----
enum class UpsampleField : int {
  half_taps, round_to_half, profile_count, spacing, pixel_span, half_rect, rect, depth_terms, ray_slope
};
inline constexpr UniformField kUpsampleFields[] = {
    {"u_half_taps", 0, 1, UniformKind::integer},       {"u_round_to_half", 1, 1, UniformKind::boolean},
    {"u_profile_count", 2, 1, UniformKind::integer},   {"u_spacing", 4, 2, UniformKind::floats},
    {"u_pixel_span", 6, 2, UniformKind::floats},       {"u_half_rect", 8, 4, UniformKind::integers},
    {"u_rect", 12, 4, UniformKind::integers},          {"u_depth_terms", 16, 4, UniformKind::floats},
    {"u_ray_slope", 20, 4, UniformKind::floats},
};
inline constexpr UniformStruct kUpsampleUniforms = {"upsample", 6, kUpsampleFields, std::size(kUpsampleFields)};
using UpsampleUniforms = UniformValues<6>;
// `half`: the half-size rectangle; `round_to_half`: whether the target is RGBA16F.
UpsampleUniforms fill_upsample_uniforms(const FilterRun& run, const std::array<int, 4>& half, bool round_to_half);

}  // namespace sss::gl
