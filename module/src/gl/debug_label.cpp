#include "debug_label.hpp"

namespace sss::gl {

DebugGroup::DebugGroup(const Functions& gl, bool enabled, const char* name)
    : gl_(gl), active_(enabled && gl.has_debug) {
  if (active_) gl_.PushDebugGroup(DEBUG_SOURCE_APPLICATION, 0, -1, name);
}

DebugGroup::~DebugGroup() {
  if (active_) gl_.PopDebugGroup();
}

void label_object(const Functions& gl, bool enabled, GLenum identifier, GLuint name, const char* label) {
  if (enabled && gl.has_debug && name != 0) gl.ObjectLabel(identifier, name, -1, label);
}

}  // namespace sss::gl
