// The GL context of the project's host programs (the benchmark, the scene dump, the soak): a
// headless OpenGL 3.3 core context, current, with the host-side GL loaded. Header only: those
// programs link the headless helper and host_gl, not the test support library.
#pragma once

#include <cstdio>
#include <string>

#include "host_gl.hpp"
#include "sss_headless.h"

namespace sss_test {

// On failure prints "<program>: ..." to stderr and returns nullptr, leaving no context behind.
inline sss_headless* open_host_context(sss_headless_backend backend, const char* program) {
  sss_headless_desc desc = {};
  desc.backend = backend;
  desc.major = 3;
  desc.minor = 3;
  desc.core_profile = 1;
  sss_headless* headless = nullptr;
  char error[512] = "";
  if (sss_headless_create(&desc, &headless, error, sizeof error) != 0) {
    std::fprintf(stderr, "%s: no GL context: %s\n", program, error);
    return nullptr;
  }
  std::string missing;
  if (!host_gl::load(sss_headless_get_proc_address, headless, &missing)) {
    std::fprintf(stderr, "%s: missing GL functions: %s\n", program, missing.c_str());
    sss_headless_destroy(headless);
    return nullptr;
  }
  return headless;
}

}  // namespace sss_test
