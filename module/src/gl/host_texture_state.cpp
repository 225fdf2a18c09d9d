#include "host_texture_state.hpp"

namespace sss::gl {

namespace {
void bind_on_unit_0(const Functions& gl, const TextureInfo& texture) {
  gl.ActiveTexture(TEXTURE0);
  gl.BindTexture(texture.target, texture.name);
}

bool is_mipmap_filter(GLint filter) {
  return filter != static_cast<GLint>(NEAREST) && filter != static_cast<GLint>(LINEAR);
}
}  // namespace

bool has_depth_stencil_mode(const Functions& gl) { return gl.api.version() >= (gl.api.es ? 31 : 43); }

GLenum query_depth_stencil_mode(const Functions& gl, const TextureInfo& texture) {
  bind_on_unit_0(gl, texture);
  GLint mode = static_cast<GLint>(DEPTH_COMPONENT);
  gl.GetTexParameteriv(texture.target, DEPTH_STENCIL_TEXTURE_MODE, &mode);
  return static_cast<GLenum>(mode);
}

bool query_image_complete(const Functions& gl, const TextureInfo& texture) {
  bind_on_unit_0(gl, texture);
  GLint filter = 0, base = 0;
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_MIN_FILTER, &filter);
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_BASE_LEVEL, &base);
  if (base != 0) return false;  // the compute path binds level 0: below the base level, stores are invalid
  if (!is_mipmap_filter(filter)) return true;
  GLint max_level = 1000, immutable = 0;
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_MAX_LEVEL, &max_level);
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_IMMUTABLE_FORMAT, &immutable);
  return max_level == 0 || immutable != 0;
}

DepthSamplingOverride::DepthSamplingOverride(const Functions& gl, const TextureInfo& depth, GLenum host_mode)
    : gl_(gl) {
  if (host_mode != STENCIL_INDEX) return;
  name_ = depth.name;
  target_ = depth.target;
  bind_on_unit_0(gl_, depth);
  gl_.TexParameteri(target_, DEPTH_STENCIL_TEXTURE_MODE, static_cast<GLint>(DEPTH_COMPONENT));
}

void DepthSamplingOverride::restore() {
  if (name_ == 0) return;
  gl_.ActiveTexture(TEXTURE0);
  gl_.BindTexture(target_, name_);
  gl_.TexParameteri(target_, DEPTH_STENCIL_TEXTURE_MODE, static_cast<GLint>(STENCIL_INDEX));
  name_ = 0;
}

}  // namespace sss::gl
