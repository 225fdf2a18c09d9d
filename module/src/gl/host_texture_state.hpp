// Host texture parameters that change what the passes read or write and that the module's own
// sampler objects cannot override: GL_DEPTH_STENCIL_TEXTURE_MODE (a depth-stencil texture set to
// stencil sampling returns stencil indices to a depth fetch) and the completeness that image
// stores need (an incomplete texture's image stores are undefined: a silent no-op on some
// drivers). The api layer asks (or takes the frame's word) and fills the FilterRun; these bind the
// texture on unit 0, which the caller's StateGuard restores.
#pragma once

#include "gl_functions.hpp"
#include "texture_query.hpp"

namespace sss::gl {

// GL_DEPTH_STENCIL_TEXTURE_MODE exists: desktop GL 4.3+ (ARB_stencil_texturing), OpenGL ES 3.1+.
bool has_depth_stencil_mode(const Functions& gl);

// The texture's GL_DEPTH_STENCIL_TEXTURE_MODE (GL_DEPTH_COMPONENT or GL_STENCIL_INDEX).
GLenum query_depth_stencil_mode(const Functions& gl, const TextureInfo& texture);

// Whether image stores to level 0 of the single-sample `texture` are sure to be defined: base level
// 0, and a minification filter without mipmaps, or one level only (maximum level 0), or immutable
// storage (every level it has is specified). A mutable texture with a mipmap filter and more levels
// allowed may lack them: not asked further (that would take a query per level).
bool query_image_complete(const Functions& gl, const TextureInfo& texture);

// Makes the depth fetches of the passes read depth from a depth-stencil texture the host set to
// stencil sampling: switches its GL_DEPTH_STENCIL_TEXTURE_MODE to GL_DEPTH_COMPONENT on
// construction when `host_mode` is GL_STENCIL_INDEX, and puts GL_STENCIL_INDEX back in restore() or
// the destructor. It is the host texture's state, not the context's, so it is put back whether or
// not the host asked for state restoration (SSS_CREATE_NO_STATE_RESTORE).
class DepthSamplingOverride {
 public:
  DepthSamplingOverride(const Functions& gl, const TextureInfo& depth, GLenum host_mode);
  ~DepthSamplingOverride() { restore(); }
  DepthSamplingOverride(const DepthSamplingOverride&) = delete;
  DepthSamplingOverride& operator=(const DepthSamplingOverride&) = delete;
  void restore();

 private:
  const Functions& gl_;
  GLuint name_ = 0;  // 0: nothing to put back
  GLenum target_ = TEXTURE_2D;
};

}  // namespace sss::gl
