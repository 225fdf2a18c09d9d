#include "gpu_memory.hpp"

namespace sss::gl {

std::uint64_t texel_bytes(GLint internal_format) {
  switch (static_cast<GLenum>(internal_format)) {
    case R8:
    case R8UI: return 1;
    case R16F:
    case R16UI:
    case DEPTH_COMPONENT16: return 2;
    case R32F:
    case R32UI:
    case R11F_G11F_B10F:
    case RGBA8:
    case DEPTH_COMPONENT24:
    case DEPTH_COMPONENT32:
    case DEPTH_COMPONENT32F:
    case DEPTH24_STENCIL8: return 4;
    case RGBA16F:
    case RG32UI:
    case DEPTH32F_STENCIL8: return 8;
    case RGBA32F:
    case RGBA32UI: return 16;
    default: return 0;
  }
}

void GpuMemory::set(GLenum kind, GLuint name, std::uint64_t bytes) {
  if (name != 0) bytes_[{kind, name}] = bytes;
}

void GpuMemory::set_2d(GLenum kind, GLuint name, GLint internal_format, int width, int height) {
  const std::uint64_t texels = static_cast<std::uint64_t>(width > 0 ? width : 0) *
                               static_cast<std::uint64_t>(height > 0 ? height : 0);
  set(kind, name, texels * texel_bytes(internal_format));
}

void GpuMemory::erase(GLenum kind, GLuint name) { bytes_.erase({kind, name}); }

std::uint64_t GpuMemory::total() const {
  std::uint64_t sum = 0;
  for (const auto& entry : bytes_) sum += entry.second;
  return sum;
}

}  // namespace sss::gl
