// What the module's GL objects hold (sss_stats.gpu_memory_bytes): each texture's, renderbuffer's and
// buffer's storage as the module specified it (width × height × the format's bytes per texel, or a
// buffer's size), kept per object as it is (re)allocated and deleted. The driver may hold more
// (alignment, compression metadata, mip tails): this is what the module asked for.
#pragma once

#include <cstdint>
#include <map>
#include <utility>

#include "gl_functions.hpp"

namespace sss::gl {

// The bytes one texel of a sized internal format takes as allocated: the formats the module
// allocates and the host's it copies; 0 for any other. DEPTH24_STENCIL8 is 4, DEPTH32F_STENCIL8 8
// (32 bits of depth, 8 of stencil, padded to the 64-bit texel drivers store).
std::uint64_t texel_bytes(GLint internal_format);

class GpuMemory {
 public:
  // `kind`: TEXTURE, RENDERBUFFER or BUFFER; `name`: the object. Replaces what it held before.
  void set(GLenum kind, GLuint name, std::uint64_t bytes);
  // A 2D object of `width` × `height` texels of `internal_format`.
  void set_2d(GLenum kind, GLuint name, GLint internal_format, int width, int height);
  void erase(GLenum kind, GLuint name);  // deleted (name 0: nothing)
  void clear() { bytes_.clear(); }
  std::uint64_t total() const;

 private:
  std::map<std::pair<GLenum, GLuint>, std::uint64_t> bytes_;
};

}  // namespace sss::gl
