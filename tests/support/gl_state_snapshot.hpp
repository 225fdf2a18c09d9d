// A snapshot of every GL state the module promises to restore (sss.h's list) and of the states it
// promises not to touch, for comparing before and after a call.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "host_gl.hpp"

namespace sss_test {

struct Snapshot {
  std::vector<std::pair<std::string, std::vector<GLint>>> values;

  void add(const std::string& name, std::vector<GLint> v) { values.emplace_back(name, std::move(v)); }
  void integer(const char* name, GLenum pname, int count = 1);
  void boolean(const char* name, GLenum pname, int count = 1);
  void enabled(const char* name, GLenum cap);
};

// es: an OpenGL ES context (the desktop-only states are left out).
Snapshot take_snapshot(bool es = false);
// "" when equal; else one line per differing state: "NAME: before { ... } after { ... }".
std::string describe_differences(const Snapshot& before, const Snapshot& after);

}  // namespace sss_test
