// KHR_debug groups and object labels, so captures in RenderDoc-style tools read well. Every call is
// a no-op when the extension is absent or the host turned labels off.
#pragma once

#include "gl_functions.hpp"

namespace sss::gl {

class DebugGroup {
 public:
  DebugGroup(const Functions& gl, bool enabled, const char* name);
  ~DebugGroup();
  DebugGroup(const DebugGroup&) = delete;
  DebugGroup& operator=(const DebugGroup&) = delete;

 private:
  const Functions& gl_;
  bool active_;
};

void label_object(const Functions& gl, bool enabled, GLenum identifier, GLuint name, const char* label);

}  // namespace sss::gl
