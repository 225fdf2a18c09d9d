// The GLSL dialect the shaders are compiled in, chosen at create time from the context's API:
// GLSL 3.30 core (OpenGL 3.3..4.1), GLSL 4.20 core (OpenGL 4.2+ with
// GL_ARB_explicit_uniform_location, core in 4.3 and listed by every 4.3+ driver: sampler units fixed
// in the shader with layout(binding), so no glUniform1i per sampler, and a pass struct's fields at
// their table's locations, so no glGetUniformLocation per field) and GLSL ES 3.00 (OpenGL ES 3.x:
// precision qualifiers; the passes only fetch whole texels, so nothing relies on filtering depth).
#pragma once

#include "gl_functions.hpp"

namespace sss::gl {

enum class GlslVariant : int { glsl330 = 0, glsl420 = 1, essl300 = 2 };

// `explicit_uniform_locations`: the context lists GL_ARB_explicit_uniform_location (a 4.2 context
// without it compiles GLSL 3.30).
GlslVariant choose_glsl_variant(const Api& api, bool explicit_uniform_locations);
// The header piece that starts every shader (module/shaders/version_*.glsl): the #version line and
// the dialect's macros (SSS_BINDING(unit)).
const char* glsl_header_name(GlslVariant v);
// "GLSL 330 core", "GLSL 420 core", "GLSL ES 300".
const char* glsl_variant_name(GlslVariant v);
// Sampler units come from layout(binding) in the shader.
inline bool has_explicit_bindings(GlslVariant v) { return v == GlslVariant::glsl420; }
// A pass struct's fields sit at the locations of their table (SSS_UNIFORM_AT, pass_uniforms.hpp).
inline bool has_explicit_uniform_locations(GlslVariant v) { return v == GlslVariant::glsl420; }
// A pass struct is one uniform array (SSS_UNIFORM_ARRAYS): GLSL ES 3.00 has no explicit locations.
inline bool has_uniform_arrays(GlslVariant v) { return v == GlslVariant::essl300; }

}  // namespace sss::gl
