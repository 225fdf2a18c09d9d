#include "glsl_variant.hpp"

#include "embedded_shaders.hpp"

namespace sss::gl {

GlslVariant choose_glsl_variant(const Api& api) {
  if (api.es) return GlslVariant::essl300;
  return api.version() >= 42 ? GlslVariant::glsl420 : GlslVariant::glsl330;
}

// The headers are module/shaders/version_*.glsl, so that the shaders.glslang test validates the
// very text the module compiles.
std::string glsl_header(GlslVariant v) {
  switch (v) {
    case GlslVariant::glsl420: return shaders::version_420_glsl;
    case GlslVariant::essl300: return shaders::version_es300_glsl;
    case GlslVariant::glsl330: break;
  }
  return shaders::version_330_glsl;
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
