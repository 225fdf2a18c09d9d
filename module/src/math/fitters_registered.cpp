// Linked into everything that links sss_math (tests, benchmark, tools; never a shipped library):
// registers the fitted kernels before main, as sss_tools_init does for a host, so the math layer's
// own users build every family without a call of their own.
#include "math/fitters.hpp"

namespace {
const bool registered = [] {
  sss::math::set_fitters(&sss::math::tool_fitters());
  return true;
}();
}  // namespace
