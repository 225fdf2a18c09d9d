// The GLSL dialect the shaders are compiled in, chosen at create time from the context's API:
// GLSL 3.30 core (OpenGL 3.3..4.1), GLSL 4.20 core (OpenGL 4.2+: sampler units fixed in the
// shader with layout(binding), so no glUniform1i per sampler) and GLSL ES 3.00 (OpenGL ES 3.x:
// precision qualifiers; the passes only fetch whole texels, so nothing relies on filtering depth).
#pragma once

#include "gl_functions.hpp"

namespace sss::gl {

enum class GlslVariant : int { glsl330 = 0, glsl420 = 1, essl300 = 2 };

GlslVariant choose_glsl_variant(const Api& api);
// The header piece that starts every shader (module/shaders/version_*.glsl): the #version line and
// the dialect's macros (SSS_BINDING(unit)).
const char* glsl_header_name(GlslVariant v);
// "GLSL 330 core", "GLSL 420 core", "GLSL ES 300".
const char* glsl_variant_name(GlslVariant v);
// Sampler units come from layout(binding) in the shader.
inline bool has_explicit_bindings(GlslVariant v) { return v == GlslVariant::glsl420; }

}  // namespace sss::gl
