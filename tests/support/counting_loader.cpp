#include "counting_loader.hpp"

#include <array>
#include <cstddef>
#include <cstring>

#include "gl/gl_functions.hpp"

namespace sss_test {

namespace {

// Every function the module's loader may ask for, from its own lists.
#define SSS_COUNTED_FUNCTIONS(X)        \
  SSS_GL_REQUIRED_FUNCTIONS(X)          \
  SSS_GL_DESKTOP_FUNCTIONS(X)           \
  SSS_GL_TEXTURE_QUERY_FUNCTIONS(X)     \
  SSS_GL_ES_TIMER_FUNCTIONS(X)          \
  SSS_GL_DEBUG_FUNCTIONS(X)             \
  SSS_GL_COMPUTE_FUNCTIONS(X)

enum Slot : std::size_t {
#define SSS_COUNTED_SLOT(ret, name, params) slot_##name,
  SSS_COUNTED_FUNCTIONS(SSS_COUNTED_SLOT)
#undef SSS_COUNTED_SLOT
  slot_count
};

const std::array<const char*, slot_count> kNames = {
#define SSS_COUNTED_NAME(ret, name, params) "gl" #name,
    SSS_COUNTED_FUNCTIONS(SSS_COUNTED_NAME)
#undef SSS_COUNTED_NAME
};

// The real functions (as the last lookup of each name found them) and the calls since the reset.
std::array<void*, slot_count> g_real{};
std::array<long, slot_count> g_calls{};
sss_get_proc_address_fn g_base = nullptr;

// One wrapper per slot: counts, then calls the real function with the same arguments.
template <std::size_t I, typename F>
struct Counted;
template <std::size_t I, typename R, typename... A>
struct Counted<I, R(SSS_GL_APIENTRY*)(A...)> {
  static R SSS_GL_APIENTRY call(A... args) {
    ++g_calls[I];
    R(SSS_GL_APIENTRY * real)(A...) = nullptr;
    static_assert(sizeof real == sizeof g_real[I], "function pointers are data-pointer sized");
    std::memcpy(&real, &g_real[I], sizeof real);
    return real(args...);
  }
};

template <typename F>
void* as_address(F function) {
  void* address = nullptr;
  static_assert(sizeof address == sizeof function, "function pointers are data-pointer sized");
  std::memcpy(&address, &function, sizeof address);
  return address;
}

const std::array<void*, slot_count> kWrappers = {
#define SSS_COUNTED_WRAPPER(ret, name, params) \
  as_address(&Counted<slot_##name, decltype(sss::gl::Functions::name)>::call),
    SSS_COUNTED_FUNCTIONS(SSS_COUNTED_WRAPPER)
#undef SSS_COUNTED_WRAPPER
};

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

void* counting_get_proc_address(const char* name, void* user) {
  void* real = g_base(name, user);
  if (real == nullptr) return nullptr;  // missing stays missing (es30_get_proc_address hides some)
  for (std::size_t i = 0; i < slot_count; ++i) {
    if (std::strcmp(name, kNames[i]) != 0) continue;
    if (!is_query_function(name) && !is_creation_function(name)) return real;
    g_real[i] = real;
    return kWrappers[i];
  }
  return real;
}

std::string describe(const std::map<std::string, long>& calls) {
  std::string out;
  for (const auto& [name, n] : calls) out += (out.empty() ? "" : ", ") + name + " " + std::to_string(n);
  return out.empty() ? "none" : out;
}

long total(const std::map<std::string, long>& calls) {
  long n = 0;
  for (const auto& entry : calls) n += entry.second;
  return n;
}

}  // namespace

long GlCallCounts::total_queries() const { return total(queries); }
long GlCallCounts::total_creations() const { return total(creations); }
std::string GlCallCounts::describe_queries() const { return describe(queries); }
std::string GlCallCounts::describe_creations() const { return describe(creations); }

bool is_query_function(const std::string& name) {
  return starts_with(name, "glGet") || starts_with(name, "glIs") || name == "glCheckFramebufferStatus";
}

bool is_creation_function(const std::string& name) {
  return starts_with(name, "glGen") || starts_with(name, "glCreate") || name == "glCompileShader" ||
         name == "glLinkProgram" || starts_with(name, "glTexImage") || starts_with(name, "glTexStorage") ||
         starts_with(name, "glRenderbufferStorage");
}

GlCallCounts call_counts() {
  GlCallCounts counts;
  for (std::size_t i = 0; i < slot_count; ++i) {
    if (g_calls[i] == 0) continue;
    const std::string name = kNames[i];
    if (is_query_function(name)) counts.queries[name] += g_calls[i];
    if (is_creation_function(name)) counts.creations[name] += g_calls[i];
  }
  return counts;
}

void reset_call_counts() { g_calls.fill(0); }

sss_get_proc_address_fn counting_loader(sss_get_proc_address_fn base) {
  g_base = base;
  return counting_get_proc_address;
}

}  // namespace sss_test
