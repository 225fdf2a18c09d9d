// main() of the GL suites: `--sss-backend=osmesa|egl|egl-device|egl-gles` picks the headless backend every
// test's context is created on (ctest runs each suite once per backend); the other arguments go to
// GoogleTest.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "gl_fixture.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const char* prefix = "--sss-backend=";
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], prefix, std::strlen(prefix)) != 0) continue;
    sss_headless_backend backend;
    if (sss_headless_backend_from_name(argv[i] + std::strlen(prefix), &backend) != 0) {
      std::fprintf(stderr, "unknown backend in %s (osmesa, egl, egl-device or egl-gles)\n", argv[i]);
      return 2;
    }
    sss_test::set_test_backend(backend);
  }
  return RUN_ALL_TESTS();
}
