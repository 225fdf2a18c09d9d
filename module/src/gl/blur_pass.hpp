// One pass of the separable blur, shared by the fragment and compute runners: which program
// variant a term's pass needs, its kernel and per-frame uniforms, its inputs, and whether what it
// writes is rounded to half float in the shader (module/shaders/nearest_half.glsl).
#pragma once

#include <cstddef>

#include "filter_run.hpp"
#include "pass_setup.hpp"
#include "program_cache.hpp"

namespace sss::gl {

// The compute variant of term `term`'s pass on `axis` (0 horizontal, 1 vertical) writing `outside`.
BlurVariant blur_variant(const FilterRun& run, std::size_t term, int axis, Outside outside);
// The fragment variant: it reads pass_inputs.frag's texels (so the host's depth encoding does not
// matter to it), and the horizontal pass writes them packed.
BlurVariant fragment_blur_variant(const FilterRun& run, std::size_t term, int axis, Outside outside);
// SSS_PROFILE_IDS of a run: 0 no profile texture, 1 R8UI, 2 R16UI.
int profile_ids_variant(const FilterRun& run);
// The sum of the kernel's terms: RGBA32F keeps up to six terms at float precision, but OpenGL ES
// may not render to it (GL_EXT_color_buffer_float), while every ES context the module accepts
// renders RGBA16F; an RGBA32F colour on ES was checked to have that extension, so its sum is RGBA32F.
inline bool accumulators_are_half(const Functions& gl, const FilterRun& run) {
  return gl.api.es && run.color.internal_format != static_cast<GLint>(RGBA32F);
}
// Whether the pass of term `term` on `axis` writes a half-float target, so that the shader rounds
// what it writes to nearest whatever rounding the driver's conversion does: horizontal passes
// write the intermediate (FilterRun::intermediate_format), vertical ones the sum of terms (RGBA32F; RGBA16F on ES) or, the
// last, the host's colour or output.
bool writes_half_float(const Functions& gl, const FilterRun& run, std::size_t term, int axis);
// The kernel uniforms (uploaded only when the kernel, term or axis changed since the program last
// ran) and the per-frame ones; leaves `program` in use.
void set_blur_uniforms(PassContext& ctx, BlurProgram& program, const FilterRun& run, std::size_t term, int axis);
// The compute pass's input and the host's depth on their units, with the module's samplers.
void bind_blur_inputs(PassContext& ctx, GLuint source, GLuint depth);
// The fragment pass's inputs (RGBA32UI colour and distance, R32UI strength: pass_inputs.frag, or
// the half-size ones) for `program`: on their texture units, and also on image units 0 (colour) and
// 1 (strength) where the program reads them there (BlurProgram::image_taps).
void bind_packed_inputs(PassContext& ctx, const BlurProgram& program, GLuint source, GLuint strength);
// Per-pixel profiles: the tables of the pass along `axis` on uniform buffer binding point 0
// (ProfileTables::upload ran) and, for R16UI indices, the host's index texture on its unit.
void bind_profile_inputs(PassContext& ctx, const FilterRun& run, int axis);

}  // namespace sss::gl
