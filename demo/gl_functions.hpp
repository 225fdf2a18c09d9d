// The demo's GL entry points are the project's host-side loader (integration/host_gl), visible
// unqualified inside namespace demo.
#pragma once

#include "host_gl.hpp"

namespace demo {
using namespace host_gl;  // NOLINT(google-build-using-namespace): the whole point of this header
}  // namespace demo
