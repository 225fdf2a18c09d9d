// Each pass kind's per-draw uniforms as one struct: a table of fields (name, place, size, kind),
// from which the shader's declarations are written (uniform_struct_glsl, into every variant's
// defines: the GLSL declares none of its own), the program's locations are known from the table
// (find_uniforms), and one draw's values are filled by the pass kind's one function from the
// frame's constants (math::PassConstants, computed once a frame by compute_pass_constants) and
// the kernel, and set in one call (upload_uniforms). A new uniform is one line of its pass kind's
// table and the line that fills it (pass_uniforms.cpp). Every per-draw number a program reads is
// in its struct (the LUT generator's too, filled by sss_lut_create_texture); only tables (arrays:
// u_cdf, u_spacing, u_profile, u_looks, u_texturing, u_depth_factor, the LUT generator's u_terms and
// u_gl), samplers, the vertex stage's u_tile_grid and the tile programs' one u_rect are uniforms of
// their own (tests/gl/uniform_structs_test.cpp checks every program the paths build, and that no
// field is looked up by name).
//
// A struct's form follows the dialect, and either way no field is looked up by name:
//   - desktop GL (GLSL 4.20 with GL_ARB_explicit_uniform_location): each field a uniform at its
//     row's location (layout(location)); one glGetUniformIndices call at link says which fields a
//     program uses. (GLSL 3.30 without the extension looks each field up, once at link.)
//   - GLSL ES 3.00, which has no explicit locations: the struct is one uniform array of ivec4, each
//     field a #define that reads its part (floats through intBitsToFloat, so exact: the images are
//     bit for bit the separate uniforms'), one location, one glUniform4iv per draw that changes it.
//     On desktop llvmpipe this form cost more than separate uniforms (callgrind,
//     scripts/cost-probe.sh, the 640x360 head close-up: 133.87 M -> 134.84 M instructions on the
//     default path, +0.72 %; +0.29 % on the half-resolution path), which is why the placed
//     uniforms are the desktop form.
// Measured and left: a vec4 array with the integers held as floats (its int() and `!= 0.0`
// conversions cost 0.12 instructions a pixel: the empty 640x360 fragment frame's inputs draw
// alone 27,800 more); a std140 block, which reads a buffer bound to an indexed binding point, the
// host's context state, which the state guard would save and restore every frame (four more
// queries per steady frame).
// The pieces the pass kinds share declare a uniform only where no struct does (depth.glsl,
// pass_surface.glsl, nearest_half.glsl, jitter.glsl: `#ifndef SSS_UNIFORM_u_depth_terms`).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <string>

#include "filter_run.hpp"
#include "gl_functions.hpp"
#include "glsl_variant.hpp"

namespace sss::gl {

// How a field is stored in the values and read back in GLSL.
enum class UniformKind {
  floats,      // 1, 2 or 4 floats: float, vec2, vec4
  boolean,     // 0 or 1: a bool
  integer,     // a small integer held exactly in a float: an int
  integers,    // four small integers: an ivec4
  uint_bits,   // a 32-bit uint (its bits in the value): a uint
};

struct UniformField {
  const char* glsl_name;
  int offset;  // in 32-bit values; a field never straddles an ivec4
  int size;    // 32-bit values: 1, 2 or 4
  UniformKind kind;
};

// A pass kind's struct: a name for the log, the GLSL name of its one array where the dialect
// declares the struct as one (glsl_variant.hpp has_uniform_arrays), its size in vectors of four
// values and its fields (by an enum of the kind's).
struct UniformStruct {
  const char* name;
  const char* glsl_array;
  int vectors;
  const UniformField* fields;
  std::size_t count;
};

// The most fields of a struct, and its most vectors of four values.
inline constexpr std::size_t kMaxUniformFields = 16;
inline constexpr std::size_t kMaxUniformVectors = 9;

// A program's locations of a struct's fields (-1: the program does not use the field), and the
// values the program holds: a uniform keeps its value in the program, so a draw sets only the
// fields that changed since the program's last draw (a steady frame's draws set few or none).
struct UniformLocations {
  std::array<GLint, kMaxUniformFields> at{};
  GLint array = -1;  // where the struct is one array (GLSL ES 3.00): its location, and `at` unused
  mutable std::array<std::int32_t, 4 * kMaxUniformVectors> held{};
  mutable bool holds_values = false;  // false until the first upload: every field is set then
  UniformLocations() { at.fill(-1); }
};

// One draw's values of a struct of `Vectors` vectors of four, in the table's layout: each field's
// 32-bit values (a float's bits, an integer as itself).
template <int Vectors>
struct UniformValues {
  std::array<std::int32_t, 4 * Vectors> values{};
  // `v` as the field's kind reads it: a float field takes the floats' bits, an integer, integers or
  // boolean field the floats as integers (they hold small integers exactly).
  template <typename Field>
  void set(const UniformStruct& s, Field field, const float* v) {
    const UniformField& f = s.fields[static_cast<std::size_t>(field)];
    for (int i = 0; i < f.size; ++i) {
      std::int32_t& out = values[static_cast<std::size_t>(f.offset + i)];
      if (f.kind == UniformKind::floats) {
        std::memcpy(&out, &v[i], sizeof out);
      } else {
        out = static_cast<std::int32_t>(v[i]);
      }
    }
  }
  template <typename Field>
  void set(const UniformStruct& s, Field field, float v) {
    set(s, field, &v);
  }
  // A UniformKind::uint_bits field.
  template <typename Field>
  void set_uint(const UniformStruct& s, Field field, std::uint32_t v) {
    const auto at = static_cast<std::size_t>(s.fields[static_cast<std::size_t>(field)].offset);
    std::memcpy(&values[at], &v, sizeof v);
  }
};

// The struct's declarations, for the variant's defines, in both of the dialects' forms (the
// header's SSS_UNIFORM_ARRAYS picks one): each field a uniform of its GLSL type at the location of its
// row in the table (SSS_UNIFORM_AT(row): layout(location = row) where the dialect has explicit
// uniform locations), or, in GLSL ES 3.00, which has none, the struct as one array of ivec4 with
// each field a #define that reads its part (floats through intBitsToFloat: exact); and a
// SSS_UNIFORM_<name> #define for the pieces' guards.
std::string uniform_struct_glsl(const UniformStruct& s);
// Each field's location in `program` (compiled in `dialect`), once at link. With explicit locations
// a field is at its row and one glGetUniformIndices call over the table's names says which fields the
// program uses; as one array, one glGetUniformLocation of the array; otherwise one per field.
UniformLocations find_uniforms(const Functions& gl, GLuint program, const UniformStruct& s, GlslVariant dialect);
// One draw's values into the program in use: a glUniform call per field it uses whose value it
// does not hold already (as one array: one glUniform4iv where any value changed).
void upload_uniforms(const Functions& gl, const UniformStruct& s, const UniformLocations& locations,
                     const std::int32_t* values);

// ---- The separable blur pass (separable_blur.frag, blur_debug_view.frag, separable_blur.comp) ----
// (The table's offsets pack the values a draw uploads; the GLSL types come from the kinds.)
enum class BlurField : int {
  pixels_per_mm,     // along the axis, at clip w = 1 and strength 1 (blur_pixel.glsl)
  follow_surface,    // 1 / the reach in world units (the depth Gaussian: profile mm per world unit)
  round_to_half,     // what the pass writes is rounded to half float (nearest_half.glsl)
  profile_count,     // per-pixel profiles: the profiles set
  ndc_from_depth,    // z_ndc = depth · x + y (depth.glsl)
  pixel_span,        // world width of a window pixel per unit of clip w, x and y (pass_surface.glsl)
  depth_terms,       // projection m10, m11, m14, m15 (depth.glsl)
  clamp,             // tap positions are kept inside (xy min, zw max), in pixels
  ray_slope,         // the view ray's lateral slope at window p: p · xy + zw (pass_surface.glsl)
  noise_index,       // sss_frame.noise_index (jitter.glsl)
  jitter_from,       // the first sparse tap (1 = next to the centre) that jitters (footprint_cells.glsl)
  debug_fill,        // a debug view's vertical pass: 1 writes (0, 0, 0, 1) everywhere it draws
  half_taps,         // the most taps on either side (a variant at a preset count has it as a constant)
  rect,              // the compute passes: the pixels they write (x, y, width, height)
  footprint,         // x: the term's table's reach in profile mm, yzw: its centre delta (footprint_cells.glsl)
  inv_two_variance,  // 1 / (2v) of the term's depth Gaussian, v in mm² (SSS_FOLLOW_SURFACE 2)
};
inline constexpr UniformField kBlurFields[] = {
    {"u_pixels_per_mm", 0, 1, UniformKind::floats},    {"u_follow_surface", 1, 1, UniformKind::floats},
    {"u_round_to_half", 2, 1, UniformKind::boolean},   {"u_profile_count", 3, 1, UniformKind::integer},
    {"u_ndc_from_depth", 4, 2, UniformKind::floats},   {"u_pixel_span", 6, 2, UniformKind::floats},
    {"u_depth_terms", 8, 4, UniformKind::floats},      {"u_clamp", 12, 4, UniformKind::floats},
    {"u_ray_slope", 16, 4, UniformKind::floats},       {"u_noise_index", 20, 1, UniformKind::uint_bits},
    {"u_jitter_from", 21, 1, UniformKind::integer},    {"u_debug_fill", 22, 1, UniformKind::integer},
    {"u_half_taps", 23, 1, UniformKind::integer},      {"u_rect", 24, 4, UniformKind::integers},
    {"u_footprint", 28, 4, UniformKind::floats},       {"u_inv_two_variance", 32, 1, UniformKind::floats},
};
inline constexpr int kBlurUniformVectors = 9;
inline constexpr UniformStruct kBlurUniforms = {"blur pass", "sss_blur_values", kBlurUniformVectors, kBlurFields,
                                                std::size(kBlurFields)};
using BlurUniforms = UniformValues<kBlurUniformVectors>;
// Term `term`'s pass along `axis` of `run`: `gaussian_depth` the variant's depth correction
// (SSS_FOLLOW_SURFACE 2, whose u_follow_surface is profile mm per world unit), `round_to_half`
// whether what it writes is rounded to half float.
BlurUniforms fill_blur_uniforms(const FilterRun& run, std::size_t term, int axis, bool gaussian_depth,
                                bool round_to_half);

// ---- The cross-bilateral passes (cbf_blur.frag) ----
enum class CbfField : int {
  pixels_per_mm, mm_per_world, round_to_half, half_taps, ndc_from_depth, pixel_span, depth_terms, clamp, ray_slope,
  footprint,         // the kernel's table's reach and centre delta (footprint_cells.glsl)
  spike_blend,       // rgb: b, result = b · centre + (1 - b) · normalised sum
  inv_two_variance,  // rgb: 1 / (2 σ²) per channel, mm⁻²
};
inline constexpr UniformField kCbfFields[] = {
    {"u_pixels_per_mm", 0, 1, UniformKind::floats},  {"u_mm_per_world", 1, 1, UniformKind::floats},
    {"u_round_to_half", 2, 1, UniformKind::boolean}, {"u_half_taps", 3, 1, UniformKind::integer},
    {"u_ndc_from_depth", 4, 2, UniformKind::floats}, {"u_pixel_span", 6, 2, UniformKind::floats},
    {"u_depth_terms", 8, 4, UniformKind::floats},    {"u_clamp", 12, 4, UniformKind::floats},
    {"u_ray_slope", 16, 4, UniformKind::floats},     {"u_footprint", 20, 4, UniformKind::floats},
    {"u_spike_blend", 24, 4, UniformKind::floats},   {"u_inv_two_variance", 28, 4, UniformKind::floats},
};
inline constexpr UniformStruct kCbfUniforms = {"cross-bilateral pass", "sss_cbf_values", 8, kCbfFields, std::size(kCbfFields)};
using CbfUniforms = UniformValues<8>;
CbfUniforms fill_cbf_uniforms(const FilterRun& run, int axis, bool round_to_half);

// ---- The passes' inputs (pass_inputs.frag) ----
enum class InputsField : int {
  ndc_from_depth, round_to_half,  // the albedo's quotient is rounded to half float (SSS_ALBEDO)
  depth_terms
};
inline constexpr UniformField kInputsFields[] = {
    {"u_ndc_from_depth", 0, 2, UniformKind::floats},
    {"u_round_to_half", 2, 1, UniformKind::boolean},
    {"u_depth_terms", 4, 4, UniformKind::floats},
};
inline constexpr UniformStruct kInputsUniforms = {"pass inputs", "sss_inputs_values", 2, kInputsFields, std::size(kInputsFields)};
using InputsUniforms = UniformValues<2>;
InputsUniforms fill_inputs_uniforms(const FilterRun& run);

// ---- The module's copy of the colour (colour_copy.frag) ----
enum class ColourCopyField : int { round_to_half };  // the albedo's quotient is rounded to half float
inline constexpr UniformField kColourCopyFields[] = {
    {"u_round_to_half", 0, 1, UniformKind::boolean},
};
inline constexpr UniformStruct kColourCopyUniforms = {"colour copy", "sss_copy_values", 1, kColourCopyFields,
                                                      std::size(kColourCopyFields)};
using ColourCopyUniforms = UniformValues<1>;
ColourCopyUniforms fill_colour_copy_uniforms(const FilterRun& run);

// ---- The MSAA resolve (msaa_resolve.frag) ----
enum class ResolveField : int { samples, depth_mode, round_to_half, ndc_from_depth, depth_terms };
inline constexpr UniformField kResolveFields[] = {
    {"u_samples", 0, 1, UniformKind::integer},       {"u_depth_mode", 1, 1, UniformKind::integer},
    {"u_round_to_half", 2, 1, UniformKind::boolean}, {"u_ndc_from_depth", 4, 2, UniformKind::floats},
    {"u_depth_terms", 8, 4, UniformKind::floats},
};
inline constexpr UniformStruct kResolveUniforms = {"MSAA resolve", "sss_resolve_values", 3, kResolveFields,
                                                   std::size(kResolveFields)};
using ResolveUniforms = UniformValues<3>;
ResolveUniforms fill_resolve_uniforms(const FilterRun& host);

// ---- The MSAA write-back (msaa_write.frag) ----
enum class SampleWriteField : int {
  samples,
  sample,  // the sample this draw writes (the one glSampleMaski lets through; the one-draw variant reads none)
};
inline constexpr UniformField kSampleWriteFields[] = {
    {"u_samples", 0, 1, UniformKind::integer},
    {"u_sample", 1, 1, UniformKind::integer},
};
inline constexpr UniformStruct kSampleWriteUniforms = {"MSAA write-back", "sss_write_values", 1, kSampleWriteFields,
                                                       std::size(kSampleWriteFields)};
using SampleWriteUniforms = UniformValues<1>;
SampleWriteUniforms fill_sample_write_uniforms(const FilterRun& host, int sample);

// ---- The half-resolution path's reduction (half_inputs.frag) ----
enum class HalfInputsField : int {
  rect,           // the drawn rectangle's first and last pixel: x0, y0, x1, y1
  profile_count,  // per-pixel profiles: the profiles set
  merge_reach,    // math::kHalfResolutionMergeReach
};
inline constexpr UniformField kHalfInputsFields[] = {
    {"u_rect", 0, 4, UniformKind::integers},
    {"u_profile_count", 4, 1, UniformKind::integer},
    {"u_merge_reach", 5, 1, UniformKind::floats},
};
inline constexpr UniformStruct kHalfInputsUniforms = {"half-size inputs", "sss_half_inputs_values", 2, kHalfInputsFields,
                                                      std::size(kHalfInputsFields)};
using HalfInputsUniforms = UniformValues<2>;
HalfInputsUniforms fill_half_inputs_uniforms(const FilterRun& run);

// ---- The half-resolution path's upsample (half_upsample.frag) ----
enum class UpsampleField : int {
  half_taps, round_to_half, profile_count, min_reach, spacing, pixel_span, half_rect, rect, depth_terms, ray_slope,
  min_weight
};
inline constexpr UniformField kUpsampleFields[] = {
    {"u_half_taps", 0, 1, UniformKind::integer},       {"u_round_to_half", 1, 1, UniformKind::boolean},
    {"u_profile_count", 2, 1, UniformKind::integer},   {"u_min_reach", 3, 1, UniformKind::floats},
    {"u_spacing", 4, 2, UniformKind::floats},          {"u_pixel_span", 6, 2, UniformKind::floats},
    {"u_half_rect", 8, 4, UniformKind::integers},      {"u_rect", 12, 4, UniformKind::integers},
    {"u_depth_terms", 16, 4, UniformKind::floats},     {"u_ray_slope", 20, 4, UniformKind::floats},
    {"u_min_weight", 24, 1, UniformKind::floats},
};
inline constexpr UniformStruct kUpsampleUniforms = {"upsample", "sss_upsample_values", 7, kUpsampleFields,
                                                    std::size(kUpsampleFields)};
using UpsampleUniforms = UniformValues<7>;
// `half`: the half-size rectangle; `round_to_half`: whether the target is RGBA16F.
UpsampleUniforms fill_upsample_uniforms(const FilterRun& run, const std::array<int, 4>& half, bool round_to_half);

// ---- The LUT generator (lut_generate.frag; filled by sss_lut_create_texture, api_lut_texture.cpp) ----
enum class LutField : int {
  size,                 // the LUT's width and height
  row_range,            // the first and last row's curvature (1/mm) or penumbra width (world units)
  term_count,           // the profile's Gaussians in u_terms
  support,              // mm beyond which the profile is negligible
  world_units_per_mm,   // shadow LUT only
  new_penumbra,         // shadow LUT only: the penumbra width the LUT is sharpened to
  gaussian_filter,      // shadow LUT only: 1 a Gaussian PCF penumbra, 0 a box
};
inline constexpr UniformField kLutFields[] = {
    {"u_size", 0, 2, UniformKind::floats},          {"u_row_range", 2, 2, UniformKind::floats},
    {"u_term_count", 4, 1, UniformKind::integer},   {"u_support", 5, 1, UniformKind::floats},
    {"u_world_units_per_mm", 6, 1, UniformKind::floats}, {"u_new_penumbra", 7, 1, UniformKind::floats},
    {"u_gaussian_filter", 8, 1, UniformKind::integer},
};
inline constexpr UniformStruct kLutUniforms = {"LUT generator", "sss_lut_values", 3, kLutFields, std::size(kLutFields)};
using LutUniforms = UniformValues<3>;

// Every struct fits UniformLocations.
constexpr bool fits_locations(const UniformStruct& s) {
  return s.count <= kMaxUniformFields && static_cast<std::size_t>(s.vectors) <= kMaxUniformVectors;
}
static_assert(fits_locations(kBlurUniforms) && fits_locations(kCbfUniforms) && fits_locations(kInputsUniforms) &&
              fits_locations(kColourCopyUniforms) && fits_locations(kResolveUniforms) &&
              fits_locations(kSampleWriteUniforms) && fits_locations(kHalfInputsUniforms) &&
              fits_locations(kUpsampleUniforms) && fits_locations(kLutUniforms));

}  // namespace sss::gl
