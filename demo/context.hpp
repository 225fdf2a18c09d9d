// Headless GL context for the demo: the requested backend, falling back to OSMesa, and the demo's
// GL function table loaded through it.
#pragma once

#include <sss_headless.h>

#include <string>

namespace demo {

struct Context {
  sss_headless *headless = nullptr;
  std::string backend;   // the backend that worked
  std::string renderer;  // GL_RENDERER
  std::string version;   // GL_VERSION
};

// Creates a GL 3.3 core context and loads the GL functions. Prints what went wrong on failure.
bool create_context(const std::string &backend_name, Context *context);
void destroy_context(Context *context);

}  // namespace demo
