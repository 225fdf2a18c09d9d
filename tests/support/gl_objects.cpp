#include "gl_objects.hpp"

#include <GL/glcorearb.h>

#include <cstring>
#include <sstream>

namespace sss_test {

namespace {
const char* const kNames[8] = {"textures",      "buffers",  "framebuffers", "renderbuffers",
                               "vertex arrays", "samplers", "programs",     "shaders"};
const char* const kFunctions[8] = {"glIsTexture",     "glIsBuffer",  "glIsFramebuffer", "glIsRenderbuffer",
                                   "glIsVertexArray", "glIsSampler", "glIsProgram",     "glIsShader"};
}  // namespace

int GlObjectCounts::total() const {
  int sum = 0;
  for (int c : count) sum += c;
  return sum;
}

std::string GlObjectCounts::describe() const {
  std::ostringstream out;
  for (std::size_t i = 0; i < count.size(); ++i) out << (i ? ", " : "") << kNames[i] << ' ' << count[i];
  return out.str();
}

GlObjectCounts count_gl_objects(void* (*get_proc_address)(const char*, void*), void* user, unsigned max_name) {
  GlObjectCounts counts;
  for (std::size_t kind = 0; kind < counts.count.size(); ++kind) {
    void* address = get_proc_address(kFunctions[kind], user);
    if (address == nullptr) continue;
    GLboolean(APIENTRY * is_object)(GLuint) = nullptr;
    std::memcpy(&is_object, &address, sizeof address);
    for (GLuint name = 1; name <= max_name; ++name) counts.count[kind] += is_object(name) ? 1 : 0;
  }
  return counts;
}

}  // namespace sss_test
