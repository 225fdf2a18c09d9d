// One pass of the separable blur, shared by the fragment, half-resolution and compute passes: its
// kernel and per-frame uniforms, its inputs, and whether what it writes is rounded to half float in
// the shader (module/shaders/nearest_half.glsl). Which variant a pass runs is the plan's
// (frame_plan.hpp).
#pragma once

#include <cstddef>

#include "filter_run.hpp"
#include "frame_plan.hpp"
#include "pass_setup.hpp"
#include "program_cache.hpp"

namespace sss::gl {

// Whether the pass of term `term` on `axis` writes a half-float target, so that the shader rounds
// what it writes to nearest whatever rounding the driver's conversion does: horizontal passes
// write the intermediate (FilterRun::intermediate_format), vertical ones the sum of terms (RGBA32F; RGBA16F on ES) or, the
// last, the host's colour or output.
bool writes_half_float(const Functions& gl, const FilterRun& run, std::size_t term, int axis);
// The kernel's tables (uploaded only when the kernel, term or axis changed since the program last
// ran) and the pass's struct (pass_uniforms.hpp, one call); leaves `program` in use.
// `round_to_half`: -1 as writes_half_float says, else 0 or 1 (the half-size vertical pass, which
// writes the intermediate's format, not the target's).
void set_blur_uniforms(PassContext& ctx, BlurProgram& program, const FilterRun& run, std::size_t term, int axis,
                       int round_to_half = -1);
// A debug view's vertical pass: u_debug_fill set to `fill` (1: the program writes (0, 0, 0, 1)
// wherever it draws), the struct's other fields as set_blur_uniforms left them; `program` in use.
void set_debug_fill(const Functions& gl, const BlurProgram& program, bool fill);
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
