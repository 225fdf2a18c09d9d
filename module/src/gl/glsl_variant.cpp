#include "glsl_variant.hpp"

namespace sss::gl {

GlslVariant choose_glsl_variant(const Api& api, bool explicit_uniform_locations) {
  if (api.es) return GlslVariant::essl300;
  return api.version() >= 42 && explicit_uniform_locations ? GlslVariant::glsl420 : GlslVariant::glsl330;
}

// The headers are pieces like any other, so that the shaders.glslang test validates the very text
// the module compiles.
const char* glsl_header_name(GlslVariant v) {
  switch (v) {
    case GlslVariant::glsl420: return "version_420.glsl";
    case GlslVariant::essl300: return "version_es300.glsl";
    case GlslVariant::glsl330: break;
  }
  return "version_330.glsl";
}

const char* glsl_variant_name(GlslVariant v) {
  switch (v) {
    case GlslVariant::glsl420: return "GLSL 420 core";
    case GlslVariant::essl300: return "GLSL ES 300";
    case GlslVariant::glsl330: break;
  }
  return "GLSL 330 core";
}

}  // namespace sss::gl
