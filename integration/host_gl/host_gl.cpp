#include "host_gl.hpp"

#include <cstring>

namespace host_gl {

#define HOST_GL_DEFINE(type, name) type name = nullptr;
HOST_GL_FUNCTIONS(HOST_GL_DEFINE)
#undef HOST_GL_DEFINE

namespace {

// Object pointer to function pointer without a cast the warning set would flag.
template <typename Fn>
Fn to_function(void *address) {
  Fn fn = nullptr;
  static_assert(sizeof fn == sizeof address, "function and object pointers differ in size");
  std::memcpy(&fn, &address, sizeof fn);
  return fn;
}

}  // namespace

bool load(GetProcAddressFn get_proc_address, void *user, std::string *missing) {
  bool ok = true;
#define HOST_GL_LOAD(type, name)                                                            \
  name = to_function<type>(get_proc_address(#name, user));                                  \
  if (name == nullptr) {                                                                    \
    ok = false;                                                                             \
    if (missing != nullptr) *missing += (missing->empty() ? "" : " ") + std::string(#name); \
  }
  HOST_GL_FUNCTIONS(HOST_GL_LOAD)
#undef HOST_GL_LOAD
  return ok;
}

}  // namespace host_gl
