// What the demo's checking tools (image_check.cpp, material_check.cpp) share: failures counted and
// printed one by one, and a main that runs the mode its first argument names. Exit status 0 when
// every check passed, 1 otherwise, 2 for bad usage.
#pragma once

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace demo_check {

inline int g_failures = 0;

inline void check(bool condition, const std::string &what) {
  if (!condition) {
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
    ++g_failures;
  }
}

// A mode: its name and what runs it (argv as main got it; returns 0, 1, or 2 for bad usage).
using Mode = std::pair<const char *, int (*)(int, char **)>;

inline int run_mode(int argc, char **argv, const std::vector<Mode> &modes, const char *usage) {
  const std::string mode = argc > 1 ? argv[1] : "";
  int status = 2;
  for (const Mode &m : modes) {
    if (mode == m.first) status = m.second(argc, argv);
  }
  if (status == 2) {
    std::fprintf(stderr, "usage: %s %s\n", argv[0], usage);
  } else {
    std::printf("%s\n", status == 0 ? "all checks passed" : "some checks failed");
  }
  return status;
}

}  // namespace demo_check
