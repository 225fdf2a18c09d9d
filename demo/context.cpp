#include "context.hpp"

#include "gl_functions.hpp"

#include <cstdio>

namespace demo {

namespace {

sss_headless *try_backend(sss_headless_backend backend) {
  sss_headless_desc desc{};
  desc.backend = backend;
  desc.major = 3;
  desc.minor = 3;
  desc.core_profile = 1;
  desc.debug = 0;
  sss_headless *headless = nullptr;
  char error[512] = {0};
  if (sss_headless_create(&desc, &headless, error, sizeof error) != 0) {
    std::fprintf(stderr, "sss_demo: backend %s failed: %s\n", sss_headless_backend_name(backend), error);
    return nullptr;
  }
  return headless;
}

}  // namespace

bool create_context(const std::string &backend_name, Context *context) {
  sss_headless_backend backend = SSS_HEADLESS_EGL_SURFACELESS;
  if (sss_headless_backend_from_name(backend_name.c_str(), &backend) != 0) {
    std::fprintf(stderr, "sss_demo: unknown backend '%s' (osmesa, egl, egl-device)\n", backend_name.c_str());
    return false;
  }
  sss_headless *headless = try_backend(backend);
  if (headless == nullptr && backend != SSS_HEADLESS_OSMESA) {
    std::fprintf(stderr, "sss_demo: falling back to osmesa\n");
    backend = SSS_HEADLESS_OSMESA;
    headless = try_backend(backend);
  }
  if (headless == nullptr) return false;

  std::string missing;
  if (!host_gl::load(sss_headless_get_proc_address, headless, &missing)) {
    std::fprintf(stderr, "sss_demo: GL functions missing: %s\n", missing.c_str());
    sss_headless_destroy(headless);
    return false;
  }
  context->headless = headless;
  context->backend = sss_headless_backend_name(backend);
  const char *renderer = reinterpret_cast<const char *>(glGetString(GL_RENDERER));
  const char *version = reinterpret_cast<const char *>(glGetString(GL_VERSION));
  context->renderer = renderer != nullptr ? renderer : "(unknown)";
  context->version = version != nullptr ? version : "(unknown)";
  return true;
}

void destroy_context(Context *context) {
  sss_headless_destroy(context->headless);
  *context = Context{};
}

}  // namespace demo
