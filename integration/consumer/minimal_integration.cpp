// The C++ consumer of the tools: the same API from C++ (the headers are extern "C" and include no GL
// header), linked to sss::tools through find_package(sss CONFIG) (and to sss-tools through
// pkg-config). It checks the version macros, the GL-free kernel API an engine can use to build its
// own shader variant, and a fitted kernel (NLopt, in the tools library alone).
#include <sss/sss_tools.h>

#include <array>
#include <cmath>
#include <cstdio>

int main() {
  sss_settings settings;
  sss_default_settings(&settings);
  std::array<float, SSS_MAX_TAPS * 4> taps{};
  if (sss_kernel_separable(settings.taps, settings.strength, settings.falloff, taps.data()) != SSS_OK) {
    std::fprintf(stderr, "%s\n", sss_last_error(nullptr));
    return 1;
  }
  double sum = 0.0;
  for (int i = 0; i < settings.taps; ++i) sum += taps[static_cast<std::size_t>(i) * 4];
  std::printf("sss %d.%d.%d from C++: %d taps, red weights sum to %.7f; %s for a NULL desc\n", SSS_VERSION_MAJOR,
              SSS_VERSION_MINOR, SSS_VERSION_PATCH, settings.taps, sum,
              sss_result_string(sss_create(nullptr, nullptr)));
  // A guided rank-1 kernel: an optimiser's fit, which only the tools library links.
  sss_kernel_desc guided;
  sss_default_kernel_desc(&guided);
  guided.family = SSS_KERNEL_GUIDED;
  std::array<float, SSS_KERNEL_MAX_TERMS * 2 * SSS_MAX_TAPS * 4> plan{};
  int32_t terms = 0;
  if (sss_kernel_plan(&guided, SSS_KERNEL_MAX_TERMS, plan.data(), nullptr, &terms, nullptr) != SSS_OK || terms != 1) {
    std::fprintf(stderr, "guided kernel: %s\n", sss_last_error(nullptr));
    return 1;
  }
  return std::fabs(sum - 1.0) < 1e-6 ? 0 : 1;
}
