// Counts the GL objects that exist in the current context, per kind, by asking glIs* for every
// name up to a bound (GL names are small integers handed out from 1; Mesa reuses freed ones).
// Used to show that failures, context loss and long runs leave no object behind.
#pragma once

#include <array>
#include <string>

namespace sss_test {

struct GlObjectCounts {
  // textures, buffers, framebuffers, renderbuffers, vertex arrays, samplers, programs, shaders
  std::array<int, 8> count{};

  int total() const;
  bool operator==(const GlObjectCounts& o) const { return count == o.count; }
  bool operator!=(const GlObjectCounts& o) const { return count != o.count; }
  std::string describe() const;  // "textures 3, buffers 0, ..."
};

// The context current now; `get_proc_address(name, user)` loads the glIs* functions.
GlObjectCounts count_gl_objects(void* (*get_proc_address)(const char*, void*), void* user, unsigned max_name = 4096);

}  // namespace sss_test
