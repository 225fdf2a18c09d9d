#include "glsl_variant.hpp"

namespace sss::gl {

GlslVariant choose_glsl_variant(const Api& api) {
  if (api.es) return GlslVariant::essl300;
  return api.version() >= 42 ? GlslVariant::glsl420 : GlslVariant::glsl330;
}

std::string glsl_header(GlslVariant v) {
  switch (v) {
    case GlslVariant::glsl420:
      return "#version 420 core\n#define SSS_BINDING(unit) layout(binding = unit)\n#define SSS_MANUAL_DEPTH_FILTER 0\n";
    case GlslVariant::essl300:
      // highp everywhere: the filter's weights and depths need float precision (mediump is fp16),
      // and ES gives samplers lowp by default.
      return "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
             "#define SSS_BINDING(unit)\n#define SSS_MANUAL_DEPTH_FILTER 1\n";
    case GlslVariant::glsl330: break;
  }
  return "#version 330 core\n#define SSS_BINDING(unit)\n#define SSS_MANUAL_DEPTH_FILTER 0\n";
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
