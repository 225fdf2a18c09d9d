#include "fitters.hpp"

#include <atomic>

namespace sss::math {

namespace {
// Set once by the tools (sss_tools_init) and read by every set_settings: a pointer to a constant
// table, so an atomic load is all a reader needs.
std::atomic<const Fitters*>& registered() {
  static std::atomic<const Fitters*> f{nullptr};
  return f;
}
}  // namespace

const Fitters& fitters(const char* what) {
  const Fitters* f = registered().load(std::memory_order_acquire);
  if (f == nullptr) {
    throw FittersMissing(std::string(what) +
                         " needs the tools library (NLopt, Eigen): link sss::tools and call sss_tools_init() "
                         "(sss/sss_tools.h) once before");
  }
  return *f;
}

bool have_fitters() { return registered().load(std::memory_order_acquire) != nullptr; }

void set_fitters(const Fitters* f) { registered().store(f, std::memory_order_release); }

}  // namespace sss::math
