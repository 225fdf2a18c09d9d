#include "gl_functions.hpp"

#include <cstring>

namespace demo {

#define DEMO_GL_DEFINE(type, name) type name = nullptr;
DEMO_GL_FUNCTIONS(DEMO_GL_DEFINE)
#undef DEMO_GL_DEFINE

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

bool load_gl_functions(GetProcAddressFn get_proc_address, void *user, std::string *missing) {
  bool ok = true;
#define DEMO_GL_LOAD(type, name)                                   \
  name = to_function<type>(get_proc_address(#name, user));         \
  if (name == nullptr) {                                           \
    ok = false;                                                    \
    if (missing != nullptr) *missing += (missing->empty() ? "" : " ") + std::string(#name); \
  }
  DEMO_GL_FUNCTIONS(DEMO_GL_LOAD)
#undef DEMO_GL_LOAD
  return ok;
}

}  // namespace demo
